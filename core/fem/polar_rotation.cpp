#include "fem/polar_rotation.h"

#include <Eigen/LU>
#include <Eigen/SVD>
#include <cmath>

namespace sculpt {
namespace {

// SVD with the reflection fix: the closest proper rotation, also for det F <= 0.
Eigen::Matrix3d rotationBySvd(const Eigen::Matrix3d& F) {
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(F, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d U = svd.matrixU();
  const Eigen::Matrix3d V = svd.matrixV();
  // Singular values are sorted decreasingly: flipping the last column changes the least.
  if ((U * V.transpose()).determinant() < 0) U.col(2) = -U.col(2);
  return U * V.transpose();
}

}  // namespace

Eigen::Matrix3d polarRotation(const Eigen::Matrix3d& F) {
  if (!F.allFinite()) return Eigen::Matrix3d::Identity();
  const double size = F.norm();
  if (!(size > 0)) return Eigen::Matrix3d::Identity();
  // Well-conditioned, uninverted F (the usual case): Higham's scaled Newton iteration
  // X <- (g X + X^-T / g) / 2 converges quadratically to the rotation, in a few 3x3 inverses
  // (several times cheaper than a Jacobi SVD). Anything else goes through the SVD.
  const double det = F.determinant();
  if (det > 1e-6 * size * size * size) {
    Eigen::Matrix3d X = F;
    for (int iteration = 0; iteration < 30; ++iteration) {
      const Eigen::Matrix3d inverse = X.inverse();
      const double gamma = std::sqrt(inverse.norm() / X.norm());
      const Eigen::Matrix3d next = 0.5 * (gamma * X + inverse.transpose() / gamma);
      const double change = (next - X).norm();
      X = next;
      if (change <= 1e-13) {
        // One more unscaled step polishes orthogonality to rounding.
        return 0.5 * (X + X.inverse().transpose());
      }
    }
  }
  return rotationBySvd(F);
}

}  // namespace sculpt
