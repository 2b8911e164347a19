// The inversion barrier (fem/elastic_model.h) on a level-2 model of the mixed mesh (all three
// element types) squeezed to 0.7 of its size in every direction (det F about 0.34, below the
// threshold 0.5 at every Gauss point), perturbed, rotated and with one corner region turned
// inside out: finite differences of the energy match the gradient, finite differences of the
// gradient match the exact Hessian, the solvers' Hessian is symmetric and positive
// semi-definite and agrees with the exact one where the term it drops vanishes, and states that
// keep half their volume are those of the co-rotated model, bit for bit.

#include <gtest/gtest.h>

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

class InversionBarrierTest : public MixedMeshKernelTest {
 protected:
  void SetUp() override {
    MixedMeshKernelTest::SetUp();
    if (HasFatalFailure()) return;
    std::mt19937_64 rng(2026);
    const Eigen::Matrix3d Q = randomRotation(rng);
    const Points& X = model_->mesh().restNodes;
    const Eigen::RowVector3d centre = X.colwise().mean();
    const Points noisy = X + randomPoints(X.rows(), 0.02 * L_, rng);
    x0_.resize(X.rows(), 3);
    const double low = X.col(2).minCoeff(), height = X.col(2).maxCoeff() - low;
    for (Eigen::Index i = 0; i < X.rows(); ++i) {
      Eigen::RowVector3d p = 0.7 * (noisy.row(i) - centre);
      // The bottom fifth folded up through itself: inverted Gauss points there.
      const double below = low + 0.2 * height - X(i, 2);
      if (below > 0) p.z() += 2.5 * 0.7 * below;
      x0_.row(i) = (Q * p.transpose()).transpose() + Eigen::RowVector3d(1, 2, 3);
    }
    setBarrier(true);
  }
  void setBarrier(bool exactHessian) {
    InversionBarrier barrier;
    barrier.exactHessian = exactHessian;
    model_->elastic().setModel(ElasticModel::Barrier, barrier);
    model_->elastic().updateRotations(x0_);
  }
};

TEST_F(InversionBarrierTest, TheStateIsCompressedBelowTheThresholdAndPartlyInverted) {
  const ElasticKernel::Jacobians J = model_->elastic().jacobians(x0_);
  std::printf("min det F %.3f, %u inverted Gauss points in %u of %u elements; %u elements in the "
              "barrier\n",
              J.min, J.invertedPoints, J.invertedElements, model_->mesh().numElements(),
              model_->elastic().barrierElements());
  EXPECT_LT(J.min, 0.0);
  EXPECT_GT(J.invertedElements, 0u);
  EXPECT_EQ(model_->elastic().barrierElements(), model_->mesh().numElements());
}

TEST_F(InversionBarrierTest, EnergyDifferencesMatchGradient) {
  const ElasticKernel& kernel = model_->elastic();
  std::mt19937_64 rng(1);
  const Points g = gradient(x0_);
  double worst = 0;
  for (int trial = 0; trial < 10; ++trial) {
    const Points v = randomPoints(x0_.rows(), L_, rng);
    const double h = 1e-5;
    const double fd = (kernel.energy(x0_ + h * v) - kernel.energy(x0_ - h * v)) / (2 * h);
    worst = std::max(worst, std::abs(fd - dot(g, v)) / (g.norm() * v.norm()));
  }
  std::printf("energy vs gradient: worst |fd - g.v|/(|g||v|) = %.3g\n", worst);
  EXPECT_LT(worst, 1e-7);
  // The barrier is a large part of it: without it the gradient is another one.
  model_->elastic().setModel(ElasticModel::Corotated);
  model_->elastic().updateRotations(x0_);
  EXPECT_GT((gradient(x0_) - g).norm(), 0.5 * g.norm());
}

TEST_F(InversionBarrierTest, GradientDifferencesMatchTheExactHessian) {
  std::mt19937_64 rng(2);
  double worst = 0;
  for (int trial = 0; trial < 5; ++trial) {
    const Points v = randomPoints(x0_.rows(), L_, rng);
    const double h = 1e-5;
    const Points fd = (gradient(x0_ + h * v) - gradient(x0_ - h * v)) / (2 * h);
    const Points Hv = hessianProduct(v);
    worst = std::max(worst, (fd - Hv).cwiseAbs().maxCoeff() / Hv.cwiseAbs().maxCoeff());
  }
  std::printf("gradient vs exact H v: worst max|fd - Hv|/max|Hv| = %.3g\n", worst);
  EXPECT_LT(worst, 1e-6);
}

