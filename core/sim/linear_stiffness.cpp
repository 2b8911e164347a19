#include "sim/linear_stiffness.h"

#include <Eigen/LU>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "fem/quadrature.h"
#include "fem/trilinear_shape.h"
#include "sim/node_block_rows.h"
#include "util/dense_accumulator.h"

namespace sculpt {
namespace {

using ElementStiffness = Eigen::Matrix<double, 24, 24>;

// The stand-in points' distance from the cell centre, as a fraction of the 2-point
// Gauss-Legendre rule's.
constexpr double kStandInSpread = 0.25;

// An element's stiffness K_ab = sum_q V_q (lambda g_a g_b^T + mu g_b g_a^T + mu (g_a . g_b) I),
// g = dN/dX, gathered as R_lambda + blockT(R_mu) + L (x) I3: with d_q the 24 values g_a(c) at row
// 3a + c, R_w = sum_q w_q d_q d_q^T, blockT transposing each 3x3 block, and L = sum_q mu V_q g g^T
// (8 x 8). Rank-one updates the compiler vectorises, instead of 64 3x3 blocks per point.
class ElementStiffnessSum {
 public:
  void add(const LinearShapeGradient& g, double volume, const LameParameters& lame) {
    Eigen::Matrix<double, 24, 1> d;
    for (int a = 0; a < 8; ++a) d.segment<3>(3 * a) = g.row(a).transpose();
    const ElementStiffness outer = d * d.transpose();
    lambdaPart_ += (volume * lame.lambda) * outer;
    muPart_ += (volume * lame.mu) * outer;
    gram_.noalias() += (volume * lame.mu) * g * g.transpose();
  }
  ElementStiffness matrix() const {
    ElementStiffness K = lambdaPart_;
    for (int a = 0; a < 8; ++a)
      for (int b = 0; b < 8; ++b) {
        K.block<3, 3>(3 * a, 3 * b) += muPart_.block<3, 3>(3 * a, 3 * b).transpose();
        K.block<3, 3>(3 * a, 3 * b).diagonal().array() += gram_(a, b);
      }
    return K;
  }

