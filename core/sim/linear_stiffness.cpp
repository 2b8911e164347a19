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
                                    const SparseMatrix& A, std::span<const uint8_t> skip) {
  const QuadratureRule gauss2 = gaussLegendre(2);
  // A tricubic element's stand-in is integrated at points a quarter of the Gauss-Legendre
  // points' distance from the cell centre, with their weights: constant strains are still
  // integrated exactly, while the modes that vary across the cell (where a trilinear element
  // is much stiffer than a B-spline one) are softened. On block4 at K = 1 the generalised
  // eigenvalues of the elements' stiffness against the stand-in go from [0.54, 1.01] to
  // [0.65, 1.02] (docs/fem.md, "The implicit solver's preconditioner").
  const double standIn[2] = {0.5 + kStandInSpread * (gauss2.points[0] - 0.5),
                             0.5 + kStandInSpread * (gauss2.points[1] - 0.5)};
  const auto corners = [&](uint32_t e) { return elementCorners(mesh, e); };
  SymmetricNodeBlocks nodes =
      symmetricNodePattern(mesh.numNodes(), mesh.numElements(), corners, skip);
  std::vector<uint32_t> where(mesh.numNodes());
  for (uint32_t e = 0; e < mesh.numElements(); ++e) {
    if (!skip.empty() && skip[e]) continue;
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
    addUpperBlocks(nodes, ids, [&](int a, int b) -> Eigen::Matrix3d {
      return Ke.block<3, 3>(3 * a, 3 * b);
    }, where);
  }
  return reduceSymmetricNodeBlocks(nodes, A);
}

}  // namespace sculpt
