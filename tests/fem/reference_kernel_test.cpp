// The optimised kernels (sum factorisation, packed and vectorised Gauss points) against a
// deliberately naive re-implementation written from the formulas of docs/design/local-frame-fem.md:
//   E = sum_e sum_q w_q det J_q (mu eps:eps + lambda/2 tr(eps)^2),  eps = sym(R_e^T F_q) - I,
//   F_q = sum_n x_n (x) grad N_n,  grad N_n = J_q^-T grad_xi N_n,  J_q = sum_n X_n (x) grad_xi N_n,
// with its own B-spline and trilinear shape functions, its own Gauss abscissae (closed forms)
// and its own polar decomposition. Only the connectivity and rest node positions come from
// the FemMesh. Non-affine, large, rotated deformations: this is where an index slip in a
// contraction would show (patch and rigid-motion tests only exercise affine fields).

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <Eigen/LU>
#include <Eigen/SVD>
#include <cmath>
#include <cstdio>
#include <functional>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "fem/elastic_kernel.h"
#include "fem/fem_model.h"
#include "fem/tricubic_kernel.h"
#include "support/fem_builders.h"
#include "support/mesh_builders.h"

namespace sculpt {
namespace {

using namespace sculpt::test;

struct Rule {
  std::vector<double> x, w;
};
/// Gauss-Legendre on [0, 1] from the closed forms on [-1, 1].
Rule gauss(int n) {
  std::vector<double> x, w;
  if (n == 2) {
    x = {-1 / std::sqrt(3.0), 1 / std::sqrt(3.0)};
    w = {1, 1};
  } else {
    const double a = std::sqrt(3.0 / 7 - 2.0 / 7 * std::sqrt(6.0 / 5));
    const double b = std::sqrt(3.0 / 7 + 2.0 / 7 * std::sqrt(6.0 / 5));
    const double wa = (18 + std::sqrt(30.0)) / 36, wb = (18 - std::sqrt(30.0)) / 36;
    x = {-b, -a, a, b};
    w = {wb, wa, wa, wb};
  }
  Rule r;
  for (size_t i = 0; i < x.size(); ++i) {
    r.x.push_back(0.5 * (x[i] + 1));
    r.w.push_back(0.5 * w[i]);
  }
  return r;
}
/// Two-point Gauss-Jacobi rule for the weight (1 - w)^2 on [0, 1], divided back out.
Rule collapsed() {
  const double s = std::sqrt(2.0 / 45);
  const double w0 = 1.0 / 3 - s, w1 = 1.0 / 3 + s;
  // Weights from the moments 1/3 and 1/12 of (1 - w)^2 (Cramer's rule).
  const double a0 = (w1 / 3 - 1.0 / 12) / (w1 - w0), a1 = (1.0 / 12 - w0 / 3) / (w1 - w0);
  return {{w0, w1}, {a0 / ((1 - w0) * (1 - w0)), a1 / ((1 - w1) * (1 - w1))}};
}

void bspline(double t, double B[4], double D[4]) {
  B[0] = (1 - t) * (1 - t) * (1 - t) / 6;
  B[1] = (3 * t * t * t - 6 * t * t + 4) / 6;
  B[2] = (-3 * t * t * t + 3 * t * t + 3 * t + 1) / 6;
  B[3] = t * t * t / 6;
  D[0] = -(1 - t) * (1 - t) / 2;
  D[1] = 1.5 * t * t - 2 * t;
  D[2] = -1.5 * t * t + t + 0.5;
  D[3] = t * t / 2;
}

/// Shape values and parametric gradients of an element at xi (nodes in the mesh's order).
using ShapeFn = std::function<void(const Eigen::Vector3d&, std::vector<double>&,
                                   std::vector<Eigen::Vector3d>&)>;

void tricubicShape(const Eigen::Vector3d& xi, std::vector<double>& N,
                   std::vector<Eigen::Vector3d>& dN) {
  double B[3][4], D[3][4];
  for (int d = 0; d < 3; ++d) bspline(xi[d], B[d], D[d]);
  N.assign(64, 0);
  dN.assign(64, Eigen::Vector3d::Zero());
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b)
      for (int g = 0; g < 4; ++g) {
        const int n = a * 16 + b * 4 + g;
        N[size_t(n)] = B[0][a] * B[1][b] * B[2][g];
        dN[size_t(n)] = {D[0][a] * B[1][b] * B[2][g], B[0][a] * D[1][b] * B[2][g],
                         B[0][a] * B[1][b] * D[2][g]};
      }
}

void hexShape(const Eigen::Vector3d& xi, std::vector<double>& N, std::vector<Eigen::Vector3d>& dN) {
  // VTK order: bottom (0,0) (1,0) (1,1) (0,1), then the same at w = 1.
  const int corner[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                            {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  N.assign(8, 0);
  dN.assign(8, Eigen::Vector3d::Zero());
  for (int a = 0; a < 8; ++a) {
    double f[3], s[3];
    for (int d = 0; d < 3; ++d) {
      f[d] = corner[a][d] ? xi[d] : 1 - xi[d];
      s[d] = corner[a][d] ? 1 : -1;
    }
    N[size_t(a)] = f[0] * f[1] * f[2];
    dN[size_t(a)] = {s[0] * f[1] * f[2], f[0] * s[1] * f[2], f[0] * f[1] * s[2]};
  }
}

struct ElementView {
  std::vector<uint32_t> nodes;
  ShapeFn shape;
  std::vector<Eigen::Vector3d> points;
  std::vector<double> weights;
};

std::vector<ElementView> elements(const FemMesh& mesh) {
  const Rule g4 = gauss(4), g2 = gauss(2), c2 = collapsed();
  std::vector<ElementView> out;
  for (uint32_t e = 0; e < mesh.numElements(); ++e) {
    ElementView v;
    const bool tricubic = e < mesh.numTricubic();
    if (tricubic) {
      v.nodes.assign(mesh.tricubicNodes[e].begin(), mesh.tricubicNodes[e].end());
      v.shape = tricubicShape;
    } else {
      const auto& ids = mesh.linearNodes[e - mesh.numTricubic()];
      v.nodes.assign(ids.begin(), ids.end());
      v.shape = hexShape;
    }
    const Rule& ru = tricubic ? g4 : g2;
    const Rule& rw = tricubic ? g4 : (mesh.elementType[e] == ElementType::Pyramid ? c2 : g2);
    for (size_t i = 0; i < ru.x.size(); ++i)
      for (size_t j = 0; j < ru.x.size(); ++j)
        for (size_t k = 0; k < rw.x.size(); ++k) {
          v.points.emplace_back(ru.x[i], ru.x[j], rw.x[k]);
          v.weights.push_back(ru.w[i] * ru.w[j] * rw.w[k]);
        }
    out.push_back(std::move(v));
  }
  return out;
}

Eigen::Matrix3d svdRotation(const Eigen::Matrix3d& F) {
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(F, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d U = svd.matrixU();
  if ((U * svd.matrixV().transpose()).determinant() < 0) U.col(2) *= -1;
  return U * svd.matrixV().transpose();
}

struct Reference {
  double energy = 0;
  Points gradient;
  std::vector<Eigen::Matrix3d> centreRotation;  ///< own polar decomposition at xi = (1/2)^3
};

/// Naive evaluation. `rotations` are the element frames to use; `rest`: subtract I (gradient
/// mode) or not (a Hessian product of x).
/// Material at a rest position (Young's modulus, Poisson ratio).
using MaterialField = std::function<Material(const Eigen::Vector3d&)>;

Reference naive(
    const FemMesh& mesh, const std::vector<ElementView>& views, const Points& x,
    const std::vector<Eigen::Matrix3d>& rotations, bool rest,
    const MaterialField& field = [](const Eigen::Vector3d&) { return Material{}; }) {
  Reference r;
  r.gradient = Points::Zero(x.rows(), 3);
  std::vector<double> N;
  std::vector<Eigen::Vector3d> dN;
  for (size_t e = 0; e < views.size(); ++e) {
    const ElementView& v = views[e];
    const Eigen::Matrix3d& R = rotations[e];
    auto gradients = [&](const Eigen::Vector3d& xi, Eigen::Matrix3d& Jinv, double& det) {
      v.shape(xi, N, dN);
      Eigen::Matrix3d J = Eigen::Matrix3d::Zero();
      for (size_t n = 0; n < v.nodes.size(); ++n)
        J += mesh.restNodes.row(v.nodes[n]).transpose() * dN[n].transpose();
      det = J.determinant();
      Jinv = J.inverse();
    };
    {
      Eigen::Matrix3d Jinv;
      double det;
      gradients({0.5, 0.5, 0.5}, Jinv, det);
      Eigen::Matrix3d F = Eigen::Matrix3d::Zero();
      for (size_t n = 0; n < v.nodes.size(); ++n)
        F += x.row(v.nodes[n]).transpose() * (Jinv.transpose() * dN[n]).transpose();
      r.centreRotation.push_back(svdRotation(F));
    }
    for (size_t q = 0; q < v.points.size(); ++q) {
      Eigen::Matrix3d Jinv;
      double det;
      gradients(v.points[q], Jinv, det);
      Eigen::Vector3d position = Eigen::Vector3d::Zero();
      for (size_t n = 0; n < v.nodes.size(); ++n)
        position += N[n] * mesh.restNodes.row(v.nodes[n]).transpose();
      const Material material = field(position);
      const double E = material.youngs, nu = material.poisson;
      const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
      std::vector<Eigen::Vector3d> grad(v.nodes.size());
      Eigen::Matrix3d F = Eigen::Matrix3d::Zero();
      for (size_t n = 0; n < v.nodes.size(); ++n) {
        grad[n] = Jinv.transpose() * dN[n];
        F += x.row(v.nodes[n]).transpose() * grad[n].transpose();
      }
      Eigen::Matrix3d eps = 0.5 * (R.transpose() * F + F.transpose() * R);
      if (rest) eps -= Eigen::Matrix3d::Identity();
      const double volume = v.weights[q] * det;
      const double tr = eps.trace();
      r.energy += volume * (mu * (eps.array() * eps.array()).sum() + 0.5 * lambda * tr * tr);
      const Eigen::Matrix3d P =
          volume * R * (2 * mu * eps + lambda * tr * Eigen::Matrix3d::Identity());
      for (size_t n = 0; n < v.nodes.size(); ++n)
        r.gradient.row(v.nodes[n]) += (P * grad[n]).transpose();
    }
  }
  return r;
}

// boxes: block3 (27 unit cubes) instead of the jittered mixed mesh; its interior elements at
// level 2 are affine and aligned with the axes, which the kernel runs through a path of its own
// (tricubic_kernel.h).
void compareWithNaive(bool painted, bool boxes = false) {
  std::string error;
  auto model = FemModel::create(boxes ? block3() : jittered(mixedMesh(), 0.05, 8),
                                FemSetup{2, false, Material{}}, &error);
  ASSERT_TRUE(model) << error;
  // Optionally a stiff, nearly incompressible ball across element boundaries: the packed
  // per-Gauss-point moduli must follow the Gauss points' positions. The ball spans from the
  // centre of the first tricubic element to the centre of the last (pyramid) element.
  const FemMesh& m0 = model->mesh();
  const Eigen::Vector3d a = m0.gaussRestPosition[32], b = m0.gaussRestPosition.back();
  const Eigen::Vector3d centre = 0.5 * (a + b);
  const double radius = 0.55 * (a - b).norm();
  Material stiff;
  stiff.youngs = 4e6;
  stiff.poisson = 0.45;
  MaterialField field = [](const Eigen::Vector3d&) { return Material{}; };
  if (painted) {
    const long changed = model->paintMaterial(centre, radius, stiff, &error);
    ASSERT_GT(changed, 0) << error;
    ASSERT_LT(changed, long(model->mesh().numGaussPoints()));
    // The ball covers Gauss points of every element type.
    bool hit[3] = {false, false, false};
    const FemMesh& m = model->mesh();
    for (uint32_t e = 0; e < m.numElements(); ++e)
      for (uint32_t q = m.gaussBegin(e); q < m.gaussBegin(e) + m.gaussCount(e); ++q)
        hit[int(m.elementType[e])] |= m.gaussMaterial[q].youngs == stiff.youngs;
    EXPECT_TRUE(hit[0] && hit[1] && (hit[2] || boxes)) << hit[0] << hit[1] << hit[2];
    field = [&](const Eigen::Vector3d& X) {
      return (X - centre).norm() <= radius ? stiff : Material{};
    };
  }
  const FemMesh& mesh = model->mesh();
  ASSERT_GT(mesh.counts().tricubic, 0u);
  if (!boxes) {
    ASSERT_GT(mesh.counts().pyramid, 0u);
  }
  // The kernel runs affine elements aligned with the axes through a path of their own
  // (tricubic_kernel.h): block3 has some, and others.
  uint32_t axisAligned = 0;
  for (uint32_t e = 0; e < mesh.numTricubic(); ++e) {
    const Eigen::Matrix3d* J = mesh.tricubicInverseJacobian.data() + size_t(e) * 64;
    int8_t rows[3];
    axisAligned += affineInverseJacobians(J) && axisAlignedRows(J[0], rows);
  }
  std::printf("%u of %u tricubic elements are affine and aligned with the axes\n", axisAligned,
              mesh.numTricubic());
  if (boxes) {
    EXPECT_GT(axisAligned, 0u);
    EXPECT_LT(axisAligned, mesh.numTricubic());
  }
  const std::vector<ElementView> views = elements(mesh);

  // Own rest volumes against the stored Gauss volumes.
  double volumeError = 0;
  {
    std::vector<double> N;
    std::vector<Eigen::Vector3d> dN;
    for (uint32_t e = 0; e < mesh.numElements(); ++e)
      for (size_t q = 0; q < views[e].points.size(); ++q) {
        views[e].shape(views[e].points[q], N, dN);
        Eigen::Matrix3d J = Eigen::Matrix3d::Zero();
        for (size_t n = 0; n < views[e].nodes.size(); ++n)
          J += mesh.restNodes.row(views[e].nodes[n]).transpose() * dN[n].transpose();
        const double own = views[e].weights[q] * J.determinant();
        volumeError =
            std::max(volumeError, std::abs(own - mesh.gaussVolume[mesh.gaussBegin(e) + q]) / own);
      }
  }
  EXPECT_LT(volumeError, 1e-12);

  // A non-affine, large deformation: bend about z, twist, noise, then a big rotation.
  std::mt19937_64 rng(77);
  std::uniform_real_distribution<double> uni(-1, 1);
  const Eigen::Matrix3d Q = randomRotation(rng);
  Points x(mesh.numNodes(), 3);
  for (Eigen::Index n = 0; n < x.rows(); ++n) {
    const Eigen::Vector3d X = mesh.restNodes.row(n).transpose();
    const double angle = 0.3 * X.x();
    Eigen::Vector3d y(X.x() - 0.2 * X.y() * X.y(), X.y() + 0.15 * X.x() * X.z(),
                      X.z() + 0.1 * std::sin(X.x()));
    y = Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitX()) * y;
    y += 0.02 * Eigen::Vector3d(uni(rng), uni(rng), uni(rng));
    x.row(n) = (Q * y).transpose() + Eigen::RowVector3d(2, -1, 0.5);
  }
  ElasticKernel& kernel = model->elastic();
  kernel.updateRotations(x);
  const Reference ref = naive(mesh, views, x, kernel.rotations(), true, field);

  double rotationError = 0;
  for (uint32_t e = 0; e < mesh.numElements(); ++e)
    rotationError = std::max(rotationError,
                             (kernel.rotations()[e] - ref.centreRotation[e]).cwiseAbs().maxCoeff());
  EXPECT_LT(rotationError, 1e-10);

  const double energy = kernel.energy(x);
  const double energyError = std::abs(energy - ref.energy) / ref.energy;
  EXPECT_LT(energyError, 1e-11);
  Points g = Points::Zero(x.rows(), 3);
  kernel.addGradient(x, g);
  const double gradientError =
      (g - ref.gradient).cwiseAbs().maxCoeff() / ref.gradient.cwiseAbs().maxCoeff();
  EXPECT_LT(gradientError, 1e-11);

  // Hessian product with the same frames: the naive gradient of dx without the rest term.
  Points dx(x.rows(), 3);
  for (Eigen::Index n = 0; n < dx.rows(); ++n)
    dx.row(n) = Eigen::RowVector3d(uni(rng), uni(rng), uni(rng));
  const Reference refH = naive(mesh, views, dx, kernel.rotations(), false, field);
  Points h = Points::Zero(x.rows(), 3);
  kernel.addHessianProduct(dx, h);
  const double hessianError =
      (h - refH.gradient).cwiseAbs().maxCoeff() / refH.gradient.cwiseAbs().maxCoeff();
  EXPECT_LT(hessianError, 1e-11);

  std::printf(
      "naive reference%s on level-2 %s (%u tricubic, %u trilinear, %u pyramid): "
      "volume rel.err %.2g, |R_e - R_naive| %.2g, energy %.10g vs %.10g (rel.err %.2g), "
      "gradient rel.err %.2g, Hessian product rel.err %.2g\n",
      painted ? " (painted ball)" : "", boxes ? "block3" : "mixed mesh", mesh.counts().tricubic,
      mesh.counts().trilinear, mesh.counts().pyramid, volumeError, rotationError, energy,
      ref.energy, energyError, gradientError, hessianError);
}

TEST(ReferenceKernel, UniformMaterial) { compareWithNaive(false); }

TEST(ReferenceKernel, PaintedMaterial) { compareWithNaive(true); }

TEST(ReferenceKernel, PaintedBlockOfCubes) { compareWithNaive(true, true); }

}  // namespace
}  // namespace sculpt
