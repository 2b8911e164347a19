#include "embed/deformation_gradients.h"

#include <algorithm>

#include <Eigen/LU>

#include "embed/cell_coordinates.h"
#include "fem/trilinear_shape.h"
#include "util/parallel_for.h"

namespace sculpt {

CellGradientOperator cellGradientOperator(const VolumeMesh& rest) {
  CellGradientOperator op;
  op.shapeGradients.resize(rest.cells.values.size());
  for (uint32_t c = 0; c < rest.numCells(); ++c) {
    const bool tetrahedron = rest.isTetrahedron(c);
    const Eigen::Vector3d centre = cellCentreCoordinates(tetrahedron);
    const Eigen::Matrix3d inverseJacobian = cellJacobian(rest, c, centre).inverse();
    Eigen::Vector3d* g = op.shapeGradients.data() + rest.cells.offsets[c];
    if (tetrahedron) {
      // beta_a = rows of V^-1 applied to (X - X0) for a = 1..3; beta_0 = 1 - their sum.
      g[0].setZero();
      for (int a = 1; a < 4; ++a) {
        g[a] = inverseJacobian.row(a - 1).transpose();
        g[0] -= g[a];
      }
    } else {
      double N[8], dN[8][3];
      trilinearShape(centre, N, dN);
      for (int a = 0; a < 8; ++a)
        g[a] = inverseJacobian.transpose() * Eigen::Vector3d(dN[a][0], dN[a][1], dN[a][2]);
    }
  }
  return op;
}

void computeCellGradients(const VolumeMesh& rest, const CellGradientOperator& op,
                          const Points& deformedNodes,
                          std::vector<Eigen::Matrix3d>& cellGradients) {
  cellGradients.resize(rest.numCells());
  parallelChunks(rest.numCells(), 2048, [&](uint32_t begin, uint32_t end, unsigned) {
    for (uint32_t c = begin; c < end; ++c) {
      const uint32_t first = rest.cells.offsets[c];
      const uint32_t* nodes = rest.cells.values.data() + first;
      const Eigen::Vector3d* g = op.shapeGradients.data() + first;
      Eigen::Matrix3d F;
      if (rest.cells.offsets[c + 1] - first == 4) {
        // g_0 = -(g_1 + g_2 + g_3): F = sum_{a>0} (x_a - x_0) g_a^T, three outer products.
        const Eigen::Vector3d x0 = deformedNodes.row(nodes[0]).transpose();
        F.noalias() = (deformedNodes.row(nodes[1]).transpose() - x0) * g[1].transpose();
        F.noalias() += (deformedNodes.row(nodes[2]).transpose() - x0) * g[2].transpose();
        F.noalias() += (deformedNodes.row(nodes[3]).transpose() - x0) * g[3].transpose();
      } else {
        F.setZero();
        for (int a = 0; a < 8; ++a)
          F.noalias() += deformedNodes.row(nodes[a]).transpose() * g[a].transpose();
      }
      cellGradients[c] = F;
    }
  });
}

void computeNodeGradients(const CompressedRows<CellWeight>& weights,
                          const std::vector<Eigen::Matrix3d>& cellGradients,
                          std::vector<Eigen::Matrix3d>& nodeGradients) {
  nodeGradients.resize(weights.numRows());
  parallelChunks(weights.numRows(), 2048, [&](uint32_t begin, uint32_t end, unsigned) {
    for (uint32_t node = begin; node < end; ++node) {
      Eigen::Matrix3d F = Eigen::Matrix3d::Zero();
      for (const CellWeight& w : weights.row(node)) F += w.weight * cellGradients[w.cell];
      nodeGradients[node] = F;
    }
  });
}

NodeGradientStencil nodeGradientStencil(const VolumeMesh& rest, const CellGradientOperator& op,
                                        const CompressedRows<CellWeight>& weights) {
  NodeGradientStencil stencil;
  std::vector<std::pair<uint32_t, Eigen::Vector3d>> terms;
  for (uint32_t node = 0; node < weights.numRows(); ++node) {
    terms.clear();
    for (const CellWeight& w : weights.row(node))
      for (uint32_t k = rest.cells.offsets[w.cell]; k < rest.cells.offsets[w.cell + 1]; ++k)
        terms.emplace_back(rest.cells.values[k], w.weight * op.shapeGradients[k]);
    std::sort(terms.begin(), terms.end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
    const size_t first = stencil.nodes.size();
    for (const auto& [neighbour, g] : terms) {
      if (stencil.nodes.size() > first && stencil.nodes.back() == neighbour) {
        for (int d = 0; d < 3; ++d) stencil.g[stencil.g.size() - 3 + d] += g[d];
        continue;
      }
      stencil.nodes.push_back(neighbour);
      stencil.g.insert(stencil.g.end(), {g[0], g[1], g[2]});
    }
    stencil.offsets.push_back(static_cast<uint32_t>(stencil.nodes.size()));
  }
  return stencil;
}

void applyNodeGradientStencil(const NodeGradientStencil& stencil, const Points& deformedNodes,
                              std::vector<Eigen::Matrix3d>& nodeGradients) {
  nodeGradients.resize(stencil.numNodes());
  const double* x = deformedNodes.data();  // row-major: node j at x + 3 j
  parallelChunks(stencil.numNodes(), 2048, [&](uint32_t begin, uint32_t end, unsigned) {
    for (uint32_t node = begin; node < end; ++node) {
      double F[3][3] = {};
      for (uint32_t t = stencil.offsets[node]; t < stencil.offsets[node + 1]; ++t) {
        const double* xj = x + 3 * static_cast<size_t>(stencil.nodes[t]);
        const double* g = stencil.g.data() + 3 * static_cast<size_t>(t);
        for (int r = 0; r < 3; ++r)
          for (int c = 0; c < 3; ++c) F[r][c] += xj[r] * g[c];
      }
      Eigen::Matrix3d& out = nodeGradients[node];
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) out(r, c) = F[r][c];
    }
  });
}

}  // namespace sculpt
