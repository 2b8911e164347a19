#pragma once
// A Cholesky factor of S on some coordinates F, extended exactly to more coordinates U of S by
// block elimination. With B = S_FU, Z = S_FF^-1 B and the Schur complement C = S_UU - B^T Z:
//
//     S_ext^-1 [r_F; r_U] = [w - Z x_U; x_U],   w = S_FF^-1 r_F,   x_U = C^-1 (r_U - B^T w).
//
// The preconditioner uses it for control points released from a pin since its factor was made:
// served by their diagonal alone, they cost CG several times the iterations until a new factor
// arrives (docs/fem.md, "Pin edits"). Building it solves S_FF for the |U| columns of B at once
// (matrix-matrix products in the supernodal factor) and factors the |U| x |U| complement.
//
// Where those solves cost too much (many coordinates and a large factor), the uncoupled form
// drops B: x_U = S_UU^-1 r_U from a sparse factor of S_UU, and w is left as it is (a block
// Jacobi step). It costs almost nothing to build and serves the released points nearly as well.

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <vector>

#include "sim/sparse_cholesky.h"

namespace sculpt {

class FactorExtension {
 public:
  /// S: the system on every coordinate (both triangles stored), of which `factor` factors the
  /// coordinates `factored` (increasing); `added` (none of them factored) are the coordinates to
  /// extend it to. False, and empty, when the complement is not positive definite.
  bool build(const SparseCholesky& factor, const Eigen::SparseMatrix<double>& S,
             const std::vector<int>& factored, const std::vector<int>& added);
  /// The uncoupled form: S_UU alone, factored sparse. False, and empty, when S_UU is not
  /// positive definite.
  bool buildUncoupled(const Eigen::SparseMatrix<double>& S, const std::vector<int>& added);
  void clear();
  bool empty() const { return added_ == 0; }
  bool coupled() const { return coupled_; }
  /// Multiply-adds of build() for `added` coordinates and a factor with `factorNonZeros`
  /// nonzeros in L (a forward and a back substitution per column, and the complement's
  /// factorisation), for deciding whether to.
  static double buildCost(long long factorNonZeros, size_t added);
  /// Given w = S_FF^-1 r_F (the factor's coordinates, in its numbering) and r_U (the added
  /// coordinates, in the order given to build()), completes the extended solve: w becomes its
  /// F part and xU its U part.
  void finish(Eigen::VectorXd& w, const Eigen::VectorXd& rU, Eigen::VectorXd& xU) const;

 private:
  Eigen::Index added_ = 0;
  bool coupled_ = false;
  Eigen::SparseMatrix<double> coupling_;  // B, factored rows x added columns
  Eigen::MatrixXd solved_;    // Z = S_FF^-1 B
  Eigen::LLT<Eigen::MatrixXd> complement_;
  SparseCholesky uncoupled_;  // S_UU, for the uncoupled form
  // Z is solved in single precision (a 1e-7 relative error) unless a pivot of the complement
  // comes out below this share of S_UU's diagonal entry: then in double.
  static constexpr double kLeastPivotRatioInSingle = 1e-3;
};

}  // namespace sculpt
