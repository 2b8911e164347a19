// Preconditioned conjugate gradients: the solution of a small SPD system against a direct solve,
// and right-hand sides near the largest doubles (forces of 1e200 N) solved to the same bits as the
// same system scaled by a power of two, and the scaling of a start.

#include "sim/conjugate_gradient.h"

#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <cmath>

namespace sculpt {
namespace {

Eigen::MatrixXd spdMatrix(int n) {
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i < n; ++i) {
    A(i, i) = 4.0 + 0.1 * i;
    if (i + 1 < n) A(i, i + 1) = A(i + 1, i) = -1.0;
  }
  return A;
}

CgResult solve(const Eigen::MatrixXd& A, const Eigen::VectorXd& b, Eigen::VectorXd& x) {
  const LinearOperator op = [&](const Eigen::VectorXd& in, Eigen::VectorXd& out) { out = A * in; };
  const Eigen::VectorXd diagonal = A.diagonal();
  const LinearOperator jacobi = [&](const Eigen::VectorXd& r, Eigen::VectorXd& z) {
    z = r.cwiseQuotient(diagonal);
  };
  return conjugateGradient(op, jacobi, b, x, 1e-12, 200);
}

TEST(ConjugateGradient, MatchesADirectSolve) {
  const Eigen::MatrixXd A = spdMatrix(30);
  Eigen::VectorXd b(30);
  for (int i = 0; i < 30; ++i) b[i] = std::sin(0.7 * i) + 0.2;
  Eigen::VectorXd x;
  ASSERT_TRUE(solve(A, b, x).converged);
  EXPECT_LT((x - A.llt().solve(b)).norm(), 1e-10 * b.norm());
}

TEST(ConjugateGradient, RightHandSidesNearTheLargestDoublesSolveToTheSameBits) {
  const Eigen::MatrixXd A = spdMatrix(30);
  Eigen::VectorXd b(30);
  for (int i = 0; i < 30; ++i) b[i] = std::cos(0.3 * i) - 0.1;
  Eigen::VectorXd x;
  ASSERT_TRUE(solve(A, b, x).converged);
  // |1e200 b|^2 overflows; without the scaling the solve gave up at once with x = 0.
  const double big = std::ldexp(1.0, 665);  // about 1.3e200
  Eigen::VectorXd xBig;
  const CgResult result = solve(A, big * b, xBig);
  EXPECT_TRUE(result.converged);
  ASSERT_TRUE(xBig.allFinite());
  for (int i = 0; i < 30; ++i) EXPECT_EQ(xBig[i], big * x[i]) << i;
}

TEST(ConjugateGradient, AZeroStartAppliesTheOperatorOncePerIteration) {
  // The operator is an element pass in the implicit step: a zero first iterate's residual is b
  // and needs no product; a nonzero one needs exactly one.
  const Eigen::MatrixXd A = spdMatrix(30);
  Eigen::VectorXd b(30);
  for (int i = 0; i < 30; ++i) b[i] = std::sin(1.3 * i) - 0.3;
  int products = 0;
  const LinearOperator op = [&](const Eigen::VectorXd& in, Eigen::VectorXd& out) {
    ++products;
    out = A * in;
  };
  const LinearOperator identity = [](const Eigen::VectorXd& r, Eigen::VectorXd& z) { z = r; };
  Eigen::VectorXd x = Eigen::VectorXd::Zero(30);
  const CgResult zeroStart = conjugateGradient(op, identity, b, x, 1e-10, 200);
  ASSERT_TRUE(zeroStart.converged);
  EXPECT_EQ(products, zeroStart.iterations);
  EXPECT_LT((x - A.llt().solve(b)).norm(), 1e-8 * b.norm());

  products = 0;
  Eigen::VectorXd warm = Eigen::VectorXd::Constant(30, 0.1);
  const CgResult warmStart = conjugateGradient(op, identity, b, warm, 1e-10, 200);
  ASSERT_TRUE(warmStart.converged);
  EXPECT_EQ(products, warmStart.iterations + 1);
  EXPECT_LT((warm - x).norm(), 1e-8 * x.norm());
}

// A start is scaled to the least energy along it: twice the solution becomes the solution (no
// iteration), and minus the solution becomes zero, no worse than starting there.
TEST(ConjugateGradient, AStartIsScaledToTheLeastEnergyAlongIt) {
  const Eigen::MatrixXd A = spdMatrix(30);
  Eigen::VectorXd b(30);
  for (int i = 0; i < 30; ++i) b[i] = std::cos(0.3 * i) - 0.1;
  const Eigen::VectorXd solution = A.llt().solve(b);
  Eigen::VectorXd twice = 2.0 * solution;
  const CgResult fromTwice = solve(A, b, twice);
  EXPECT_TRUE(fromTwice.converged);
  EXPECT_EQ(fromTwice.iterations, 0);
  EXPECT_LT((twice - solution).norm(), 1e-12 * solution.norm());
  Eigen::VectorXd zero, away = -solution;
  const CgResult fromZero = solve(A, b, zero), fromAway = solve(A, b, away);
  EXPECT_TRUE(fromAway.converged);
  EXPECT_EQ(fromAway.iterations, fromZero.iterations);
  EXPECT_LT((away - solution).norm(), 1e-10 * solution.norm());
}

}  // namespace
}  // namespace sculpt
