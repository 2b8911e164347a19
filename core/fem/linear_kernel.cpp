#include "fem/linear_kernel.h"

namespace sculpt {

double linearElementKernel(const double* u, const LinearPacked& element, const Eigen::Matrix3d& R,
                           bool withRestTerm, bool withEnergy, double* gradient,
                           BarrierArgs* barrier) {
  using V8 = Eigen::Array<double, 8, 1>;  // the 8 Gauss points
  // Nodes in the element frame: u' = R^T u.
  double ul[8][3];
  for (int a = 0; a < 8; ++a)
    for (int r = 0; r < 3; ++r)
      ul[a][r] = R(0, r) * u[a] + R(1, r) * u[8 + a] + R(2, r) * u[16 + a];
  V8 dN[8][3];
  for (int a = 0; a < 8; ++a)
    for (int c = 0; c < 3; ++c)
      dN[a][c] = Eigen::Map<const V8>(element.shapeGradient + (a * 3 + c) * 8);
  // M = R^T F at every Gauss point.
  V8 M[3][3];
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) {
      M[r][c] = ul[0][r] * dN[0][c];
      for (int a = 1; a < 8; ++a) M[r][c] += ul[a][r] * dN[a][c];
    }
  V8 e[3][3];
  for (int r = 0; r < 3; ++r)
    for (int s = r; s < 3; ++s) {
      const double rest = withRestTerm ? 0.5 * (R(r, s) + R(s, r)) - (r == s ? 1.0 : 0.0) : 0.0;
      e[r][s] = 0.5 * (M[r][s] + M[s][r]) + rest;
    }
  const V8 vl = Eigen::Map<const V8>(element.volumeLambda);
  const V8 vm = Eigen::Map<const V8>(element.volumeMu);
  const V8 trace = e[0][0] + e[1][1] + e[2][2];
  double energy = 0;
  if (withEnergy) {
    const V8 ee = e[0][0] * e[0][0] + e[1][1] * e[1][1] + e[2][2] * e[2][2] +
                  2.0 * (e[0][1] * e[0][1] + e[0][2] * e[0][2] + e[1][2] * e[1][2]);
    energy = (vm * ee + 0.5 * vl * trace * trace).sum();
  }
  const bool withBarrier = barrier && (barrier->settings || barrier->record);
  if (!gradient && !withBarrier) return energy;
  V8 S[3][3];
  for (int r = 0; r < 3; ++r)
    for (int s = r; s < 3; ++s) {
      S[r][s] = 2.0 * vm * e[r][s];
      if (r == s) S[r][s] += vl * trace;
      else S[s][r] = S[r][s];
    }
  if (withBarrier) {
    const V8 psi = applyBarrier(*barrier, M, R, vl, vm, withRestTerm, 0, S);
    if (withEnergy) energy += psi.sum();
  }
  if (!gradient) return energy;
  // g'_a = sum_q S_q dN_a(q), then g_a = R g'_a.
  for (int a = 0; a < 8; ++a) {
    double gl[3];
    for (int r = 0; r < 3; ++r)
      gl[r] = (S[r][0] * dN[a][0] + S[r][1] * dN[a][1] + S[r][2] * dN[a][2]).sum();
    for (int c = 0; c < 3; ++c)
      gradient[c * 8 + a] = R(c, 0) * gl[0] + R(c, 1) * gl[1] + R(c, 2) * gl[2];
  }
  return energy;
}

}  // namespace sculpt
