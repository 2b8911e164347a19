// Regularized Kelvinlets checked against the physics they claim (the Navier equation with their
// own body force) and against their definitions, never against another implementation.

#include "embed/kelvinlet.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace sculpt {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

const Vector3d kCentre(0.2, -0.1, 0.35);
constexpr double kEps = 0.7;

Matrix3d crossMatrix(const Vector3d& q) {
  Matrix3d m;
  m << 0.0, -q.z(), q.y(), q.z(), 0.0, -q.x(), -q.y(), q.x(), 0.0;
  return m;
}

Matrix3d generalLoad() {
  Matrix3d F;
  F << 0.7, -0.3, 0.5, 0.9, -0.2, 0.1, -0.4, 0.6, 0.35;
  return F;
}

Matrix3d pinchLoad() {
  Matrix3d F;
  F << 0.6, 0.2, -0.3, 0.2, -0.9, 0.4, -0.3, 0.4, 0.3;
  return F;
}

struct NamedKelvinlet {
  std::string name;
  RegularizedKelvinlet kelvinlet;
  Matrix3d load;  ///< F of the affine kinds (zero for grab)
};

/// Every kind of load, for one material.
std::vector<NamedKelvinlet> allKinds(KelvinletMaterial material) {
  const Vector3d q(0.4, 0.9, -0.2);
  const double s = 0.8;
  return {
      {"grab", RegularizedKelvinlet::grab(kCentre, Vector3d(0.3, -1.2, 0.7), kEps, material),
       Matrix3d::Zero()},
      {"twist", RegularizedKelvinlet::twist(kCentre, q, kEps, material), crossMatrix(q)},
      {"scale", RegularizedKelvinlet::scale(kCentre, s, kEps, material), s * Matrix3d::Identity()},
      {"pinch", RegularizedKelvinlet::pinch(kCentre, pinchLoad(), kEps, material), pinchLoad()},
      {"affine", RegularizedKelvinlet::affine(kCentre, generalLoad(), kEps, material),
       generalLoad()},
  };
}

std::vector<KelvinletMaterial> materials() {
  return {{1.0, 0.3}, {1.0, 0.45}, {2.5, 0.3}, {2.5, 0.45}};
}

/// `count` points at distances minRadius..maxRadius (in eps) from the centre, random directions.
std::vector<Vector3d> samplePoints(int count, double minRadius, double maxRadius) {
  std::mt19937 rng(20170730);
  std::normal_distribution<double> gauss;
  std::vector<Vector3d> points;
  for (int i = 0; i < count; ++i) {
    Vector3d direction(gauss(rng), gauss(rng), gauss(rng));
    const double t = count > 1 ? double(i) / double(count - 1) : 0.0;
    const double radius = kEps * (minRadius + t * (maxRadius - minRadius));
    points.push_back(kCentre + radius * direction.normalized());
  }
  return points;
}

using Field = std::function<Vector3d(const Vector3d&)>;

/// d u / d X by central differences (row i = gradient of u_i).
Matrix3d gradientFD(const Field& u, const Vector3d& X, double h) {
  Matrix3d G;
  for (int k = 0; k < 3; ++k) {
    const Vector3d step = h * Vector3d::Unit(k);
    G.col(k) = (u(X + step) - u(X - step)) / (2.0 * h);
  }
  return G;
}

/// Second derivatives H[i](j, k) = d^2 u_i / dX_j dX_k by central second differences.
std::array<Matrix3d, 3> hessianFD(const Field& u, const Vector3d& X, double h) {
  std::array<Matrix3d, 3> H;
  const Vector3d u0 = u(X);
  for (int j = 0; j < 3; ++j) {
    for (int k = j; k < 3; ++k) {
      const Vector3d ej = h * Vector3d::Unit(j);
      const Vector3d ek = h * Vector3d::Unit(k);
      const Vector3d d =
          j == k ? Vector3d((u(X + ej) - 2.0 * u0 + u(X - ej)) / (h * h))
                 : Vector3d((u(X + ej + ek) - u(X + ej - ek) - u(X - ej + ek) + u(X - ej - ek)) /
                            (4.0 * h * h));
      for (int i = 0; i < 3; ++i) H[std::size_t(i)](j, k) = H[std::size_t(i)](k, j) = d(i);
    }
  }
  return H;
}

