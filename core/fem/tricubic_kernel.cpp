#include "fem/tricubic_kernel.h"

#include <Eigen/Core>
#include <cmath>

#include "fem/kernel_target.h"
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

using V4 = Eigen::Array4d;
inline V4 load(const double* p) { return Eigen::Map<const V4>(p); }
inline void store(double* p, const V4& v) { Eigen::Map<V4>{p} = v; }

}  // namespace

int tricubicRestSize(bool affine) { return (affine ? 36 : 16 * 36) + 128; }

void packTricubicInverseJacobians(const Eigen::Matrix3d* inverseJacobian, bool affine,
                                  double* block) {
  const int blocks = affine ? 1 : 16;
  for (int ij = 0; ij < blocks; ++ij)
    for (int k = 0; k < 4; ++k)
      for (int rc = 0; rc < 9; ++rc)
        block[ij * 36 + rc * 4 + k] = inverseJacobian[affine ? 0 : ij * 4 + k](rc / 3, rc % 3);
}

void packTricubicMaterial(const double* volume, const LameParameters* lame, bool affine,
                          double* block) {
  double* volumeLambda = block + tricubicRestSize(affine) - 128;
  double* volumeMu = volumeLambda + 64;
  for (int q = 0; q < 64; ++q) {
    volumeLambda[q] = volume[q] * lame[q].lambda;
    volumeMu[q] = volume[q] * lame[q].mu;
  }
}

TricubicPacked tricubicPackedView(const double* block, bool affine, const double* prefetch,
                                  int prefetchCount, const int8_t* axisRows) {
  const double* material = block + tricubicRestSize(affine) - 128;
  return {block, affine ? 0 : 36, material, material + 64,
          prefetch, prefetchCount, affine ? axisRows : nullptr};
}

bool affineInverseJacobians(const Eigen::Matrix3d* inverseJacobian) {
  const double scale = inverseJacobian[0].cwiseAbs().maxCoeff();
  for (int q = 1; q < 64; ++q)
    if ((inverseJacobian[q] - inverseJacobian[0]).cwiseAbs().maxCoeff() > 1e-13 * scale)
      return false;
  return true;
}

bool axisAlignedRows(const Eigen::Matrix3d& inverseJacobian, int8_t rows[3]) {
  const double zero = 1e-13 * inverseJacobian.cwiseAbs().maxCoeff();
  bool rowUsed[3] = {false, false, false};
  for (int col = 0; col < 3; ++col) {
    int nonzero = -1;
    for (int r = 0; r < 3; ++r) {
      if (std::abs(inverseJacobian(r, col)) <= zero) continue;
      if (nonzero >= 0) return false;
      nonzero = r;
    }
    if (nonzero < 0 || rowUsed[nonzero]) return false;
    rowUsed[nonzero] = true;
    rows[col] = static_cast<int8_t>(nonzero);
  }
  return true;
}

