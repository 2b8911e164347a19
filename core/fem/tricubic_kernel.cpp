#include "fem/tricubic_kernel.h"

#include <Eigen/Core>

#include "fem/quadrature.h"
#include "subdiv/tricubic_patch.h"

namespace sculpt {
namespace {

struct Tables {
  double B[4][4], D[4][4];    // [gauss i][basis a]
  double BT[4][4], DT[4][4];  // [basis g][gauss k]
  Tables() {
    const QuadratureRule rule = gaussLegendre(4);
    for (int i = 0; i < 4; ++i) cubicBSplineBasis(rule.points[i], B[i], D[i]);
    for (int i = 0; i < 4; ++i)
      for (int a = 0; a < 4; ++a) {
        BT[a][i] = B[i][a];
        DT[a][i] = D[i][a];
      }
  }
};
const Tables& tables() {
  static const Tables t;
  return t;
}

}  // namespace

double tricubicElementKernel(const double* u, const TricubicPacked& element,
                             const Eigen::Matrix3d& R, bool withRestTerm, bool withEnergy,
                             double* gradient) {
  const Tables& T = tables();
  // Work in the element frame: u' = R^T u, so the strain needs no rotation per Gauss point;
  // the node forces are rotated back at the end.
  alignas(32) double ul[192];
  for (int n = 0; n < 64; ++n)
    for (int r = 0; r < 3; ++r)
      ul[n * 3 + r] = R(0, r) * u[n * 3] + R(1, r) * u[n * 3 + 1] + R(2, r) * u[n * 3 + 2];
  u = ul;
  // Stage A: contract a (the slowest index). QB[i][bgc], QD[i][bgc], bgc = b*12 + g*3 + c.
  alignas(32) double QB[4][48], QD[4][48];
  for (int i = 0; i < 4; ++i) {
    for (int n = 0; n < 48; ++n) QB[i][n] = QD[i][n] = 0;
    for (int a = 0; a < 4; ++a) {
      const double b = T.B[i][a], d = T.D[i][a];
      const double* x = u + a * 48;
      for (int n = 0; n < 48; ++n) {
        QB[i][n] += b * x[n];
        QD[i][n] += d * x[n];
      }
    }
  }
  // Stage B: contract b. R??[i][j][gc], gc = g*3 + c.
  alignas(32) double RBB[16][12], RBD[16][12], RDB[16][12];
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      double* bb = RBB[i * 4 + j];
      double* bd = RBD[i * 4 + j];
      double* db = RDB[i * 4 + j];
      for (int n = 0; n < 12; ++n) bb[n] = bd[n] = db[n] = 0;
      for (int b = 0; b < 4; ++b) {
        const double wb = T.B[j][b], wd = T.D[j][b];
        const double* qb = QB[i] + b * 12;
        const double* qd = QD[i] + b * 12;
        for (int n = 0; n < 12; ++n) {
          bb[n] += wb * qb[n];
          bd[n] += wd * qb[n];
          db[n] += wb * qd[n];
        }
      }
    }

  // Element constants: sym(R) - I of the rest term.
  double E0[3][3];
  for (int r = 0; r < 3; ++r)
    for (int s = 0; s < 3; ++s)
      E0[r][s] = withRestTerm ? 0.5 * (R(r, s) + R(s, r)) - (r == s ? 1.0 : 0.0) : 0.0;

