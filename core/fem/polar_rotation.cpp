#include "fem/polar_rotation.h"

#include <Eigen/LU>
#include <Eigen/SVD>
#include <algorithm>
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
  Eigen::Matrix3d R;
  polarRotations(&F, &guess, 1, &R);
  return R;
}

void polarRotations(const Eigen::Matrix3d* F, const Eigen::Matrix3d* guess, int count,
                    Eigen::Matrix3d* rotations) {
  // R = guess * Q with Q^T (guess^T F) symmetric. With M = R^T F and Q ~ I + [w]x, the skew
  // part of Q^T M vanishes to first order for (tr(M) I - M) w = 2 axial(skew M), because
  // [w]x M + M^T [w]x = [(tr(M) I - M) w]x. Each correction is applied as a Cayley rotation,
  // which is orthogonal to rounding; the iteration converges quadratically.
  // The four problems run in the lanes of 4-wide vectors; a lane that leaves the warm path goes
  // to the cold iteration on its own. Unused lanes repeat the last problem.
  using V4 = Eigen::Array4d;
  V4 f[3][3], r[3][3], done[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int l = 0; l < 4; ++l) {
        const int k = std::min(l, count - 1);
        f[i][j][l] = F[k](i, j);
        r[i][j][l] = guess[k](i, j);
        done[i][j][l] = guess[k](i, j);
      }
  enum class Lane { Running, Converged, Cold };
  Lane lane[4] = {Lane::Running, Lane::Running, Lane::Running, Lane::Running};
  auto anyRunning = [&] {
    for (int l = 0; l < count; ++l)
      if (lane[l] == Lane::Running) return true;
    return false;
  };
  for (int iteration = 0; iteration < 4 && anyRunning(); ++iteration) {
    V4 m[3][3];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        m[i][j] = r[0][i] * f[0][j] + r[1][i] * f[1][j] + r[2][i] * f[2][j];
    const V4 trace = m[0][0] + m[1][1] + m[2][2];
    const V4 sx = m[2][1] - m[1][2], sy = m[0][2] - m[2][0], sz = m[1][0] - m[0][1];
    // A = tr(M) I - M by its adjugate (rows of cofactors).
    const V4 a00 = trace - m[0][0], a11 = trace - m[1][1], a22 = trace - m[2][2];
    const V4 a01 = -m[0][1], a02 = -m[0][2], a10 = -m[1][0], a12 = -m[1][2], a20 = -m[2][0],
             a21 = -m[2][1];
    const V4 c00 = a11 * a22 - a12 * a21, c01 = a02 * a21 - a01 * a22, c02 = a01 * a12 - a02 * a11;
    const V4 c10 = a12 * a20 - a10 * a22, c11 = a00 * a22 - a02 * a20, c12 = a02 * a10 - a00 * a12;
    const V4 c20 = a10 * a21 - a11 * a20, c21 = a01 * a20 - a00 * a21, c22 = a00 * a11 - a01 * a10;
    const V4 det = a00 * c00 + a01 * c10 + a02 * c20;
    const V4 floor = 1e-6 * trace * trace * trace;
    const V4 inv = 1.0 / det;
    const V4 wx = inv * (c00 * sx + c01 * sy + c02 * sz);
    const V4 wy = inv * (c10 * sx + c11 * sy + c12 * sz);
    const V4 wz = inv * (c20 * sx + c21 * sy + c22 * sz);
    const V4 step = wx * wx + wy * wy + wz * wz;
    // det F = det M: a nearly degenerate F is rejected, as the cold path does.
    const V4 detM = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                    m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                    m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    // Cayley rotation of w: I + 2/(1 + |v|^2) ([v]x + [v]x^2), v = w/2.
    const V4 vx = 0.5 * wx, vy = 0.5 * wy, vz = 0.5 * wz;
    const V4 vv = vx * vx + vy * vy + vz * vz, s = 2.0 / (1.0 + vv);
    const V4 q[3][3] = {{1.0 + s * (vx * vx - vv), s * (vx * vy - vz), s * (vx * vz + vy)},
                        {s * (vy * vx + vz), 1.0 + s * (vy * vy - vv), s * (vy * vz - vx)},
                        {s * (vz * vx - vy), s * (vz * vy + vx), 1.0 + s * (vz * vz - vv)}};
    V4 next[3][3];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        next[i][j] = r[i][0] * q[0][j] + r[i][1] * q[1][j] + r[i][2] * q[2][j];
    for (int l = 0; l < count; ++l) {
      if (lane[l] != Lane::Running) continue;
      // Near the polar rotation A is about tr(S) I - S, positive definite for an SPD stretch
      // S; this also rejects the other stationary points (half turns away), where det A < 0.
      // A far guess (|w| > 1/2) starts cold; so does anything else, NaN included.
      if (!(trace[l] > 0) || !(det[l] > floor[l]) || !(step[l] <= 0.25)) {
        lane[l] = Lane::Cold;
      } else if (step[l] <= 1e-14) {
        lane[l] = detM[l] > floor[l] ? Lane::Converged : Lane::Cold;
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j) done[i][j][l] = next[i][j][l];
      }
    }
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) r[i][j] = next[i][j];
  }
  // One Newton-Schulz step, R (3I - R^T R) / 2, removes the rounding that products of
  // rotations accumulate.
  V4 p[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      p[i][j] = (i == j ? 3.0 : 0.0) - (done[0][i] * done[0][j] + done[1][i] * done[1][j] +
                                        done[2][i] * done[2][j]);
  for (int l = 0; l < count; ++l) {
    if (lane[l] != Lane::Converged) {
      rotations[l] = polarRotation(F[l]);
      continue;
    }
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        rotations[l](i, j) = 0.5 * (done[i][0][l] * p[0][j][l] + done[i][1][l] * p[1][j][l] +
                                    done[i][2][l] * p[2][j][l]);
  }
}

}  // namespace sculpt
