#include "fem/barrier_stress.h"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>

namespace sculpt {

void recordCurvature(double* record, int points, int lanes, const double* volumeLambda,
                     const double* volumeMu, const InversionBarrier& barrier) {
  // psi = c t^3 with t = threshold - J and c = stiffness / threshold times the bulk modulus
  // V (lambda + 2 mu / 3): psi'' = 6 c t.
  const double perBulk = barrier.stiffness / barrier.threshold;
  for (int q = 0; q < points; ++q) {
    double* group = record + size_t(q / lanes) * 9 * size_t(lanes);
    const int lane = q % lanes;
    Eigen::Matrix3d A;
    for (int rc = 0; rc < 9; ++rc) A(rc / 3, rc % 3) = group[rc * lanes + lane];
    const double t = std::max(0.0, barrier.threshold - A.determinant());
    const double bulk = volumeLambda[q] + 2.0 / 3.0 * volumeMu[q];
    const double root = std::sqrt(6.0 * perBulk * bulk * t);
    // cof(A), written out: A^T cof(A) = det(A) I, also where A is singular.
    for (int r = 0; r < 3; ++r)
      for (int m = 0; m < 3; ++m) {
        const int r1 = (r + 1) % 3, r2 = (r + 2) % 3, m1 = (m + 1) % 3, m2 = (m + 2) % 3;
        group[(r * 3 + m) * lanes + lane] =
            root * (A(r1, m1) * A(r2, m2) - A(r1, m2) * A(r2, m1));
      }
  }
}

}  // namespace sculpt
