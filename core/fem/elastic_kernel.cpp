#include "fem/elastic_kernel.h"

#include <array>

#include "fem/polar_rotation.h"
#include "fem/quadrature.h"
#include "subdiv/tricubic_patch.h"
#include "util/parallel_for.h"

namespace sculpt {
namespace {

// B-spline values and derivatives at the 4 Gauss points and at the centre.
struct TricubicTables {
  double B[4][4], D[4][4];  // [gauss point][basis]
  double Bc[4], Dc[4];
  TricubicTables() {
    const QuadratureRule rule = gaussLegendre(4);
    for (int i = 0; i < 4; ++i) cubicBSplineBasis(rule.points[i], B[i], D[i]);
    cubicBSplineBasis(0.5, Bc, Dc);
  }
};
const TricubicTables& tables() {
  static const TricubicTables t;
  return t;
}

// Stress work at one Gauss point: returns H = V R sigma J^-T (the derivative of the point's
// energy with respect to the parametric gradient) and adds the energy when asked. `gradU` is
// the displacement gradient (or its variation); the strain sym(R^T (I + gradU)) - I is formed
// as sym(R^T gradU) + (sym(R) - I) so that small strains of stiff materials keep their digits
// (positions of size L would otherwise add E * L * 1e-16 of noise to every stress).
inline Eigen::Matrix3d gaussPointStress(const Eigen::Matrix3d& gradU, const Eigen::Matrix3d& R,
                                        const Eigen::Matrix3d& inverseJacobianT, double volume,
                                        const LameParameters& lame, bool withRestTerm,
                                        double* energy) {
  Eigen::Matrix3d eps = R.transpose() * gradU;
  eps = 0.5 * (eps + eps.transpose()).eval();
  if (withRestTerm) {
    eps += 0.5 * (R + R.transpose());
    eps -= Eigen::Matrix3d::Identity();
  }
  const double trace = eps.trace();
  Eigen::Matrix3d sigma = 2.0 * lame.mu * eps;
  sigma.diagonal().array() += lame.lambda * trace;
  if (energy)
    *energy += volume * (lame.mu * eps.squaredNorm() + 0.5 * lame.lambda * trace * trace);
  return volume * R * sigma * inverseJacobianT;
}

}  // namespace

ElasticKernel::ElasticKernel(const FemMesh& mesh)
    : mesh_(mesh), rotations_(mesh.numElements(), Eigen::Matrix3d::Identity()) {}

void ElasticKernel::resetRotations() {
  rotations_.assign(mesh_.numElements(), Eigen::Matrix3d::Identity());
}

void ElasticKernel::updateRotations(const Points& nodes) {
  const TricubicTables& T = tables();
  const uint32_t numTricubic = mesh_.numTricubic();
  parallelChunks(mesh_.numElements(), 256, [&](uint32_t begin, uint32_t end, unsigned) {
    for (uint32_t e = begin; e < end; ++e) {
      Eigen::Matrix3d F = Eigen::Matrix3d::Zero();
      if (e < numTricubic) {
        const auto& ids = mesh_.tricubicNodes[e];
        Eigen::Matrix3d G = Eigen::Matrix3d::Zero();
        for (int a = 0; a < 4; ++a)
          for (int b = 0; b < 4; ++b)
            for (int g = 0; g < 4; ++g) {
              const Eigen::Vector3d x = nodes.row(ids[a * 16 + b * 4 + g]).transpose();
              G.col(0) += T.Dc[a] * T.Bc[b] * T.Bc[g] * x;
              G.col(1) += T.Bc[a] * T.Dc[b] * T.Bc[g] * x;
              G.col(2) += T.Bc[a] * T.Bc[b] * T.Dc[g] * x;
            }
        F = G * mesh_.tricubicCentreInverseJacobian[e];
      } else {
        const uint32_t l = e - numTricubic;
        const auto& ids = mesh_.linearNodes[l];
        const LinearShapeGradient& dN = mesh_.linearCentreShapeGradient[l];
        for (int a = 0; a < kLinearNodes; ++a)
          F += nodes.row(ids[a]).transpose() * dN.row(a);
      }
      rotations_[e] = polarRotation(F);
    }
  });
}

double ElasticKernel::energy(const Points& nodes) const {
  return run(nodes, Mode::Gradient, nullptr, true);
}

void ElasticKernel::addGradient(const Points& nodes, Points& gradient) const {
  run(nodes, Mode::Gradient, &gradient, false);
}

void ElasticKernel::addHessianProduct(const Points& dx, Points& result) const {
  run(dx, Mode::HessianProduct, &result, false);
}

double ElasticKernel::run(const Points& x, Mode mode, Points* out, bool withEnergy) const {
  const TricubicTables& T = tables();
  const bool subtractIdentity = mode == Mode::Gradient;
  const Points& rest = mesh_.restNodes;
  const uint32_t numTricubic = mesh_.numTricubic();
  const Eigen::Index numNodes = mesh_.numNodes();
  const unsigned workers = workerCount();
  if (out) {
    workerBuffers_.resize(workers);
    for (Points& buffer : workerBuffers_) buffer.setZero(numNodes, 3);
  }
  std::vector<double> workerEnergy(workers, 0.0);

  parallelChunks(mesh_.numElements(), 64, [&](uint32_t begin, uint32_t end, unsigned worker) {
    Points* sink = out ? &workerBuffers_[worker] : nullptr;
    double* energy = withEnergy ? &workerEnergy[worker] : nullptr;
    for (uint32_t e = begin; e < end; ++e) {
      const Eigen::Matrix3d& R = rotations_[e];
      const uint32_t gauss0 = mesh_.gaussBegin(e);
      if (e < numTricubic) {
        const auto& ids = mesh_.tricubicNodes[e];
        double xe[64][3];  // displacements (gradient) or the direction (Hessian)
        for (int n = 0; n < 64; ++n)
          for (int c = 0; c < 3; ++c)
            xe[n][c] = subtractIdentity ? x(ids[n], c) - rest(ids[n], c) : x(ids[n], c);
        // Forward sum factorisation: contract w, then v, then u.
        double P0[4][4][4][3], P1[4][4][4][3];  // [a][b][k][c]
        for (int a = 0; a < 4; ++a)
          for (int b = 0; b < 4; ++b)
            for (int k = 0; k < 4; ++k)
              for (int c = 0; c < 3; ++c) {
                double s0 = 0, s1 = 0;
                for (int g = 0; g < 4; ++g) {
                  s0 += T.B[k][g] * xe[a * 16 + b * 4 + g][c];
                  s1 += T.D[k][g] * xe[a * 16 + b * 4 + g][c];
                }
                P0[a][b][k][c] = s0;
                P1[a][b][k][c] = s1;
              }
        double Q00[4][4][4][3], Q10[4][4][4][3], Q01[4][4][4][3];  // [a][j][k][c]
        for (int a = 0; a < 4; ++a)
          for (int j = 0; j < 4; ++j)
            for (int k = 0; k < 4; ++k)
              for (int c = 0; c < 3; ++c) {
                double s00 = 0, s10 = 0, s01 = 0;
                for (int b = 0; b < 4; ++b) {
                  s00 += T.B[j][b] * P0[a][b][k][c];
                  s10 += T.D[j][b] * P0[a][b][k][c];
                  s01 += T.B[j][b] * P1[a][b][k][c];
                }
                Q00[a][j][k][c] = s00;
                Q10[a][j][k][c] = s10;
                Q01[a][j][k][c] = s01;
              }
        double Hu[4][4][4][3], Hv[4][4][4][3], Hw[4][4][4][3];  // [i][j][k][c]
        for (int i = 0; i < 4; ++i)
          for (int j = 0; j < 4; ++j)
            for (int k = 0; k < 4; ++k) {
              Eigen::Matrix3d G;
              for (int c = 0; c < 3; ++c) {
                double su = 0, sv = 0, sw = 0;
                for (int a = 0; a < 4; ++a) {
                  su += T.D[i][a] * Q00[a][j][k][c];
                  sv += T.B[i][a] * Q10[a][j][k][c];
                  sw += T.B[i][a] * Q01[a][j][k][c];
                }
                G(c, 0) = su;
                G(c, 1) = sv;
                G(c, 2) = sw;
              }
              const int q = i * 16 + j * 4 + k;
              const Eigen::Matrix3d& Jinv = mesh_.tricubicInverseJacobian[size_t(e) * 64 + q];
              const Eigen::Matrix3d H =
                  gaussPointStress(G * Jinv, R, Jinv.transpose(), mesh_.gaussVolume[gauss0 + q],
                                   mesh_.gaussLame[gauss0 + q], subtractIdentity, energy);
              for (int c = 0; c < 3; ++c) {
                Hu[i][j][k][c] = H(c, 0);
                Hv[i][j][k][c] = H(c, 1);
                Hw[i][j][k][c] = H(c, 2);
              }
            }
        if (!sink) continue;
        // Transposed contractions: u, then v, then w.
        for (int a = 0; a < 4; ++a)
          for (int j = 0; j < 4; ++j)
            for (int k = 0; k < 4; ++k)
              for (int c = 0; c < 3; ++c) {
                double s00 = 0, s10 = 0, s01 = 0;
                for (int i = 0; i < 4; ++i) {
                  s00 += T.D[i][a] * Hu[i][j][k][c];
                  s10 += T.B[i][a] * Hv[i][j][k][c];
                  s01 += T.B[i][a] * Hw[i][j][k][c];
                }
                Q00[a][j][k][c] = s00;
                Q10[a][j][k][c] = s10;
                Q01[a][j][k][c] = s01;
              }
        for (int a = 0; a < 4; ++a)
          for (int b = 0; b < 4; ++b)
            for (int k = 0; k < 4; ++k)
              for (int c = 0; c < 3; ++c) {
                double s0 = 0, s1 = 0;
                for (int j = 0; j < 4; ++j) {
                  s0 += T.B[j][b] * Q00[a][j][k][c] + T.D[j][b] * Q10[a][j][k][c];
                  s1 += T.B[j][b] * Q01[a][j][k][c];
                }
                P0[a][b][k][c] = s0;
                P1[a][b][k][c] = s1;
              }
        for (int a = 0; a < 4; ++a)
          for (int b = 0; b < 4; ++b)
            for (int g = 0; g < 4; ++g) {
              const uint32_t node = ids[a * 16 + b * 4 + g];
              for (int c = 0; c < 3; ++c) {
                double s = 0;
                for (int k = 0; k < 4; ++k)
                  s += T.B[k][g] * P0[a][b][k][c] + T.D[k][g] * P1[a][b][k][c];
                (*sink)(node, c) += s;
              }
            }
      } else {
        const uint32_t l = e - numTricubic;
        const auto& ids = mesh_.linearNodes[l];
        Eigen::Matrix<double, kLinearNodes, 3> xe, ge = Eigen::Matrix<double, kLinearNodes, 3>::Zero();
        for (int a = 0; a < kLinearNodes; ++a)
          xe.row(a) = subtractIdentity ? Eigen::RowVector3d(x.row(ids[a]) - rest.row(ids[a]))
                                       : Eigen::RowVector3d(x.row(ids[a]));
        for (int q = 0; q < kLinearGaussPoints; ++q) {
          const LinearShapeGradient& dN = mesh_.linearShapeGradient[size_t(l) * 8 + q];
          const Eigen::Matrix3d F = xe.transpose() * dN;
          const Eigen::Matrix3d H =
              gaussPointStress(F, R, Eigen::Matrix3d::Identity(), mesh_.gaussVolume[gauss0 + q],
                               mesh_.gaussLame[gauss0 + q], subtractIdentity, energy);
          ge.noalias() += dN * H.transpose();
        }
        if (!sink) continue;
        for (int a = 0; a < kLinearNodes; ++a) sink->row(ids[a]) += ge.row(a);
      }
    }
  });

  if (out) {
    for (unsigned w = 0; w < workers; ++w) *out += workerBuffers_[w];
  }
  double total = 0;
  for (double v : workerEnergy) total += v;
  return total;
}

}  // namespace sculpt
