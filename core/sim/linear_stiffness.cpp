#include "sim/linear_stiffness.h"

#include <Eigen/LU>
#include <array>

#include "fem/quadrature.h"
#include "fem/trilinear_shape.h"

namespace sculpt {
namespace {

using ElementStiffness = Eigen::Matrix<double, 24, 24>;

// K_ab = sum_q V_q (lambda g_a g_b^T + mu (g_a . g_b) I + mu g_b g_a^T), g = dN/dX.
void addGaussPointStiffness(const LinearShapeGradient& g, double volume, const LameParameters& lame,
                            ElementStiffness& K) {
  for (int a = 0; a < 8; ++a)
    for (int b = 0; b < 8; ++b) {
      const Eigen::Vector3d ga = g.row(a).transpose(), gb = g.row(b).transpose();
      Eigen::Matrix3d block = lame.lambda * ga * gb.transpose() + lame.mu * gb * ga.transpose();
      block.diagonal().array() += lame.mu * ga.dot(gb);
      K.block<3, 3>(3 * a, 3 * b) += volume * block;
    }
}

// The 8 nodes of element e's stand-in: a trilinear or pyramid element's own, a tricubic
// element's cell corners (block [1,2]^3 of its 4^3 nodes) in trilinear order.
std::array<uint32_t, 8> standInCorners(const FemMesh& mesh, uint32_t e) {
  if (e >= mesh.numTricubic()) return mesh.linearNodes[e - mesh.numTricubic()];
  std::array<uint32_t, 8> ids;
  const auto& block = mesh.tricubicNodes[e];
  for (int a = 0; a < 8; ++a) {
    const int* corner = kTrilinearCorner[a];
    ids[a] = block[(1 + corner[0]) * 16 + (1 + corner[1]) * 4 + (1 + corner[2])];
  }
  return ids;
}

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

SparseMatrix kroneckerIdentity3(const SparseMatrix& scalar) {
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(size_t(scalar.nonZeros()) * 3);
  for (int k = 0; k < scalar.outerSize(); ++k)
    for (SparseMatrix::InnerIterator it(scalar, k); it; ++it)
      for (int c = 0; c < 3; ++c)
        triplets.emplace_back(int(3 * it.row() + c), int(3 * it.col() + c), it.value());
  SparseMatrix result(3 * scalar.rows(), 3 * scalar.cols());
  result.setFromTriplets(triplets.begin(), triplets.end());
  return result;
}

SparseMatrix reducedLinearStiffness(const FemModel& model) {
  return reducedLinearStiffness(model.mesh(), model.mesh().gaussLame, model.stencilMatrix());
}

Eigen::VectorXd controlPointModulus(const FemMesh& mesh, std::span<const LameParameters> lame,
                                    const SparseMatrix& A) {
  Eigen::VectorXd nodeModulus = Eigen::VectorXd::Zero(Eigen::Index(mesh.numNodes()));
  for (uint32_t e = 0; e < mesh.numElements(); ++e) {
    const LameParameters m = meanLame(mesh, lame, e);
    for (uint32_t id : standInCorners(mesh, e)) nodeModulus[id] += m.lambda + 2 * m.mu;
  }
  return A.transpose() * nodeModulus;
}

SparseMatrix reducedLinearStiffness(const FemMesh& mesh, std::span<const LameParameters> lame,
                                    const SparseMatrix& A) {
  const QuadratureRule gauss2 = gaussLegendre(2);
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(size_t(mesh.numElements()) * 24 * 24);
  ElementStiffness K;
  for (uint32_t e = 0; e < mesh.numElements(); ++e) {
    K.setZero();
    const std::array<uint32_t, 8> ids = standInCorners(mesh, e);
    const uint32_t g0 = mesh.gaussBegin(e);
    if (e < mesh.numTricubic()) {
      const LameParameters mean = meanLame(mesh, lame, e);
      for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j)
          for (int k = 0; k < 2; ++k) {
            double N[8], dN[8][3];
            trilinearShape({gauss2.points[i], gauss2.points[j], gauss2.points[k]}, N, dN);
            Eigen::Matrix<double, 8, 3> dNdXi;
            Eigen::Matrix3d J = Eigen::Matrix3d::Zero();
            for (int a = 0; a < 8; ++a)
              for (int d = 0; d < 3; ++d) {
                dNdXi(a, d) = dN[a][d];
                J.col(d) += dN[a][d] * mesh.restNodes.row(ids[a]).transpose();
              }
            const double det = J.determinant();
            if (!(det > 0)) continue;  // a corner hexahedron may be poor; skip its point
            addGaussPointStiffness(dNdXi * J.inverse(),
                                   gauss2.weights[i] * gauss2.weights[j] * gauss2.weights[k] * det,
                                   mean, K);
          }
    } else {
      const uint32_t l = e - mesh.numTricubic();
      for (int q = 0; q < kLinearGaussPoints; ++q)
        addGaussPointStiffness(mesh.linearShapeGradient[size_t(l) * 8 + q],
                               mesh.gaussVolume[g0 + q], lame[g0 + q], K);
    }
    for (int a = 0; a < 8; ++a)
      for (int b = 0; b < 8; ++b)
        for (int c = 0; c < 3; ++c)
          for (int d = 0; d < 3; ++d)
            triplets.emplace_back(int(3 * ids[a] + c), int(3 * ids[b] + d), K(3 * a + c, 3 * b + d));
  }
  const int n = int(mesh.numNodes());
  SparseMatrix nodeK(3 * n, 3 * n);
  nodeK.setFromTriplets(triplets.begin(), triplets.end());
  const SparseMatrix A3 = kroneckerIdentity3(A);
  return reduceToControlPoints(A3, nodeK);
}

}  // namespace sculpt
