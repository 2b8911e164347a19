// With the element rotations frozen the co-rotated energy is quadratic in the node positions:
// finite differences of energy() must match addGradient(), finite differences of addGradient()
// must match addHessianProduct(), the Hessian must be symmetric, positive semidefinite and have
// the rigid modes in its null space. Checked on a level-2 model of the mixed mesh, which has
// all three element types, at a randomly perturbed and rotated configuration.

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>
#include <optional>
#include <random>
#include <string>

#include "fem/elastic_kernel.h"
#include "fem/fem_model.h"
#include "support/fem_builders.h"
#include "support/mixed_mesh_kernel.h"
#include "support/mesh_builders.h"

namespace sculpt {
namespace {

using namespace sculpt::test;

class GradientConsistency : public MixedMeshKernelTest {
 protected:
  void SetUp() override {
    MixedMeshKernelTest::SetUp();
    if (HasFatalFailure()) return;
    // x0: rest nodes, randomly perturbed (about 5% strain), then rotated and translated, so
    // the frozen rotations are far from the identity and differ between elements.
    std::mt19937_64 rng(2024);
    const Eigen::Matrix3d Q = randomRotation(rng);
    const Points& X = model_->mesh().restNodes;
    const Points noisy = X + randomPoints(X.rows(), 0.05 * L_, rng);
    x0_.resize(X.rows(), 3);
    for (Eigen::Index i = 0; i < X.rows(); ++i)
      x0_.row(i) = (Q * noisy.row(i).transpose()).transpose() + Eigen::RowVector3d(1, 2, 3);
    model_->elastic().updateRotations(x0_);
  }
};

TEST_F(GradientConsistency, EnergyDifferencesMatchGradient) {
  const ElasticKernel& kernel = model_->elastic();
  std::mt19937_64 rng(1);
  const Points g = gradient(x0_);
  double worst = 0;
  for (int trial = 0; trial < 10; ++trial) {
    const Points v = randomPoints(x0_.rows(), L_, rng);
    const double h = 1e-4;
    const double fd = (kernel.energy(x0_ + h * v) - kernel.energy(x0_ - h * v)) / (2 * h);
    const double analytic = dot(g, v);
    worst = std::max(worst, std::abs(fd - analytic) / (g.norm() * v.norm()));
  }
  EXPECT_LT(worst, 1e-6);
  std::printf("central difference of energy vs gradient . v: worst |fd - g.v|/(|g||v|) = %.3g\n",
              worst);
}

TEST_F(GradientConsistency, GradientDifferencesMatchHessianProduct) {
  std::mt19937_64 rng(2);
  double worst = 0;
  for (int trial = 0; trial < 5; ++trial) {
    const Points v = randomPoints(x0_.rows(), L_, rng);
    const double h = 1e-4;
    const Points fd = (gradient(x0_ + h * v) - gradient(x0_ - h * v)) / (2 * h);
    const Points Hv = hessianProduct(v);
    worst = std::max(worst, (fd - Hv).cwiseAbs().maxCoeff() / Hv.cwiseAbs().maxCoeff());
  }
  EXPECT_LT(worst, 1e-6);
  std::printf("central difference of gradient vs H v: worst max|fd - Hv|/max|Hv| = %.3g\n", worst);
}

TEST_F(GradientConsistency, EnergyIsExactlyQuadraticWithFrozenRotations) {
  // E(x0 + v) = E(x0) + g.v + v.Hv / 2 for any v (no step-size error at all).
  const ElasticKernel& kernel = model_->elastic();
  std::mt19937_64 rng(3);
  const double e0 = kernel.energy(x0_);
  const Points g = gradient(x0_);
  double worst = 0;
  for (double size : {0.01, 0.3, 2.0}) {
    const Points v = randomPoints(x0_.rows(), size * L_, rng);
    const double predicted = e0 + dot(g, v) + 0.5 * dot(v, hessianProduct(v));
    const double actual = kernel.energy(x0_ + v);
    worst = std::max(worst, std::abs(actual - predicted) / std::max(actual, e0));
  }
  EXPECT_LT(worst, 1e-10);
  // The gradient is affine: g(x0 + v) = g(x0) + H v.
  const Points v = randomPoints(x0_.rows(), L_, rng);
  const Points lhs = gradient(x0_ + v);
  const Points rhs = g + hessianProduct(v);
  const double affineError = (lhs - rhs).cwiseAbs().maxCoeff() / lhs.cwiseAbs().maxCoeff();
  EXPECT_LT(affineError, 1e-10);
  std::printf("quadratic model: worst rel. error %.3g; g(x0+v) - g(x0) - Hv: %.3g\n", worst,
              affineError);
}

TEST_F(GradientConsistency, HessianIsSymmetricAndPositiveSemidefinite) {
  std::mt19937_64 rng(4);
  double worstSym = 0, minRayleigh = 1e300, maxRayleigh = 0;
  for (bool atRest : {true, false}) {
    if (atRest) model_->elastic().resetRotations();
    for (int trial = 0; trial < 10; ++trial) {
      const Points v = randomPoints(x0_.rows(), 1.0, rng);
      const Points w = randomPoints(x0_.rows(), 1.0, rng);
      const Points Hv = hessianProduct(v), Hw = hessianProduct(w);
      const double a = dot(v, Hw), b = dot(w, Hv);
      worstSym = std::max(worstSym, std::abs(a - b) / (Hv.norm() * w.norm()));
      const double rv = dot(v, Hv) / dot(v, v);
      minRayleigh = std::min(minRayleigh, rv);
      maxRayleigh = std::max(maxRayleigh, rv);
      EXPECT_GE(dot(v, Hv), 0.0);
    }
    if (atRest) model_->elastic().updateRotations(x0_);
  }
  EXPECT_LT(worstSym, 1e-10);
  EXPECT_GT(minRayleigh, 0.0);
  std::printf("Hessian: worst |v.Hw - w.Hv|/(|Hv||w|) = %.3g, Rayleigh quotients in [%.4g, %.4g]\n",
              worstSym, minRayleigh, maxRayleigh);
}

TEST_F(GradientConsistency, RigidModesAreInTheNullSpace) {
  // Translations with any rotations; infinitesimal rotations about the frame of each element
  // only when all R_e are equal, so test them at rest (R_e = I): H (omega x X) = 0.
  ElasticKernel& kernel = model_->elastic();
  kernel.resetRotations();
  const Points& X = model_->mesh().restNodes;
  std::mt19937_64 rng(5);
  const double scale = hessianProduct(randomPoints(X.rows(), 1.0, rng)).cwiseAbs().maxCoeff();
  double worst = 0;
  for (int axis = 0; axis < 3; ++axis) {
    Points translation = Points::Zero(X.rows(), 3);
    translation.col(axis).setOnes();
    worst = std::max(worst, hessianProduct(translation).cwiseAbs().maxCoeff() / scale);
    Points rotation(X.rows(), 3);
    for (Eigen::Index i = 0; i < X.rows(); ++i)
      rotation.row(i) = Eigen::Vector3d::Unit(axis).cross(X.row(i).transpose()).transpose();
    worst = std::max(worst, hessianProduct(rotation).cwiseAbs().maxCoeff() / (scale * 3.0));
  }
  EXPECT_LT(worst, 1e-12);
  std::printf("rigid modes: worst max|H r| relative to a random product = %.3g\n", worst);
}

TEST_F(GradientConsistency, ControlPointGradientIsATransposeOfNodeGradient) {
  // E(p) = E(A p): d/dp E = A^T g, checked by central differences on the control points.
  const ElasticKernel& kernel = model_->elastic();
  std::mt19937_64 rng(6);
  const Eigen::Index n = model_->numControlPoints();
  Points p = model_->restControl() + randomPoints(n, 0.05 * L_, rng);
  Points nodes;
  model_->nodesFromControl(p, nodes);
  Points reduced = Points::Zero(n, 3);
  model_->addToControl(gradient(nodes), reduced);
  auto energyAt = [&](const Points& control) {
    Points x;
    model_->nodesFromControl(control, x);
    return kernel.energy(x);
  };
  double worst = 0;
  for (int trial = 0; trial < 5; ++trial) {
    const Points v = randomPoints(n, L_, rng);
    const double h = 1e-4;
    const double fd = (energyAt(p + h * v) - energyAt(p - h * v)) / (2 * h);
    worst = std::max(worst, std::abs(fd - dot(reduced, v)) / (reduced.norm() * v.norm()));
  }
  EXPECT_LT(worst, 1e-6);
  std::printf("control points: worst |fd - (A^T g).v|/(|A^T g||v|) = %.3g\n", worst);
}

}  // namespace
}  // namespace sculpt
