// A factor of part of a system, extended to more of its coordinates through the Schur
// complement (or beside it, uncoupled), against dense Cholesky solves; and the preconditioner
// serving points released from a pin with it.

#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <cstdio>
#include <random>
#include <vector>

#include "sim/factor_extension.h"
#include "sim/simulator.h"
#include "sim/standard_forms.h"
#include "sim/system_preconditioner.h"
#include "support/fem_builders.h"
#include "support/grid_laplacian.h"

namespace sculpt {
namespace {

using SparseMatrix = Eigen::SparseMatrix<double>;

Eigen::VectorXd randomVector(Eigen::Index n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  Eigen::VectorXd v(n);
  for (Eigen::Index i = 0; i < n; ++i) v[i] = u(rng);
  return v;
}

SparseMatrix restricted(const SparseMatrix& S, const std::vector<int>& keep) {
  Eigen::MatrixXd dense = Eigen::MatrixXd(S)(keep, keep);
  return dense.sparseView();
}

// S's solve on `factored` followed by `added`, through the extension, against a dense Cholesky
// solve of S on the same coordinates; returns the relative difference.
double extendedAgainstDense(const SparseMatrix& S, const std::vector<int>& factored,
                            const std::vector<int>& added, SparseCholesky::Method method) {
  SparseCholesky factor(method);
  if (!factored.empty()) {
    EXPECT_TRUE(factor.factor(restricted(S, factored)));
  }
  FactorExtension extension;
  EXPECT_TRUE(extension.build(factor, S, factored, added));
  EXPECT_FALSE(extension.empty());

  std::vector<int> all = factored;
  all.insert(all.end(), added.begin(), added.end());
  const Eigen::VectorXd r = randomVector(Eigen::Index(all.size()), 3);
  const Eigen::VectorXd truth = Eigen::MatrixXd(S)(all, all).llt().solve(r);

  const Eigen::Index n = Eigen::Index(factored.size());
  Eigen::MatrixXd w = Eigen::MatrixXd::Zero(n, 1);
  if (n > 0) factor.solve(Eigen::MatrixXd(r.head(n)), w);  // in double precision
  Eigen::VectorXd wF = w.col(0), xU;
  extension.finish(wF, r.tail(Eigen::Index(added.size())), xU);
  Eigen::VectorXd x(r.size());
  x << wF, xU;
  return (x - truth).norm() / truth.norm();
}

TEST(FactorExtension, SolvesTheWholeSystemAsADenseCholeskyDoes) {
  const SparseMatrix S = test::gridLaplacian(6, 0.05);  // 216 coordinates
  // Every fifth coordinate, and a block of neighbours, left out of the factor.
  std::vector<int> factored, added;
  for (int i = 0; i < int(S.rows()); ++i) {
    if (i % 5 == 0 || (i >= 100 && i < 120)) added.push_back(i);
    else factored.push_back(i);
  }
  for (SparseCholesky::Method method :
       {SparseCholesky::Method::Supernodal, SparseCholesky::Method::Simplicial}) {
    const double difference = extendedAgainstDense(S, factored, added, method);
    std::printf("[ measured ] %zu coordinates added to a factor of %zu: %.2e from the dense "
                "solve\n", added.size(), factored.size(), difference);
    EXPECT_LT(difference, 1e-12);
  }
}

TEST(FactorExtension, FromNoFactoredCoordinatesItIsTheWholeSolve) {
  const SparseMatrix S = test::gridLaplacian(3, 0.5);
  std::vector<int> added(size_t(S.rows()));
  for (size_t i = 0; i < added.size(); ++i) added[i] = int(i);
  EXPECT_LT(extendedAgainstDense(S, {}, added, SparseCholesky::Method::Supernodal), 1e-13);
}

TEST(FactorExtension, TheUncoupledFormSolvesTheAddedBlockAlone) {
  const SparseMatrix S = test::gridLaplacian(5, 0.05);
  std::vector<int> added;
  for (int i = 40; i < 90; i += 2) added.push_back(i);
  FactorExtension extension;
  ASSERT_TRUE(extension.buildUncoupled(S, added));
  EXPECT_FALSE(extension.coupled());
  const Eigen::VectorXd rU = randomVector(Eigen::Index(added.size()), 5);
  const Eigen::VectorXd truth = Eigen::MatrixXd(S)(added, added).llt().solve(rU);
  Eigen::VectorXd w = randomVector(10, 6), xU;
  const Eigen::VectorXd before = w;
  extension.finish(w, rU, xU);
  // The sparse factor solves in single precision.
  EXPECT_LT((xU - truth).norm(), 1e-6 * truth.norm());
  EXPECT_EQ(w, before);  // the factored part is left as it was
}

TEST(FactorExtension, RefusesAnIndefiniteSystem) {
  SparseMatrix S = test::gridLaplacian(4, 0.05);
  std::vector<int> factored, added;
  for (int i = 0; i < int(S.rows()); ++i) (i < 60 ? factored : added).push_back(i);
  S.coeffRef(62, 62) = -1.0;  // a negative pivot among the added coordinates
  SparseCholesky factor(SparseCholesky::Method::Supernodal);
  ASSERT_TRUE(factor.factor(restricted(S, factored)));
  FactorExtension extension;
  EXPECT_FALSE(extension.build(factor, S, factored, added));
  EXPECT_TRUE(extension.empty());
  EXPECT_FALSE(extension.buildUncoupled(S, added));
  EXPECT_TRUE(extension.empty());
}

std::vector<int> dofsFrom(const FemModel& model, int firstPoint) {
  std::vector<int> dofs;
  for (int i = 3 * firstPoint; i < 3 * int(model.numControlPoints()); ++i) dofs.push_back(i);
  return dofs;
}

TEST(FactorExtension, PointsReleasedFromAPinAreSolvedAsAFreshFactorSolvesThem) {
  auto model = test::buildModel(test::block3(), 1, false);
  ASSERT_TRUE(model);
  // Double-precision solves, so that "the same" means to rounding.
  SystemPreconditioner old(SparseCholesky::Method::Simplicial);
  ASSERT_TRUE(old.update(*model, 3600, 60, 1, dofsFrom(*model, 16)));
  const std::vector<int> released = dofsFrom(*model, 10);  // six points released
  ASSERT_TRUE(old.update(*model, 3600, 60, 1, released));
  EXPECT_EQ(old.stats().extensions, 1);
  EXPECT_EQ(old.stats().factorizations, 1);

  SystemPreconditioner fresh(SparseCholesky::Method::Simplicial);
  ASSERT_TRUE(fresh.update(*model, 3600, 60, 1, released));
  const Eigen::VectorXd r = randomVector(Eigen::Index(released.size()), 4);
  Eigen::VectorXd a, b;
  old.apply(r, a);
  fresh.apply(r, b);
  const double difference = (a - b).norm() / b.norm();
  std::printf("[ measured ] extended against fresh factor: %.2e\n", difference);
  EXPECT_LT(difference, 1e-10);
}

TEST(FactorExtension, ReleasingAPinCostsTheStepsNoMoreIterationsThanAFreshFactor) {
  // Two block3 solids sagging with their bottom and top layers pinned; the top is released,
  // and one of them refactors at once: the other's steps, served by the extended factor until
  // its new factor is adopted, take as many CG iterations.
  const Eigen::AlignedBox3d bottom(Eigen::Vector3d(-1, -1, -1), Eigen::Vector3d(4, 0.01, 4));
  const Eigen::AlignedBox3d top(Eigen::Vector3d(-1, 2.99, -1), Eigen::Vector3d(4, 4, 4));
  std::vector<int> iterations[2];
  for (int refactored = 0; refactored < 2; ++refactored) {
    auto model = test::buildModel(test::block3(), 1, false);
    ASSERT_TRUE(model);
    Simulator simulator(*model);
    simulator.fixInBox(bottom);
    const uint32_t topPoints = simulator.fixInBox(top);
    ASSERT_GT(topPoints, 0u);
    simulator.addLoad(std::make_unique<GravityForm>(*model, Eigen::Vector3d(0, -9.81, 0)));
    for (int i = 0; i < 5; ++i) ASSERT_TRUE(simulator.step().ok);
    const Points& rest = model->restControl();
    for (Eigen::Index p = 0; p < rest.rows(); ++p)
      if (top.contains(rest.row(p).transpose())) simulator.setFixed(uint32_t(p), false);
    if (refactored) {
      ASSERT_TRUE(simulator.step().ok);  // the new pins reach the preconditioner here
      simulator.refactorPreconditioner();
    } else {
      iterations[0].push_back(simulator.step().iterations);
    }
    for (int i = 0; i < 6; ++i) {
      const StepReport report = simulator.step();
      ASSERT_TRUE(report.ok) << report.message;
      EXPECT_LE(report.residual, simulator.settings().implicitTolerance);
      iterations[refactored].push_back(report.iterations);
    }
    if (!refactored) {
      EXPECT_EQ(simulator.preconditionerStats().extensions, 1);
      EXPECT_EQ(simulator.preconditionerStats().factorizations, 1);  // the new one not yet
    }
  }
  for (size_t i = 0; i < 6; ++i) {
    std::printf("[ measured ] step %zu after the release: %d iterations (extended), %d (fresh)\n",
                i + 1, iterations[0][i + 1], iterations[1][i]);
    EXPECT_LE(iterations[0][i + 1], iterations[1][i] + 1);
  }
}

}  // namespace
}  // namespace sculpt
