#pragma once
// A sparse Cholesky factor L L^T = S of a symmetric positive definite matrix, refactored without
// repeating the ordering and symbolic analysis while S keeps its sparsity pattern (new
// materials, a new time step). CHOLMOD's supernodal method factors the dense column blocks of
// L with BLAS: the preconditioner's matrix couples every control point with its 7^3 B-spline
// neighbours, so L is close to dense in blocks and a column-by-column factorisation runs at a
// fraction of the machine's speed (docs/BENCHMARKS.md, "The implicit solver's preconditioner").

#include <Eigen/SparseCore>
#include <memory>

namespace sculpt {

class SparseCholesky {
 public:
  enum class Method { Supernodal, Simplicial };
  /// Supernodal unless the environment says SCULPT_CHOLESKY=simplicial (Eigen's column-by-column
  /// factorisation, kept for comparisons: docs/BENCHMARKS.md).
  static Method defaultMethod();
  explicit SparseCholesky(Method method = defaultMethod());
  ~SparseCholesky();
  SparseCholesky(SparseCholesky&&) noexcept;
  SparseCholesky& operator=(SparseCholesky&&) noexcept;

  /// Factors S (both triangles stored, column-major). False when S is not positive definite;
  /// the previous factor is then gone.
  bool factor(const Eigen::SparseMatrix<double>& S);
  /// The ordering and symbolic analysis for S's pattern alone: a later factor() of a matrix with
  /// this pattern does only the numeric work.
  void analyse(const Eigen::SparseMatrix<double>& S);
  bool valid() const { return valid_; }
  Eigen::Index size() const { return size_; }
  /// z = S^-1 r. Requires valid(). The supernodal factor solves in single precision
  /// (single_precision_factor.h): z is S^-1 r to about 1e-6 relative, for a preconditioner.
  void solve(const Eigen::VectorXd& r, Eigen::VectorXd& z) const;
  enum class Precision { Single, Double };
  /// Z = S^-1 R for many right-hand sides at once, with matrix-matrix products in each
  /// supernode; the supernodal factor, like solve(r), in single precision unless asked for
  /// double (the simplicial one always in double). Requires valid().
  void solve(const Eigen::MatrixXd& R, Eigen::MatrixXd& Z,
             Precision precision = Precision::Single) const;
  /// Nonzeros of L (a measure of the factor's memory and of one solve's cost).
  long long factorNonZeros() const;

 private:
  struct Impl;
  Method method_;
  std::unique_ptr<Impl> impl_;
  bool valid_ = false;
  Eigen::Index size_ = 0;
};

}  // namespace sculpt
