// A factor of part of a system, extended to more of its coordinates through the Schur
// complement (or beside it, uncoupled), against dense Cholesky solves. The preconditioner's use
// of it for points released from a pin: system_preconditioner_test.cpp.

#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <cstdio>
#include <vector>

#include "sim/factor_extension.h"
#include "support/grid_laplacian.h"
#include "support/random_vector.h"

namespace sculpt {
namespace {

using SparseMatrix = Eigen::SparseMatrix<double>;

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
  const Eigen::VectorXd r = test::randomVector(Eigen::Index(all.size()), 3);
  const Eigen::VectorXd truth = Eigen::MatrixXd(S)(all, all).llt().solve(r);

  const Eigen::Index n = Eigen::Index(factored.size());
  Eigen::MatrixXd w = Eigen::MatrixXd::Zero(n, 1);
  if (n > 0) factor.solve(Eigen::MatrixXd(r.head(n)), w);
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
    // The supernodal factor solves in single precision (Z included), the simplicial in double.
    EXPECT_LT(difference, method == SparseCholesky::Method::Supernodal ? 1e-6 : 1e-12);
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
  const Eigen::VectorXd rU = test::randomVector(Eigen::Index(added.size()), 5);
  const Eigen::VectorXd truth = Eigen::MatrixXd(S)(added, added).llt().solve(rU);
  Eigen::VectorXd w = test::randomVector(10, 6), xU;
  const Eigen::VectorXd before = w;
  extension.finish(w, rU, xU);
  // The sparse factor solves in single precision.
  EXPECT_LT((xU - truth).norm(), 1e-6 * truth.norm());
  EXPECT_EQ(w, before);  // the factored part is left as it was
}

TEST(FactorExtension, SolvesInDoublePrecisionWhereTheComplementIsNearlySingular) {
  // A grid Laplacian with free (Neumann) boundaries, plus 1e-9 times the identity: the
  // constant vector's eigenvalue is 1e-9 of the others, and the factored coordinates pass it to
  // the added ones' complement, below the rounding of a single-precision Z.
  SparseMatrix S = test::gridLaplacian(6, 0.0);
  for (int c = 0; c < int(S.cols()); ++c) S.coeffRef(c, c) = 1e-9 + double(S.col(c).nonZeros() - 1);
  std::vector<int> factored, added;
  for (int i = 0; i < int(S.rows()); ++i) (i % 7 == 3 ? added : factored).push_back(i);
  SparseCholesky factor(SparseCholesky::Method::Supernodal);
  ASSERT_TRUE(factor.factor(restricted(S, factored)));
  // The premise: with Z in single precision the complement's last pivot is its rounding
  // (measured: 0.81 from the dense solve when it was used).
  const Eigen::MatrixXd B = Eigen::MatrixXd(S)(factored, added);
  Eigen::MatrixXd Z;
  factor.solve(B, Z, SparseCholesky::Precision::Single);
  const Eigen::MatrixXd S_UU = Eigen::MatrixXd(S)(added, added);
  const Eigen::LLT<Eigen::MatrixXd> C(S_UU - B.transpose() * Z);
  if (C.info() == Eigen::Success) {
    const double ratio =
        (C.matrixLLT().diagonal().array().square() / S_UU.diagonal().array()).minCoeff();
    std::printf("[ measured ] least pivot from a single-precision Z: %.2e of S_UU's\n", ratio);
    EXPECT_LT(ratio, 1e-3);
  }
  const double difference = extendedAgainstDense(S, factored, added,
                                                 SparseCholesky::Method::Supernodal);
  std::printf("[ measured ] nearly singular complement: %.2e from the dense solve\n", difference);
  EXPECT_LT(difference, 1e-6);
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

}  // namespace
}  // namespace sculpt
