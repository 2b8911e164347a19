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
  Eigen::MatrixXd C = Eigen::MatrixXd(restrictedMatrix(S, added, added));
  if (n > 0) {
    factor.solve(Eigen::MatrixXd(coupling_), solved_);
    C.noalias() -= coupling_.transpose() * solved_;
  } else {
    solved_.resize(0, m);
  }
  complement_.compute(C);
  if (complement_.info() != Eigen::Success) {
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