namespace {

// The transposed stages C, B and A: from H = S Jinv^T at the Gauss points ([ij][c][k]) back to
// the 64 nodes, out[c*64 + a*16 + b*4 + g].
using GaussRows = double[16][3][4];
[[gnu::always_inline]] SCULPT_KERNEL_TARGET inline void gaussToNodes(const GaussRows& HU,
                                                                     const GaussRows& HV,
                                                                     const GaussRows& HW,
                                                                     double* out) {
  const Tables& T = tables();
  // Transposed stage C: back to g, with g in the vector lanes (no horizontal sums).
  alignas(32) double RBB[16][12], RBD[16][12], RDB[16][12];
  V4 Brow[4], Drow[4];  // [k] over g
  for (int k = 0; k < 4; ++k) {
    Brow[k] = V4(T.B[k][0], T.B[k][1], T.B[k][2], T.B[k][3]);
    Drow[k] = V4(T.D[k][0], T.D[k][1], T.D[k][2], T.D[k][3]);
  }
  for (int ij = 0; ij < 16; ++ij)
    for (int c = 0; c < 3; ++c) {
      V4 db = HU[ij][c][0] * Brow[0], bd = HV[ij][c][0] * Brow[0], bb = HW[ij][c][0] * Drow[0];
      for (int k = 1; k < 4; ++k) {
        db += HU[ij][c][k] * Brow[k];
        bd += HV[ij][c][k] * Brow[k];
        bb += HW[ij][c][k] * Drow[k];
      }
      store(RDB[ij] + c * 4, db);
      store(RBD[ij] + c * 4, bd);
      store(RBB[ij] + c * 4, bb);
    }
  // Transposed stage B: back to b. QB[i][c*16 + b*4 + g].
  alignas(32) double QB[4][48], QD[4][48];
  for (int i = 0; i < 4; ++i)
    for (int c = 0; c < 3; ++c)
      for (int b = 0; b < 4; ++b) {
        V4 qb = V4::Zero(), qd = V4::Zero();
        for (int j = 0; j < 4; ++j) {
          const double wb = T.B[j][b], wd = T.D[j][b];
          qb += wb * load(RBB[i * 4 + j] + c * 4) + wd * load(RBD[i * 4 + j] + c * 4);
          qd += wb * load(RDB[i * 4 + j] + c * 4);
        }
        store(QB[i] + c * 16 + b * 4, qb);
        store(QD[i] + c * 16 + b * 4, qd);
      }
  // Transposed stage A: back to a.
  for (int a = 0; a < 4; ++a)
    for (int n = 0; n < 48; n += 4) {
      V4 sum = T.B[0][a] * load(QB[0] + n) + T.D[0][a] * load(QD[0] + n);
      for (int i = 1; i < 4; ++i) sum += T.B[i][a] * load(QB[i] + n) + T.D[i][a] * load(QD[i] + n);
      store(out + (n / 16) * 64 + a * 16 + n % 16, sum);
    }
}

// The kernel for a general inverse Jacobian (kAxisAligned false) or for one with a single
// nonzero per column (element.axisRows): M = G Jinv and H = S Jinv^T are then one product per
// entry instead of three.
template <bool kAxisAligned>
SCULPT_KERNEL_TARGET double tricubicKernel(const double* u, const TricubicPacked& element,
                                           const Eigen::Matrix3d& R, bool withRestTerm,
                                           bool withEnergy, double* gradient,
                                           BarrierArgs* barrier) {
  const Tables& T = tables();
  // Every stage below works on whole V4 rows (four consecutive values of the fastest index):
  // written out explicitly, since GCC otherwise unrolls the small loops into scalar code.
  // Work in the element frame: u' = R^T u, so the strain needs no rotation per Gauss point;
  // the node forces are rotated back at the end. ul[c][a*16 + b*4 + g].
  alignas(32) double ul[192];
  for (int r = 0; r < 3; ++r)
    for (int n = 0; n < 64; n += 4)
      store(ul + r * 64 + n,
            R(0, r) * load(u + n) + R(1, r) * load(u + 64 + n) + R(2, r) * load(u + 128 + n));
  // Stage A: contract a (the slowest node index). QB[i][c*16 + b*4 + g], QD likewise.
  alignas(32) double QB[4][48], QD[4][48];
  for (int i = 0; i < 4; ++i)
    for (int n = 0; n < 48; n += 4) {
      const int c = n / 16, bg = n % 16;
      V4 qb = V4::Zero(), qd = V4::Zero();
      for (int a = 0; a < 4; ++a) {
        const V4 x = load(ul + c * 64 + a * 16 + bg);
        qb += T.B[i][a] * x;
        qd += T.D[i][a] * x;
      }
      store(QB[i] + n, qb);
      store(QD[i] + n, qd);
    }
  // Stage B: contract b. R??[i*4 + j][c*4 + g].
  alignas(32) double RBB[16][12], RBD[16][12], RDB[16][12];
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      for (int c = 0; c < 3; ++c) {
        V4 bb = V4::Zero(), bd = V4::Zero(), db = V4::Zero();
        for (int b = 0; b < 4; ++b) {
          const double wb = T.B[j][b], wd = T.D[j][b];
          const V4 qb = load(QB[i] + c * 16 + b * 4);
          const V4 qd = load(QD[i] + c * 16 + b * 4);
          bb += wb * qb;
          bd += wd * qb;
          db += wb * qd;
        }
        store(RBB[i * 4 + j] + c * 4, bb);
        store(RBD[i * 4 + j] + c * 4, bd);
        store(RDB[i * 4 + j] + c * 4, db);
      }

  // Element constants: sym(R) - I of the rest term.
  double E0[3][3];
  for (int r = 0; r < 3; ++r)
    for (int s = 0; s < 3; ++s)
      E0[r][s] = withRestTerm ? 0.5 * (R(r, s) + R(s, r)) - (r == s ? 1.0 : 0.0) : 0.0;

  V4 BT[4], DT[4];  // [g] over the four Gauss points k
  for (int g = 0; g < 4; ++g) {
    BT[g] = V4(T.BT[g][0], T.BT[g][1], T.BT[g][2], T.BT[g][3]);
    DT[g] = V4(T.DT[g][0], T.DT[g][1], T.DT[g][2], T.DT[g][3]);
  }
  // An axis-aligned element's one nonzero per column of Jinv (the same at every Gauss point).
  V4 axisScale[3];
  if constexpr (kAxisAligned)
    for (int col = 0; col < 3; ++col)
      axisScale[col] = V4::Constant(element.inverseJacobian[(element.axisRows[col] * 3 + col) * 4]);
  // Stage C and the stresses, four Gauss points (k = 0..3) at a time. The displacement
  // gradient is rotated into the element frame first (M = R^T G), so the stress needs no
  // rotation until it is turned back into node forces.
  alignas(32) double HU[16][3][4], HV[16][3][4], HW[16][3][4];  // [ij][c][k]
  V4 energyLanes = V4::Zero();
  const int prefetchLines = (element.prefetchCount * 8 + 63) / 64;
  const char* prefetch = reinterpret_cast<const char*>(element.prefetch);
  // The barrier's arguments as a local copy, which the record's stores cannot alias. A Hessian
  // product of an element without a recorded state has nothing to do with it.
  const bool withBarrier =
      barrier && (withRestTerm ? barrier->settings || barrier->record
                               : barrier->settings && barrier->state);
  BarrierArgs barrierArgs = withBarrier ? *barrier : BarrierArgs{};
  for (int ij = 0; ij < 16; ++ij) {
    // A sixteenth of the next element's rest data per Gauss-point block.
    for (int line = ij * prefetchLines / 16; line < (ij + 1) * prefetchLines / 16; ++line)
      __builtin_prefetch(prefetch + 64 * line);
    V4 G[3][3];  // G[c][m]: d u_c / d xi_m
    for (int c = 0; c < 3; ++c) {
      G[c][0] = RDB[ij][c * 4] * BT[0];
      G[c][1] = RBD[ij][c * 4] * BT[0];
      G[c][2] = RBB[ij][c * 4] * DT[0];
      for (int g = 1; g < 4; ++g) {
        G[c][0] += RDB[ij][c * 4 + g] * BT[g];
        G[c][1] += RBD[ij][c * 4 + g] * BT[g];
        G[c][2] += RBB[ij][c * 4 + g] * DT[g];
      }
    }
    V4 J[3][3];
    if constexpr (!kAxisAligned)
      for (int r = 0; r < 3; ++r)
        for (int col = 0; col < 3; ++col)
          J[r][col] =
              load(element.inverseJacobian + ij * element.jacobianStride + (r * 3 + col) * 4);
    const V4 vl = load(element.volumeLambda + ij * 4);
    const V4 vm = load(element.volumeMu + ij * 4);
    // M = G Jinv = R^T F (G is already in the element frame).
    V4 M[3][3];
    for (int r = 0; r < 3; ++r)
      for (int col = 0; col < 3; ++col) {
        if constexpr (kAxisAligned)
          M[r][col] = G[r][element.axisRows[col]] * axisScale[col];
        else
          M[r][col] = G[r][0] * J[0][col] + G[r][1] * J[1][col] + G[r][2] * J[2][col];
      }
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
    if (withBarrier) {
      const V4 psi = applyBarrier(barrierArgs, M, R, vl, vm, withRestTerm, size_t(ij), S);
      if (withEnergy) energyLanes += psi;
    }
    if (withEnergy) {
      V4 ee = e[0][0] * e[0][0] + e[1][1] * e[1][1] + e[2][2] * e[2][2] +
              2.0 * (e[0][1] * e[0][1] + e[0][2] * e[0][2] + e[1][2] * e[1][2]);
      energyLanes += vm * ee + 0.5 * vl * trace * trace;
    }
    if (!gradient) continue;
    // H = S Jinv^T, in the element frame.
    for (int c = 0; c < 3; ++c) {
      if constexpr (kAxisAligned) {
        double* H[3] = {HU[ij][c], HV[ij][c], HW[ij][c]};  // by row of Jinv
        for (int col = 0; col < 3; ++col)
          store(H[element.axisRows[col]], S[c][col] * axisScale[col]);
      } else {
        store(HU[ij][c], S[c][0] * J[0][0] + S[c][1] * J[0][1] + S[c][2] * J[0][2]);
        store(HV[ij][c], S[c][0] * J[1][0] + S[c][1] * J[1][1] + S[c][2] * J[1][2]);
        store(HW[ij][c], S[c][0] * J[2][0] + S[c][1] * J[2][1] + S[c][2] * J[2][2]);
      }
    }
  }
  if (withBarrier) barrier->active = barrierArgs.active;
  const double energy = energyLanes.sum();
  if (!gradient) return energy;

  // Back to the nodes, in the element frame: ul[c][a*16 + b*4 + g].
  gaussToNodes(HU, HV, HW, ul);
  // Rotated back to the world frame.
  for (int c = 0; c < 3; ++c)
    for (int n = 0; n < 64; n += 4)
      store(gradient + c * 64 + n, R(c, 0) * load(ul + n) + R(c, 1) * load(ul + 64 + n) +
                                       R(c, 2) * load(ul + 128 + n));
  return energy;
}

// The Hessian products at rotation I with the unit vector of each node a and coordinate c, into
// column c*64 + a of K. That vector's displacement gradient at Gauss point (i, j, k) is e_c g^T,
// g the physical gradient of the node's basis function B_a1(xi) B_a2(eta) B_a3(zeta): a product
// of 1D values instead of the forward contractions, which the three coordinates share.
SCULPT_KERNEL_TARGET void restStiffnessColumns(const TricubicPacked& element, double* K) {
  const Tables& T = tables();
  V4 BT[4], DT[4];  // [g] over the four Gauss points k
  for (int g = 0; g < 4; ++g) {
    BT[g] = V4(T.BT[g][0], T.BT[g][1], T.BT[g][2], T.BT[g][3]);
    DT[g] = V4(T.DT[g][0], T.DT[g][1], T.DT[g][2], T.DT[g][3]);
  }
  alignas(32) double H[3][3][16][3][4];  // [c][U, V or W][ij][row][k]
  for (int a = 0; a < 64; ++a) {
    const int a1 = a / 16, a2 = a / 4 % 4, a3 = a % 4;
    for (int ij = 0; ij < 16; ++ij) {
      const int i = ij / 4, j = ij % 4;
      // d B_a / d xi_m over the four Gauss points k.
      const V4 dN[3] = {(T.D[i][a1] * T.B[j][a2]) * BT[a3], (T.B[i][a1] * T.D[j][a2]) * BT[a3],
                        (T.B[i][a1] * T.B[j][a2]) * DT[a3]};
      V4 J[3][3];
      for (int m = 0; m < 3; ++m)
        for (int col = 0; col < 3; ++col)
          J[m][col] =
              load(element.inverseJacobian + ij * element.jacobianStride + (m * 3 + col) * 4);
      V4 g[3];
      for (int col = 0; col < 3; ++col)
        g[col] = dN[0] * J[0][col] + dN[1] * J[1][col] + dN[2] * J[2][col];
      const V4 vl = load(element.volumeLambda + ij * 4);
      const V4 vm = load(element.volumeMu + ij * 4);
      for (int c = 0; c < 3; ++c) {
        // S = 2 mu sym(e_c g^T) + lambda g_c I, times the Gauss volume.
        V4 S[3][3];
        for (int r = 0; r < 3; ++r)
          for (int t = 0; t < 3; ++t) {
            S[r][t] = V4::Zero();
            if (r == c) S[r][t] += vm * g[t];
            if (t == c) S[r][t] += vm * g[r];
            if (r == t) S[r][t] += vl * g[c];
          }
        for (int r = 0; r < 3; ++r)
          for (int m = 0; m < 3; ++m)  // H = S Jinv^T
            store(H[c][m][ij][r], S[r][0] * J[m][0] + S[r][1] * J[m][1] + S[r][2] * J[m][2]);
      }
    }
    for (int c = 0; c < 3; ++c) gaussToNodes(H[c][0], H[c][1], H[c][2], K + (c * 64 + a) * 192);
  }
}

}  // namespace

void tricubicRestStiffness(const TricubicPacked& element, double* K) {
  restStiffnessColumns(element, K);
}

double tricubicElementKernel(const double* u, const TricubicPacked& element,
                             const Eigen::Matrix3d& R, bool withRestTerm, bool withEnergy,
                             double* gradient, BarrierArgs* barrier) {
  return element.axisRows
             ? tricubicKernel<true>(u, element, R, withRestTerm, withEnergy, gradient, barrier)
             : tricubicKernel<false>(u, element, R, withRestTerm, withEnergy, gradient, barrier);
}

}  // namespace sculpt