  using V4 = Eigen::Array4d;  // four Gauss points along w
  V4 BT[4], DT[4];
  for (int g = 0; g < 4; ++g) {
    BT[g] = V4(T.BT[g][0], T.BT[g][1], T.BT[g][2], T.BT[g][3]);
    DT[g] = V4(T.DT[g][0], T.DT[g][1], T.DT[g][2], T.DT[g][3]);
  }
  double energy = 0;
  // Stage C and the stresses, four Gauss points (k = 0..3) at a time. The displacement
  // gradient is rotated into the element frame first (M = R^T G), so the stress needs no
  // rotation until it is turned back into node forces.
  alignas(32) double HU[16][3][4], HV[16][3][4], HW[16][3][4];  // [ij][c][k]
  V4 energyLanes = V4::Zero();
  for (int ij = 0; ij < 16; ++ij) {
    V4 G[3][3];  // G[c][m]: d u_c / d xi_m
    for (int c = 0; c < 3; ++c)
      for (int m = 0; m < 3; ++m) G[c][m] = V4::Zero();
    for (int g = 0; g < 4; ++g)
      for (int c = 0; c < 3; ++c) {
        G[c][0] += RDB[ij][g * 3 + c] * BT[g];
        G[c][1] += RBD[ij][g * 3 + c] * BT[g];
        G[c][2] += RBB[ij][g * 3 + c] * DT[g];
      }
    V4 J[3][3];
    for (int r = 0; r < 3; ++r)
      for (int col = 0; col < 3; ++col)
        J[r][col] = Eigen::Map<const V4>(element.inverseJacobian + ij * 36 + (r * 3 + col) * 4);
    const V4 vl = Eigen::Map<const V4>(element.volumeLambda + ij * 4);
    const V4 vm = Eigen::Map<const V4>(element.volumeMu + ij * 4);
    // M = G Jinv = R^T F (G is already in the element frame).
    V4 M[3][3];
    for (int r = 0; r < 3; ++r)
      for (int col = 0; col < 3; ++col)
        M[r][col] = G[r][0] * J[0][col] + G[r][1] * J[1][col] + G[r][2] * J[2][col];
    V4 e[3][3];
    for (int r = 0; r < 3; ++r)
      for (int s = r; s < 3; ++s) e[r][s] = 0.5 * (M[r][s] + M[s][r]) + E0[r][s];
    const V4 trace = e[0][0] + e[1][1] + e[2][2];
    V4 S[3][3];
    for (int r = 0; r < 3; ++r)
      for (int s = r; s < 3; ++s) {
        S[r][s] = 2.0 * vm * e[r][s];
        if (r == s) S[r][s] += vl * trace;
        else S[s][r] = S[r][s];
      }
    if (withEnergy) {
      V4 ee = e[0][0] * e[0][0] + e[1][1] * e[1][1] + e[2][2] * e[2][2] +
              2.0 * (e[0][1] * e[0][1] + e[0][2] * e[0][2] + e[1][2] * e[1][2]);
      energyLanes += vm * ee + 0.5 * vl * trace * trace;
    }
    if (!gradient) continue;
    // H = S Jinv^T, in the element frame.
    for (int c = 0; c < 3; ++c) {
      Eigen::Map<V4>{HU[ij][c]} = S[c][0] * J[0][0] + S[c][1] * J[0][1] + S[c][2] * J[0][2];
      Eigen::Map<V4>{HV[ij][c]} = S[c][0] * J[1][0] + S[c][1] * J[1][1] + S[c][2] * J[1][2];
      Eigen::Map<V4>{HW[ij][c]} = S[c][0] * J[2][0] + S[c][1] * J[2][1] + S[c][2] * J[2][2];
    }
  }
  energy = energyLanes.sum();
  if (!gradient) return energy;

  // Transposed stage C: back to g, with g in the vector lanes (no horizontal sums). The
  // transposed stages keep the coordinate-major order n = c*4 + g inside each b block.
  V4 Brow[4], Drow[4];  // [k] over g
  for (int k = 0; k < 4; ++k) {
    Brow[k] = V4(T.B[k][0], T.B[k][1], T.B[k][2], T.B[k][3]);
    Drow[k] = V4(T.D[k][0], T.D[k][1], T.D[k][2], T.D[k][3]);
  }
  for (int ij = 0; ij < 16; ++ij)
    for (int c = 0; c < 3; ++c) {
      V4 db = V4::Zero(), bd = V4::Zero(), bb = V4::Zero();
      for (int k = 0; k < 4; ++k) {
        db += HU[ij][c][k] * Brow[k];
        bd += HV[ij][c][k] * Brow[k];
        bb += HW[ij][c][k] * Drow[k];
      }
      Eigen::Map<V4>{RDB[ij] + c * 4} = db;
      Eigen::Map<V4>{RBD[ij] + c * 4} = bd;
      Eigen::Map<V4>{RBB[ij] + c * 4} = bb;
    }
  // Transposed stage B: back to b.
  for (int i = 0; i < 4; ++i) {
    for (int n = 0; n < 48; ++n) QB[i][n] = QD[i][n] = 0;
    for (int j = 0; j < 4; ++j) {
      const double* bb = RBB[i * 4 + j];
      const double* bd = RBD[i * 4 + j];
      const double* db = RDB[i * 4 + j];
      for (int b = 0; b < 4; ++b) {
        const double wb = T.B[j][b], wd = T.D[j][b];
        double* qb = QB[i] + b * 12;
        double* qd = QD[i] + b * 12;
        for (int n = 0; n < 12; ++n) {
          qb[n] += wb * bb[n] + wd * bd[n];
          qd[n] += wb * db[n];
        }
      }
    }
  }
  // Transposed stage A: back to a, rotated back to the world frame and added to the gradient
  // in node order (g*3 + c).
  for (int a = 0; a < 4; ++a) {
    alignas(32) double sum[48];
    for (int n = 0; n < 48; ++n) sum[n] = 0;
    for (int i = 0; i < 4; ++i) {
      const double b = T.B[i][a], d = T.D[i][a];
      for (int n = 0; n < 48; ++n) sum[n] += b * QB[i][n] + d * QD[i][n];
    }
    double* out = gradient + a * 48;
    for (int b = 0; b < 4; ++b)
      for (int g = 0; g < 4; ++g) {
        const double l0 = sum[b * 12 + g], l1 = sum[b * 12 + 4 + g], l2 = sum[b * 12 + 8 + g];
        for (int c = 0; c < 3; ++c)
          out[b * 12 + g * 3 + c] += R(c, 0) * l0 + R(c, 1) * l1 + R(c, 2) * l2;
      }
  }
  return energy;
}

}  // namespace sculpt
