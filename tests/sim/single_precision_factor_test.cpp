// The preconditioner's single-precision solve against a double-precision factorisation of the
// same matrix, and its fall-back to double precision where single precision's range ends.

#include <gtest/gtest.h>

#include <Eigen/SparseCholesky>
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