/// The two elastic terms of the Navier operator, from Richardson-extrapolated second differences.
struct NavierTerms {
  Vector3d shear;       ///< mu Lap u
  Vector3d dilatation;  ///< mu / (1 - 2 nu) grad div u
};

NavierTerms navierTermsFD(const RegularizedKelvinlet& k, const Vector3d& X) {
  const Field u = [&](const Vector3d& p) { return k.displacement(p); };
  const double h = 1e-2 * k.eps();
  const std::array<Matrix3d, 3> coarse = hessianFD(u, X, h);
  const std::array<Matrix3d, 3> fine = hessianFD(u, X, 0.5 * h);
  Vector3d lap, gradDiv;
  for (int i = 0; i < 3; ++i) {
    const Matrix3d H = (4.0 * fine[std::size_t(i)] - coarse[std::size_t(i)]) / 3.0;
    lap(i) = H.trace();
    gradDiv(i) = 0.0;
    for (int m = 0; m < 3; ++m)
      gradDiv(i) += (4.0 * fine[std::size_t(m)](i, m) - coarse[std::size_t(m)](i, m)) / 3.0;
  }
  const double mu = k.material().shearModulus;
  const double nu = k.material().poissonRatio;
  return {mu * lap, mu / (1.0 - 2.0 * nu) * gradDiv};
}

// (1) mu Lap u + mu / (1 - 2 nu) grad div u + b = 0 at 20 points, 0.3..3 eps from the centre.
TEST(KelvinletTest, NavierEquationHoldsWithItsBodyForce) {
  const double tolerance = 1e-6;  // relative to the largest of |mu Lap u|, |grad div term|, |b|
  double worst = 0.0;
  for (const KelvinletMaterial& material : materials()) {
    for (const NamedKelvinlet& nk : allKinds(material)) {
      for (const Vector3d& X : samplePoints(20, 0.3, 3.0)) {
        const NavierTerms t = navierTermsFD(nk.kelvinlet, X);
        const Vector3d b = nk.kelvinlet.bodyForceDensity(X);
        const double scale = std::max({t.shear.norm(), t.dilatation.norm(), b.norm()});
        const double residual = (t.shear + t.dilatation + b).norm() / scale;
        worst = std::max(worst, residual);
        EXPECT_LT(residual, tolerance)
            << nk.name << " nu=" << material.poissonRatio << " mu=" << material.shearModulus
            << " at |r|=" << (X - kCentre).norm() / kEps << " eps";
        // The load is not negligible there, so a wrong body force cannot hide in the tolerance
        EXPECT_GT(b.norm(), 1e-3 * scale) << nk.name;
      }
    }
  }
  std::printf("[ measured ] worst relative Navier residual %.3g (tolerance %.0e)\n", worst,
              tolerance);
}

// (2) u(0) = (3 a - 2 b) / (2 eps) f.
TEST(KelvinletTest, GrabTipDisplacement) {
  for (const KelvinletMaterial& material : materials()) {
    const Vector3d f(0.3, -1.2, 0.7);
    const auto k = RegularizedKelvinlet::grab(kCentre, f, kEps, material);
    const double a = 1.0 / (4.0 * std::numbers::pi * material.shearModulus);
    const double b = a / (4.0 * (1.0 - material.poissonRatio));
    const Vector3d expected = (3.0 * a - 2.0 * b) / (2.0 * kEps) * f;
    EXPECT_LT((k.displacement(kCentre) - expected).norm(), 1e-14 * expected.norm());
    EXPECT_LT((k.map(kCentre) - kCentre - expected).norm(), 1e-14 * expected.norm());
  }
}

