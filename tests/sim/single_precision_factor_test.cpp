// The preconditioner's single-precision solve against a double-precision factorisation of the
// same matrix, and its fall-back to double precision where single precision's range ends.

#include <gtest/gtest.h>

#include <Eigen/SparseCholesky>
#include <cmath>
#include <cstdio>
#include <vector>

#include "sim/sparse_cholesky.h"
#include "support/grid_laplacian.h"
#include "support/random_vector.h"

namespace sculpt {
namespace {

// |z - S^-1 r| / |S^-1 r| for the supernodal solve z, against a double-precision factor.
double relativeDifference(const Eigen::SparseMatrix<double>& S) {
  const Eigen::VectorXd r = test::randomVector(S.rows(), 7);
  SparseCholesky supernodal(SparseCholesky::Method::Supernodal);
  EXPECT_TRUE(supernodal.factor(S));
  Eigen::VectorXd z;
  supernodal.solve(r, z);
  const Eigen::SimplicialLLT<Eigen::SparseMatrix<double>> exact(S);
  const Eigen::VectorXd reference = exact.solve(r);
  return (z - reference).norm() / reference.norm();
}

TEST(SinglePrecisionFactor, SolvesToSinglePrecisionOfTheDoubleFactor) {
  // 2,744 rows, condition number about 240: the error stays near float's epsilon times it.
  const double difference = relativeDifference(test::gridLaplacian(14, 0.05));
  std::printf("[ measured ] single-precision solve: relative difference %.2e\n", difference);
  EXPECT_LT(difference, 1e-5);
  EXPECT_GT(difference, 1e-9);  // the single-precision solve ran, not the double one
}

TEST(SinglePrecisionFactor, SolvesManyRightHandSidesAtOnceToSinglePrecision) {
  // Columns a thousand times apart share one scaling; each keeps single precision's accuracy.
  const Eigen::SparseMatrix<double> S = test::gridLaplacian(14, 0.05);
  Eigen::MatrixXd R(S.rows(), 4);
  for (Eigen::Index j = 0; j < R.cols(); ++j)
    R.col(j) = test::randomVector(S.rows(), unsigned(11 + j)) * std::pow(1e3, double(j) - 1);
  SparseCholesky supernodal(SparseCholesky::Method::Supernodal);
  ASSERT_TRUE(supernodal.factor(S));
  Eigen::MatrixXd Z;
  supernodal.solve(R, Z);
  ASSERT_EQ(Z.rows(), S.rows());
  ASSERT_EQ(Z.cols(), R.cols());
  const Eigen::SimplicialLLT<Eigen::SparseMatrix<double>> exact(S);
  for (Eigen::Index j = 0; j < R.cols(); ++j) {
    const Eigen::VectorXd reference = exact.solve(Eigen::VectorXd(R.col(j)));
    const double difference = (Z.col(j) - reference).norm() / reference.norm();
    std::printf("[ measured ] column %ld: relative difference %.2e\n", long(j), difference);
    EXPECT_LT(difference, 1e-5);
    EXPECT_GT(difference, 1e-9);  // solved in single precision
  }
}

TEST(SinglePrecisionFactor, KeepsItsAccuracyForMatricesOfAnyScale) {
  // Entries of 1e50 (S^-1 r ~ 1e-50 lies below single precision's range), of 1e80 (L ~ 1e40
  // above it) and of 1e-80: L and r are scaled by powers of two into range and back.
  for (const double scale : {1e50, 1e80, 1e-80}) {
    SCOPED_TRACE(scale);
    const double difference = relativeDifference(test::gridLaplacian(14, 0.05) * scale);
    std::printf("[ measured ] matrix scaled by %.0e: relative difference %.2e\n", scale,
                difference);
    EXPECT_LT(difference, 1e-5);
  }
}

TEST(SinglePrecisionFactor, FallsBackToDoublePrecisionBeyondSinglePrecisionsRange) {
  // Two decoupled grids, one 1e80 times the other: no single scaling holds both halves of
  // the solution in single precision, so the double-precision solve answers, to its rounding.
  const Eigen::SparseMatrix<double> small = test::gridLaplacian(8, 0.05) * 1e-40;
  const Eigen::SparseMatrix<double> large = test::gridLaplacian(8, 0.05) * 1e40;
  std::vector<Eigen::Triplet<double>> entries;
  for (const auto* block : {&small, &large})
    for (int c = 0; c < block->outerSize(); ++c)
      for (Eigen::SparseMatrix<double>::InnerIterator it(*block, c); it; ++it) {
        const int offset = block == &small ? 0 : int(small.rows());
        entries.emplace_back(int(it.row()) + offset, int(it.col()) + offset, it.value());
      }
  Eigen::SparseMatrix<double> S(2 * small.rows(), 2 * small.rows());
  S.setFromTriplets(entries.begin(), entries.end());
  const double difference = relativeDifference(S);
  std::printf("[ measured ] scales 1e-40 and 1e40 together: relative difference %.2e\n",
              difference);
  EXPECT_LT(difference, 1e-12);
}

}  // namespace
}  // namespace sculpt
