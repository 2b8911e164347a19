// Moving a SparseMatrix takes its arrays (core/util/eigen_sparse_move.h): Eigen 3.4.0 alone copied
// them, and the preconditioner passes its matrices on by moves.
#include <gtest/gtest.h>

#include <future>
#include <utility>

#include "fem/mass_matrix.h"

namespace sculpt {
namespace {

SparseMatrix tridiagonal(int n) {
  SparseMatrix A(n, n);
  for (int i = 0; i < n; ++i) {
    A.insert(i, i) = 2.0;
    if (i > 0) A.insert(i - 1, i) = -1.0;
    if (i + 1 < n) A.insert(i + 1, i) = -1.0;
  }
  A.makeCompressed();
  return A;
}

TEST(SparseMatrixMove, AMoveTakesTheArraysAndLeavesTheSourceEmpty) {
  SparseMatrix source = tridiagonal(100);
  const double* values = source.valuePtr();
  const SparseMatrix copy = source;
  SparseMatrix moved = std::move(source);
  EXPECT_EQ(moved.valuePtr(), values);  // the same array, not a copy of it
  EXPECT_EQ(source.rows(), 0);          // NOLINT(bugprone-use-after-move): checked on purpose
  EXPECT_EQ(source.nonZeros(), 0);
  EXPECT_EQ((Eigen::MatrixXd(moved) - Eigen::MatrixXd(copy)).norm(), 0.0);
}

TEST(SparseMatrixMove, AMoveAssignmentTakesTheArrays) {
  SparseMatrix source = tridiagonal(50);
  const double* values = source.valuePtr();
  SparseMatrix target = tridiagonal(7);
  target = std::move(source);
  EXPECT_EQ(target.valuePtr(), values);
  EXPECT_EQ(target.rows(), 50);
  EXPECT_EQ(target.nonZeros(), 148);
}

TEST(SparseMatrixMove, AFuturesResultIsMovedOut) {
  const double* made = nullptr;
  std::future<SparseMatrix> future = std::async(std::launch::async, [&made] {
    SparseMatrix A = tridiagonal(1000);
    made = A.valuePtr();
    return A;
  });
  const SparseMatrix A = future.get();
  EXPECT_EQ(A.valuePtr(), made);
  EXPECT_EQ(A.nonZeros(), 2998);
}

}  // namespace
}  // namespace sculpt