 private:
  ElementStiffness lambdaPart_ = ElementStiffness::Zero(), muPart_ = ElementStiffness::Zero();
  Eigen::Matrix<double, 8, 8> gram_ = Eigen::Matrix<double, 8, 8>::Zero();
};


LameParameters meanLame(const FemMesh& mesh, std::span<const LameParameters> lame, uint32_t e) {
  const uint32_t g0 = mesh.gaussBegin(e);
  const int count = e < mesh.numTricubic() ? kTricubicGaussPoints : kLinearGaussPoints;
  LameParameters mean;
  for (int q = 0; q < count; ++q) {
    mean.lambda += lame[g0 + q].lambda / count;
    mean.mu += lame[g0 + q].mu / count;
  }
  return mean;
}

}  // namespace

SparseMatrix reduceNodeBlocks(const NodeBlockRows& K, const SparseMatrix& A) {
  // S_ij = sum_nm A_ni K_nm A_mj on 3x3 blocks, in two sparse passes with dense row
  // accumulators: T = K A row by row, then S = A^T T. As scalar sparse products it took 4x
  // longer, most of a first step (block10 at K = 1: 260 ms).
  const uint32_t numNodes = K.numNodes();
  const Eigen::Index numControl = A.cols();
  // A dense accumulator over the control points.
  DenseAccumulator<Eigen::Matrix3d> sum(size_t(numControl), Eigen::Matrix3d::Zero());

  // T = K A: per node n, the blocks T_nj = sum_m K_nm A_mj.
  using RowSparseMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;
  const RowSparseMatrix rowsOfA = A;
  std::vector<size_t> tBegin(size_t(numNodes) + 1, 0);
  std::vector<uint32_t> tColumn;
  std::vector<Eigen::Matrix3d> tBlock;
  for (uint32_t n = 0; n < numNodes; ++n) {
    for (uint32_t k = K.begin[n]; k < K.begin[n + 1]; ++k)
      for (RowSparseMatrix::InnerIterator it(rowsOfA, K.column[k]); it; ++it)
        sum.add(uint32_t(it.col()), it.value() * K.block[k]);
    sum.drain([&](uint32_t j, const Eigen::Matrix3d& block) {
      tColumn.push_back(j);
      tBlock.push_back(block);
    });
    tBegin[n + 1] = tColumn.size();
  }

  // S = A^T T: control row i gathers A_ni T_n over the nodes n of A's column i. S is symmetric,
  // so row i's blocks, transposed, are column i's: column 3i + c holds S_ij(c, r) at row 3j + r.
  SparseMatrix S(3 * numControl, 3 * numControl);
  S.reserve(Eigen::Index(tColumn.size()) * 9);  // a guess; the matrix grows as needed
  std::vector<std::pair<uint32_t, Eigen::Matrix3d>> rowBlocks;
  for (Eigen::Index i = 0; i < numControl; ++i) {
    for (SparseMatrix::InnerIterator it(A, i); it; ++it) {
      const size_t n = size_t(it.row());
      for (size_t k = tBegin[n]; k < tBegin[n + 1]; ++k)
        sum.add(tColumn[k], it.value() * tBlock[k]);
    }
    sum.sortTouched();
    rowBlocks.clear();
    sum.drain([&](uint32_t j, const Eigen::Matrix3d& block) { rowBlocks.emplace_back(j, block); });
    for (int c = 0; c < 3; ++c) {
      S.startVec(3 * i + c);
      for (const auto& [j, block] : rowBlocks)
        for (int r = 0; r < 3; ++r) S.insertBack(3 * Eigen::Index(j) + r, 3 * i + c) = block(c, r);
    }
  }
  S.finalize();
  return S;
}

Eigen::Matrix<double, 24, 24> linearElementStiffness(const FemMesh& mesh,
                                                     std::span<const LameParameters> lame,
                                                     uint32_t e) {
  ElementStiffnessSum sum;
  const uint32_t l = e - mesh.numTricubic(), g0 = mesh.gaussBegin(e);
  for (int q = 0; q < kLinearGaussPoints; ++q)
    sum.add(mesh.linearShapeGradient[size_t(l) * 8 + q], mesh.gaussVolume[g0 + q], lame[g0 + q]);
  return sum.matrix();
}

std::array<uint32_t, 8> elementCorners(const FemMesh& mesh, uint32_t e) {
  if (e >= mesh.numTricubic()) return mesh.linearNodes[e - mesh.numTricubic()];
  std::array<uint32_t, 8> ids;
  const auto& block = mesh.tricubicNodes[e];
  for (int a = 0; a < 8; ++a) {
    const int* corner = kTrilinearCorner[a];
    ids[a] = block[(1 + corner[0]) * 16 + (1 + corner[1]) * 4 + (1 + corner[2])];
  }
  return ids;
}

SparseMatrix reducedLinearStiffness(const FemModel& model) {
  return reducedLinearStiffness(model.mesh(), model.mesh().gaussLame, model.stencilMatrix());
}

Eigen::VectorXd controlPointModulus(const FemMesh& mesh, std::span<const LameParameters> lame,
                                    const SparseMatrix& A) {
  Eigen::VectorXd nodeModulus = Eigen::VectorXd::Zero(Eigen::Index(mesh.numNodes()));
  for (uint32_t e = 0; e < mesh.numElements(); ++e) {
    const LameParameters m = meanLame(mesh, lame, e);
    for (uint32_t id : elementCorners(mesh, e)) nodeModulus[id] += m.lambda + 2 * m.mu;
  }
  return A.transpose() * nodeModulus;
}

SparseMatrix reducedLinearStiffness(const FemMesh& mesh, std::span<const LameParameters> lame,
                                    const SparseMatrix& A) {
  const QuadratureRule gauss2 = gaussLegendre(2);
  // A tricubic element's stand-in is integrated at points a quarter of the Gauss-Legendre
  // points' distance from the cell centre, with their weights: constant strains are still
  // integrated exactly, while the modes that vary across the cell (where a trilinear element
  // is much stiffer than a B-spline one) are softened. On block4 at K = 1 the generalised
  // eigenvalues of the elements' stiffness against the stand-in go from [0.54, 1.01] to
  // [0.65, 1.02] (docs/fem.md, "The implicit solver's preconditioner").
  const double standIn[2] = {0.5 + kStandInSpread * (gauss2.points[0] - 0.5),
                             0.5 + kStandInSpread * (gauss2.points[1] - 0.5)};
  std::vector<std::vector<uint32_t>> neighbours(mesh.numNodes());
  std::vector<std::vector<Eigen::Matrix3d>> blocks(mesh.numNodes());
  for (uint32_t e = 0; e < mesh.numElements(); ++e) {
    ElementStiffnessSum sum;
    const std::array<uint32_t, 8> ids = elementCorners(mesh, e);
    if (e < mesh.numTricubic()) {
      const LameParameters mean = meanLame(mesh, lame, e);
      for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j)
          for (int k = 0; k < 2; ++k) {
            double N[8], dN[8][3];
            trilinearShape({standIn[i], standIn[j], standIn[k]}, N, dN);
            Eigen::Matrix<double, 8, 3> dNdXi;
            Eigen::Matrix3d J = Eigen::Matrix3d::Zero();
            for (int a = 0; a < 8; ++a)
              for (int d = 0; d < 3; ++d) {
                dNdXi(a, d) = dN[a][d];
                J.col(d) += dN[a][d] * mesh.restNodes.row(ids[a]).transpose();
              }
            const double det = J.determinant();
            if (!(det > 0)) continue;  // a corner hexahedron may be poor; skip its point
            sum.add(dNdXi * J.inverse(),
                    gauss2.weights[i] * gauss2.weights[j] * gauss2.weights[k] * det, mean);
          }
    }
    const ElementStiffness Ke = e < mesh.numTricubic() ? sum.matrix()
                                                       : linearElementStiffness(mesh, lame, e);
    for (int a = 0; a < 8; ++a) {
      std::vector<uint32_t>& row = neighbours[ids[a]];
      std::vector<Eigen::Matrix3d>& rowBlocks = blocks[ids[a]];
      for (int b = 0; b < 8; ++b) {
        const auto at = std::find(row.begin(), row.end(), ids[b]);
        const Eigen::Matrix3d block = Ke.block<3, 3>(3 * a, 3 * b);
        if (at != row.end()) {
          rowBlocks[size_t(at - row.begin())] += block;
        } else {
          row.push_back(ids[b]);
          rowBlocks.push_back(block);
        }
      }
    }
  }
  NodeBlockRows K;
  for (uint32_t n = 0; n < mesh.numNodes(); ++n) {
    K.column.insert(K.column.end(), neighbours[n].begin(), neighbours[n].end());
    K.block.insert(K.block.end(), blocks[n].begin(), blocks[n].end());
    K.begin.push_back(uint32_t(K.column.size()));
  }
  neighbours = {};
  blocks = {};
  return reduceNodeBlocks(K, A);
}

}  // namespace sculpt