// (3) The twist, scale and pinch closed forms equal the general affine formula.
TEST(KelvinletTest, SpecialFormsMatchGeneralAffine) {
  double worst = 0.0;
  for (const KelvinletMaterial& material : materials()) {
    const Vector3d q(0.4, 0.9, -0.2);
    const std::vector<std::pair<RegularizedKelvinlet, RegularizedKelvinlet>> pairs = {
        {RegularizedKelvinlet::twist(kCentre, q, kEps, material),
         RegularizedKelvinlet::affine(kCentre, crossMatrix(q), kEps, material)},
        {RegularizedKelvinlet::scale(kCentre, 0.8, kEps, material),
         RegularizedKelvinlet::affine(kCentre, 0.8 * Matrix3d::Identity(), kEps, material)},
        {RegularizedKelvinlet::pinch(kCentre, pinchLoad(), kEps, material),
         RegularizedKelvinlet::affine(kCentre, pinchLoad(), kEps, material)},
    };
    for (const auto& [special, general] : pairs) {
      for (const Vector3d& X : samplePoints(30, 0.05, 20.0)) {
        const Vector3d expected = general.displacement(X);
        const double error = (special.displacement(X) - expected).norm() / expected.norm();
        worst = std::max(worst, error);
        EXPECT_LT(error, 1e-12);
      }
    }
  }
  std::printf("[ measured ] worst relative special/general difference %.3g (tolerance 1e-12)\n",
              worst);
}

// (4) grad u(0) = (b (F^T + F + tr F I) - 2.5 a F) / eps^3, analytic and by finite differences.
TEST(KelvinletTest, CentreGradientMatchesClosedForm) {
  for (const KelvinletMaterial& material : materials()) {
    for (const NamedKelvinlet& nk : allKinds(material)) {
      if (nk.name == "grab") continue;
      const RegularizedKelvinlet& k = nk.kelvinlet;
      const Matrix3d& F = nk.load;
      const double e3 = kEps * kEps * kEps;
      const Matrix3d expected =
          (k.b() * (F.transpose() + F + F.trace() * Matrix3d::Identity()) - 2.5 * k.a() * F) / e3;
      EXPECT_LT((k.displacementGradient(kCentre) - expected).norm(), 1e-13 * expected.norm())
          << nk.name;
      const Field u = [&](const Vector3d& p) { return k.displacement(p); };
      EXPECT_LT((gradientFD(u, kCentre, 1e-4 * kEps) - expected).norm(), 1e-7 * expected.norm())
          << nk.name;
    }
  }
}

// (5) The analytic displacement gradient against central differences of the displacement.
TEST(KelvinletTest, DisplacementGradientMatchesFiniteDifferences) {
  const double tolerance = 1e-7;
  double worst = 0.0;
  for (const KelvinletMaterial& material : materials()) {
    for (const NamedKelvinlet& nk : allKinds(material)) {
      const Field u = [&](const Vector3d& p) { return nk.kelvinlet.displacement(p); };
      for (const Vector3d& X : samplePoints(25, 0.05, 10.0)) {
        const Matrix3d expected = gradientFD(u, X, 1e-4 * kEps);
        const double error =
            (nk.kelvinlet.displacementGradient(X) - expected).norm() / expected.norm();
        worst = std::max(worst, error);
        EXPECT_LT(error, tolerance) << nk.name;
      }
    }
  }
  std::printf("[ measured ] worst relative gradient error %.3g (tolerance %.0e)\n", worst,
              tolerance);
}

// (6) |u| ~ r^-1 for grab and r^-2 for affine loads: least-squares slope of log |u| over
// r = 10..100 eps along several directions.
TEST(KelvinletTest, FarFieldDecayExponents) {
  const KelvinletMaterial material{1.0, 0.45};
  double worst = 0.0;
  for (const NamedKelvinlet& nk : allKinds(material)) {
    const double expectedSlope = nk.name == "grab" ? -1.0 : -2.0;
    for (const Vector3d& direction : {Vector3d(1, 0, 0), Vector3d(0.3, -0.8, 0.5).normalized(),
                                      Vector3d(-1, 1, 1).normalized()}) {
      double sx = 0, sy = 0, sxx = 0, sxy = 0;
      const int n = 21;
      for (int i = 0; i < n; ++i) {
        const double radius = kEps * std::pow(10.0, 1.0 + double(i) / double(n - 1));
        const double x = std::log(radius);
        const double y = std::log(nk.kelvinlet.displacement(kCentre + radius * direction).norm());
        sx += x, sy += y, sxx += x * x, sxy += x * y;
      }
      const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
      worst = std::max(worst, std::abs(slope - expectedSlope));
      EXPECT_NEAR(slope, expectedSlope, 0.02) << nk.name << " direction " << direction.transpose();
    }
  }
  std::printf("[ measured ] worst decay-exponent deviation %.3g (tolerance 0.02)\n", worst);
}

