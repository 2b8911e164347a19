#include "sim/factor_extension.h"

#include "sim/restricted_matrix.h"

namespace sculpt {

void FactorExtension::clear() {
  added_ = 0;
  coupled_ = false;
  coupling_ = {};
  solved_.resize(0, 0);
}

double FactorExtension::buildCost(long long factorNonZeros, size_t added) {
  const double m = double(added);
  return 2.0 * double(factorNonZeros) * m + m * m * m / 3.0;
}

bool FactorExtension::build(const SparseCholesky& factor, const Eigen::SparseMatrix<double>& S,
                            const std::vector<int>& factored, const std::vector<int>& added) {
  clear();
  const Eigen::Index n = Eigen::Index(factored.size()), m = Eigen::Index(added.size());
  if (m == 0) return true;
  // B is sparse (the factored coordinates next to the added ones): kept so, and dense only as
  // the solve's right-hand sides.
  coupling_ = restrictedMatrix(S, factored, added);
  const Eigen::MatrixXd S_UU = Eigen::MatrixXd(restrictedMatrix(S, added, added));
  // The complement's pivots against S_UU's diagonal: how much of S_UU the coupling cancels.
  // Each pivot keeps the rounding of Z times the inverse of that ratio.
  auto complement = [&](SparseCholesky::Precision precision) {
    if (n > 0) {
      factor.solve(Eigen::MatrixXd(coupling_), solved_, precision);
      // B^T Z as (Z^T B)^T: each of B's nonzeros adds a contiguous row of Z^T's columns.
      const Eigen::MatrixXd solvedTransposed = solved_.transpose();
      complement_.compute(S_UU - solvedTransposed * coupling_);
    } else {
      solved_.resize(0, m);
      complement_.compute(S_UU);
    }
    if (complement_.info() != Eigen::Success) return 0.0;
    const Eigen::MatrixXd& L = complement_.matrixLLT();
    return (L.diagonal().array().square() / S_UU.diagonal().array()).minCoeff();
  };
  // Z in single precision is close enough for a preconditioner unless the coupling cancels
  // most of a pivot (a nearly singular S); then in double.
  double leastPivotRatio = complement(SparseCholesky::Precision::Single);
  if (leastPivotRatio < kLeastPivotRatioInSingle)
    leastPivotRatio = complement(SparseCholesky::Precision::Double);
  if (leastPivotRatio <= 0.0) {  // not positive definite
    clear();
    return false;
  }
  added_ = m;
  coupled_ = true;
  return true;
}

bool FactorExtension::buildUncoupled(const Eigen::SparseMatrix<double>& S,
                                     const std::vector<int>& added) {
  clear();
  if (added.empty()) return true;
  if (!uncoupled_.factor(restrictedMatrix(S, added, added))) return false;
  added_ = Eigen::Index(added.size());
  coupled_ = false;
  return true;
}

void FactorExtension::finish(Eigen::VectorXd& w, const Eigen::VectorXd& rU,
                             Eigen::VectorXd& xU) const {
  if (!coupled_) {
    uncoupled_.solve(rU, xU);
    return;
  }
  xU = complement_.solve(rU - coupling_.transpose() * w);
  w.noalias() -= solved_ * xU;
}

}  // namespace sculpt
