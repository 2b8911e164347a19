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
                          const Points& deformedNodes, std::vector<Eigen::Matrix3d>& cellGradients) {
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
  std::vector<NodeGradientStencil::Term> terms;
  for (uint32_t node = 0; node < weights.numRows(); ++node) {
    terms.clear();
    for (const CellWeight& w : weights.row(node))
      for (uint32_t k = rest.cells.offsets[w.cell]; k < rest.cells.offsets[w.cell + 1]; ++k)
        terms.push_back({rest.cells.values[k], w.weight * op.shapeGradients[k]});
    std::sort(terms.begin(), terms.end(),
              [](const auto& a, const auto& b) { return a.node < b.node; });
    for (size_t t = 0; t < terms.size(); ++t) {
      if (!stencil.rows.values.empty() && t > 0 && stencil.rows.values.back().node == terms[t].node)
        stencil.rows.values.back().g += terms[t].g;
      else
        stencil.rows.values.push_back(terms[t]);
    }
    stencil.rows.closeRow();
  }
  return stencil;
}

void applyNodeGradientStencil(const NodeGradientStencil& stencil, const Points& deformedNodes,
                              std::vector<Eigen::Matrix3d>& nodeGradients) {
  nodeGradients.resize(stencil.rows.numRows());
  parallelChunks(stencil.rows.numRows(), 2048, [&](uint32_t begin, uint32_t end, unsigned) {
    for (uint32_t node = begin; node < end; ++node) {
      Eigen::Matrix3d F = Eigen::Matrix3d::Zero();
      for (const auto& term : stencil.rows.row(node))
        F.noalias() += deformedNodes.row(term.node).transpose() * term.g.transpose();
      nodeGradients[node] = F;
    }
  });
}

}  // namespace sculpt
