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

Eigen::Matrix3d polarRotation(const Eigen::Matrix3d& F, const Eigen::Matrix3d& guess) {
  // R = guess * Q with Q^T (guess^T F) symmetric. With M = R^T F and Q ~ I + [w]x, the skew
  // part of Q^T M vanishes to first order for (tr(M) I - M) w = 2 axial(skew M), because
  // [w]x M + M^T [w]x = [(tr(M) I - M) w]x. Each correction is applied as a Cayley rotation,
  // which is orthogonal to rounding; the iteration converges quadratically.
  Eigen::Matrix3d R = guess;
  for (int iteration = 0; iteration < 4; ++iteration) {
    const Eigen::Matrix3d M = R.transpose() * F;
    const double trace = M(0, 0) + M(1, 1) + M(2, 2);
    const Eigen::Vector3d skew(M(2, 1) - M(1, 2), M(0, 2) - M(2, 0), M(1, 0) - M(0, 1));
    // A = tr(M) I - M by its adjugate (rows of cofactors).
    const double a00 = trace - M(0, 0), a11 = trace - M(1, 1), a22 = trace - M(2, 2);
    const double a01 = -M(0, 1), a02 = -M(0, 2), a10 = -M(1, 0), a12 = -M(1, 2),
                 a20 = -M(2, 0), a21 = -M(2, 1);
    const double c00 = a11 * a22 - a12 * a21, c01 = a02 * a21 - a01 * a22,
                 c02 = a01 * a12 - a02 * a11;
    const double c10 = a12 * a20 - a10 * a22, c11 = a00 * a22 - a02 * a20,
                 c12 = a02 * a10 - a00 * a12;
    const double c20 = a10 * a21 - a11 * a20, c21 = a01 * a20 - a00 * a21,
                 c22 = a00 * a11 - a01 * a10;
    const double det = a00 * c00 + a01 * c10 + a02 * c20;
    // Near the polar rotation A is about tr(S) I - S, positive definite for an SPD stretch S;
    // this also rejects the other stationary points (half turns away), where det A < 0.
    // Anything else (NaN included) goes the cold way.
    if (!(trace > 0) || !(det > 1e-6 * trace * trace * trace)) break;
    const double inv = 1.0 / det;
    const Eigen::Vector3d w(inv * (c00 * skew.x() + c01 * skew.y() + c02 * skew.z()),
                            inv * (c10 * skew.x() + c11 * skew.y() + c12 * skew.z()),
                            inv * (c20 * skew.x() + c21 * skew.y() + c22 * skew.z()));
    const double step = w.squaredNorm();
    if (!(step <= 0.25)) break;  // the guess is far: start cold
    // Cayley rotation of w: I + 2/(1 + |v|^2) ([v]x + [v]x^2), v = w/2.
    const Eigen::Vector3d v = 0.5 * w;
    const double vv = v.squaredNorm(), f = 2.0 / (1.0 + vv);
    Eigen::Matrix3d Q;
    Q << 1 + f * (v.x() * v.x() - vv), f * (v.x() * v.y() - v.z()), f * (v.x() * v.z() + v.y()),
        f * (v.y() * v.x() + v.z()), 1 + f * (v.y() * v.y() - vv), f * (v.y() * v.z() - v.x()),
        f * (v.z() * v.x() - v.y()), f * (v.z() * v.y() + v.x()), 1 + f * (v.z() * v.z() - vv);
    R = R * Q;
    if (step <= 1e-14) {
      // Reject a nearly degenerate F, as the cold path does (det F = det M), then one
      // Newton-Schulz step removes the rounding that products of rotations accumulate.
      if (!(M.determinant() > 1e-6 * trace * trace * trace)) break;
      return 0.5 * R * (3.0 * Eigen::Matrix3d::Identity() - R.transpose() * R);
    }
  }
  return polarRotation(F);
}

}  // namespace sculpt