TEST_F(InversionBarrierTest, TheSolversHessianIsSymmetricAndPositiveSemidefinite) {
  setBarrier(false);
  std::mt19937_64 rng(4);
  double worstSym = 0, minRayleigh = 1e300;
  for (int trial = 0; trial < 10; ++trial) {
    const Points v = randomPoints(x0_.rows(), 1.0, rng);
    const Points w = randomPoints(x0_.rows(), 1.0, rng);
    const Points Hv = hessianProduct(v), Hw = hessianProduct(w);
    worstSym = std::max(worstSym, std::abs(dot(v, Hw) - dot(w, Hv)) / (Hv.norm() * w.norm()));
    minRayleigh = std::min(minRayleigh, dot(v, Hv) / dot(v, v));
  }
  std::printf("solver Hessian: worst asymmetry %.3g, smallest Rayleigh quotient %.4g\n", worstSym,
              minRayleigh);
  EXPECT_LT(worstSym, 1e-10);
  EXPECT_GT(minRayleigh, 0.0);
  // And it is not the exact one: the dropped term psi' d cof(F) is there at this state.
  const Points v = randomPoints(x0_.rows(), 1.0, rng);
  const Points gaussNewton = hessianProduct(v);
  setBarrier(true);
  EXPECT_GT((hessianProduct(v) - gaussNewton).norm(), 1e-3 * gaussNewton.norm());
}

// Along a displacement in one direction, v = a phi(X), every Gauss point's dA = R^T a grad(phi)^T
// has rank one, so J is linear along it (det(A + s u w^T) = det(A) (1 + s w^T A^-1 u)) and the
// term the solvers drop, psi' d^2J, is zero: their Hessian's quadratic form is the exact one's.
TEST_F(InversionBarrierTest, TheSolversHessianIsTheExactOneAlongADisplacementInOneDirection) {
  std::mt19937_64 rng(6);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  double worstOneDirection = 0, leastGeneral = 1e300;
  for (int trial = 0; trial < 5; ++trial) {
    const Eigen::RowVector3d a(uniform(rng), uniform(rng), uniform(rng));
    Points v(x0_.rows(), 3);
    for (Eigen::Index i = 0; i < v.rows(); ++i) v.row(i) = uniform(rng) * L_ * a;
    const Points general = randomPoints(x0_.rows(), L_, rng);
    setBarrier(false);
    const double solver = dot(v, hessianProduct(v));
    const double solverGeneral = dot(general, hessianProduct(general));
    setBarrier(true);
    const double exact = dot(v, hessianProduct(v));
    const double exactGeneral = dot(general, hessianProduct(general));
    worstOneDirection = std::max(worstOneDirection, std::abs(solver - exact) / std::abs(exact));
    leastGeneral = std::min(leastGeneral,
                            std::abs(solverGeneral - exactGeneral) / std::abs(exactGeneral));
  }
  std::printf("v^T H v, solvers' against exact: one direction %.3g, general %.3g\n",
              worstOneDirection, leastGeneral);
  EXPECT_LT(worstOneDirection, 1e-12);
  EXPECT_GT(leastGeneral, 1e-4);  // elsewhere the dropped term is there
}

TEST_F(InversionBarrierTest, StatesKeepingHalfTheirVolumeAreThoseOfTheCorotatedModel) {
  // 5% strain: det F near 1 everywhere, so the barrier adds exactly nothing.
  std::mt19937_64 rng(5);
  const Points& X = model_->mesh().restNodes;
  const Points x = X + randomPoints(X.rows(), 0.05 * L_, rng);
  const Points v = randomPoints(X.rows(), L_, rng);
  ElasticKernel& kernel = model_->elastic();
  // Both from the same warm start, so that the rotations agree to the bit.
  kernel.setModel(ElasticModel::Barrier);
  kernel.resetRotations();
  kernel.updateRotations(x);
  EXPECT_EQ(kernel.barrierElements(), 0u);
  const double barrierEnergy = kernel.energy(x);
  const Points barrierGradient = gradient(x), barrierHv = hessianProduct(v);
  kernel.setModel(ElasticModel::Corotated);
  kernel.resetRotations();
  kernel.updateRotations(x);
  EXPECT_EQ(kernel.energy(x), barrierEnergy);
  EXPECT_TRUE((gradient(x).array() == barrierGradient.array()).all());
  EXPECT_TRUE((hessianProduct(v).array() == barrierHv.array()).all());
}

}  // namespace
}  // namespace sculpt
