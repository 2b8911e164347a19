#pragma once
// The inversion barrier of fem/elastic_model.h at a group of Gauss points held in the lanes of an
// Eigen array (4 for the tricubic kernel, 8 for the linear one). Everything is in the element's
// co-rotated frame: A = R^T F, and the stress added is dpsi/dA, which the kernels turn into node
// forces as they do their own stress (det and cofactor are unchanged by the proper rotation R).

#include <Eigen/Core>
#include <cstddef>

#include "fem/elastic_model.h"

namespace sculpt {

/// What a kernel call needs of the barrier. Gradient mode: when `record` is non-null the kernel
/// writes A at every Gauss point there (with or without `settings`: the Jacobian report uses it) (9
/// values per point, lanes fastest, in the kernel's Gauss-point blocks) and sets `active` when some
/// point lies below the threshold. Hessian mode: `state` is that record of this element turned
/// into h by recordCurvature (A itself when the settings ask for the exact Hessian); null means
/// no point of it was below the threshold, so the barrier adds nothing to its Hessian.
struct BarrierArgs {
  const InversionBarrier* settings = nullptr;  ///< null: the corotated model, no barrier
  double* record = nullptr;
  bool active = false;
  const double* state = nullptr;
};

namespace barrier_detail {

// Column m of cof(A): the cross product of the other two columns, so that A^T cof(A) = det(A) I.
template <class V>
[[gnu::always_inline]] inline void cofactorColumn(const V (&A)[3][3], int m, V (&column)[3]) {
  const int p = (m + 1) % 3, q = (m + 2) % 3;
  for (int r = 0; r < 3; ++r) {
    const int r1 = (r + 1) % 3, r2 = (r + 2) % 3;
    column[r] = A[r1][p] * A[r2][q] - A[r2][p] * A[r1][q];
  }
}

template <class V>
void cofactor(const V (&A)[3][3], V (&cof)[3][3]) {
  for (int m = 0; m < 3; ++m) {
    V column[3];
    cofactorColumn(A, m, column);
    for (int r = 0; r < 3; ++r) cof[r][m] = column[r];
  }
}

// det(A) through cof(A)'s first column.
template <class V>
[[gnu::always_inline]] inline V determinant(const V (&A)[3][3]) {
  V first[3];
  cofactorColumn(A, 0, first);
  return A[0][0] * first[0] + A[1][0] * first[1] + A[2][0] * first[2];
}

// psi = c t^3 with t = threshold - J: c per lane, from the lanes' V lambda and V mu (c is the
// barrier's stiffness, in units of the bulk modulus, over the threshold, times V times that
// modulus).
template <class V>
V coefficient(const V& volumeLambda, const V& volumeMu, const InversionBarrier& b) {
  return (b.stiffness / b.threshold) * (volumeLambda + (2.0 / 3.0) * volumeMu);
}

// A 3x3 group of lanes as one object, to pass copies out of line.
template <class V>
struct Lanes {
  V v[3][3];
};

}  // namespace barrier_detail

/// Gradient mode at the lanes' A (= R^T F): adds dpsi/dA to S and returns psi per lane (zero
/// where J >= threshold). `c` is barrier_detail::coefficient per lane. `any` is set when a lane
/// is below the threshold.
template <class V>
[[gnu::noinline]] V addBarrierStress(const V (&A)[3][3], const V& c, const InversionBarrier& b,
                                     V (&S)[3][3], bool& any) {
  const V t = (b.threshold - barrier_detail::determinant(A)).max(0.0);
  if (!(t > 0.0).any()) return V::Zero();
  any = true;
  V cof[3][3];
  barrier_detail::cofactor(A, cof);
  const V slope = -3.0 * c * t * t;  // dpsi/dJ
  for (int r = 0; r < 3; ++r)
    for (int m = 0; m < 3; ++m) S[r][m] += slope * cof[r][m];
  return c * t * t * t;
}

/// Hessian mode from h = sqrt(psi'') cof(A) (recordCurvature): adds (h : dA) h, the Hessian the
/// solvers keep, psi'' cof (x) cof, applied to dA.
template <class V>
[[gnu::noinline]] void addBarrierCurvature(const V (&h)[3][3], const V (&dA)[3][3], V (&S)[3][3]) {
  V dJ = V::Zero();
  for (int r = 0; r < 3; ++r)
    for (int m = 0; m < 3; ++m) dJ += h[r][m] * dA[r][m];
  for (int r = 0; r < 3; ++r)
    for (int m = 0; m < 3; ++m) S[r][m] += dJ * h[r][m];
}

/// Hessian mode, exact (InversionBarrier::exactHessian): adds the barrier's second derivative
/// at the recorded A applied to the direction's dA to S. `c` as for addBarrierStress.
template <class V>
[[gnu::noinline]] void addBarrierHessian(const V (&A)[3][3], const V (&dA)[3][3], const V& c,
                                         const InversionBarrier& b, V (&S)[3][3]) {
  V cof[3][3];
  barrier_detail::cofactor(A, cof);
  const V J = A[0][0] * cof[0][0] + A[1][0] * cof[1][0] + A[2][0] * cof[2][0];
  const V t = (b.threshold - J).max(0.0);
  if (!(t > 0.0).any()) return;
  V dJ = V::Zero();
  for (int r = 0; r < 3; ++r)
    for (int m = 0; m < 3; ++m) dJ += cof[r][m] * dA[r][m];
  const V curvature = 6.0 * c * t * dJ;  // psi'' dJ
  for (int r = 0; r < 3; ++r)
    for (int m = 0; m < 3; ++m) S[r][m] += curvature * cof[r][m];
  // psi' d cof(A)[dA]: column m of cof is a_p x a_q, so its change is da_p x a_q + a_p x da_q.
  const V slope = -3.0 * c * t * t;
  for (int m = 0; m < 3; ++m) {
    const int p = (m + 1) % 3, q = (m + 2) % 3;
    for (int r = 0; r < 3; ++r) {
      const int r1 = (r + 1) % 3, r2 = (r + 2) % 3;
      const V change =
          dA[r1][p] * A[r2][q] - dA[r2][p] * A[r1][q] + A[r1][p] * dA[r2][q] - A[r2][p] * dA[r1][q];
      S[r][m] += slope * change;
    }
  }
}

/// One kernel group of Gauss points (the lanes of V): with `gradientMode`, A = M + R^T (M the
/// lanes' R^T grad u) gets its barrier stress added to S, is recorded at `block` (9 values per
/// lane, lanes fastest) and psi is returned; otherwise (Hessian mode, M the direction's
/// R^T grad d) the recorded state's second derivative along M is added. Zero when nothing acts.
/// Inlined into the kernels: nearly every point is far above the threshold, and there J alone
/// (a few products on values in registers) decides; the stress is computed out of line.
template <class V>
[[gnu::always_inline]] inline V applyBarrier(BarrierArgs& b, const V (&M)[3][3],
                                             const Eigen::Matrix3d& R, const V& volumeLambda,
                                             const V& volumeMu, bool gradientMode, size_t block,
                                             V (&S)[3][3]) {
  constexpr int kLanes = V::SizeAtCompileTime;
  V A[3][3];
  if (gradientMode) {
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) A[r][c] = M[r][c] + R(c, r);
    if (b.record)
      for (int rc = 0; rc < 9; ++rc)
        Eigen::Map<V>(b.record + (block * 9 + size_t(rc)) * kLanes) = A[rc / 3][rc % 3];
    if (!b.settings) return V::Zero();
    if (!(barrier_detail::determinant(A) < b.settings->threshold).any()) return V::Zero();
  } else if (!b.state || !b.settings) {
    return V::Zero();
  }
  // Out of line on copies: the kernel's own S and M, whose addresses never leave it, can then
  // stay in registers on the usual path.
  barrier_detail::Lanes<V> a, m, s;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) {
      a.v[r][c] = gradientMode
                      ? A[r][c]
                      : V(Eigen::Map<const V>(b.state + (block * 9 + size_t(r * 3 + c)) * kLanes));
      m.v[r][c] = M[r][c];
      s.v[r][c] = S[r][c];
    }
  const V coefficient = barrier_detail::coefficient(volumeLambda, volumeMu, *b.settings);
  V psi = V::Zero();
  if (gradientMode)
    psi = addBarrierStress(a.v, coefficient, *b.settings, s.v, b.active);
  else if (b.settings->exactHessian)
    addBarrierHessian(a.v, m.v, coefficient, *b.settings, s.v);
  else
    addBarrierCurvature(a.v, m.v, s.v);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) S[r][c] = s.v[r][c];
  return psi;
}

/// Turns an element's record of A at `points` Gauss points (groups of `lanes`, as the kernels
/// write it) into h = sqrt(psi''(J)) cof(A) in place, zero at points above the threshold: all a
/// Hessian product needs unless the exact Hessian is asked for, so that cof(A) is not found again
/// at every product. `volumeLambda` and `volumeMu` are the points' V lambda and V mu.
void recordCurvature(double* record, int points, int lanes, const double* volumeLambda,
                     const double* volumeMu, const InversionBarrier& barrier);

}  // namespace sculpt