// (7) The twist field is divergence-free (volume-preserving to first order); scale is not.
TEST(KelvinletTest, TwistIsDivergenceFree) {
  for (const KelvinletMaterial& material : materials()) {
    const auto twist =
        RegularizedKelvinlet::twist(kCentre, Vector3d(0.4, 0.9, -0.2), kEps, material);
    const auto scale = RegularizedKelvinlet::scale(kCentre, 0.8, kEps, material);
    const Field u = [&](const Vector3d& p) { return twist.displacement(p); };
    const Field v = [&](const Vector3d& p) { return scale.displacement(p); };
    for (const Vector3d& X : samplePoints(30, 0.0, 10.0)) {
      const Matrix3d G = gradientFD(u, X, 1e-4 * kEps);
      EXPECT_LT(std::abs(G.trace()), 1e-8 * G.norm());
      EXPECT_LT(std::abs(twist.displacementGradient(X).trace()), 1e-14 * G.norm());
      // The scale field is a dilatation inside the brush (outside it tends to the
      // divergence-free r / |r|^3), so it shows the check can fail
      if ((X - kCentre).norm() < kEps) {
        const Matrix3d H = gradientFD(v, X, 1e-4 * kEps);
        EXPECT_GT(std::abs(H.trace()), 0.1 * H.norm());
      }
    }
  }
}

// (8) The affine load is, by definition, sum_j d/dr_j of the grab field with force F e_j.
TEST(KelvinletTest, AffineIsDerivativeOfGrab) {
  const double tolerance = 1e-7;
  double worst = 0.0;
  for (const KelvinletMaterial& material : materials()) {
    for (const NamedKelvinlet& nk : allKinds(material)) {
      if (nk.name == "grab") continue;
      const Matrix3d& F = nk.load;
      const double h = 1e-4 * kEps;
      for (const Vector3d& X : samplePoints(25, 0.05, 10.0)) {
        Vector3d expected = Vector3d::Zero();
        for (int j = 0; j < 3; ++j) {
          const auto grab = RegularizedKelvinlet::grab(kCentre, F.col(j), kEps, material);
          const Vector3d step = h * Vector3d::Unit(j);
          expected += (grab.displacement(X + step) - grab.displacement(X - step)) / (2.0 * h);
        }
        const double error = (nk.kelvinlet.displacement(X) - expected).norm() / expected.norm();
        worst = std::max(worst, error);
        EXPECT_LT(error, tolerance) << nk.name;
      }
    }
  }
  std::printf("[ measured ] worst relative affine/derivative-of-grab error %.3g (tolerance %.0e)\n",
              worst, tolerance);
}

TEST(KelvinletTest, RejectsInvalidInput) {
  Matrix3d notSymmetric = pinchLoad();
  notSymmetric(0, 1) += 1e-6;
  EXPECT_THROW(RegularizedKelvinlet::pinch(kCentre, notSymmetric, kEps), std::invalid_argument);
  EXPECT_THROW(RegularizedKelvinlet::pinch(kCentre, Matrix3d::Identity(), kEps),
               std::invalid_argument);
  EXPECT_NO_THROW(RegularizedKelvinlet::pinch(kCentre, Matrix3d::Zero(), kEps));
  EXPECT_THROW(RegularizedKelvinlet::grab(kCentre, Vector3d::UnitX(), 0.0), std::invalid_argument);
  EXPECT_THROW(RegularizedKelvinlet::scale(kCentre, 1.0, kEps, {1.0, 0.5}), std::invalid_argument);
  EXPECT_THROW(RegularizedKelvinlet::scale(kCentre, 1.0, kEps, {0.0, 0.3}), std::invalid_argument);
}

}  // namespace
}  // namespace sculpt
