#include "sim/factor_extension.h"

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
  std::vector<Eigen::Index> position(size_t(S.rows()), -1);  // in F, then U as n + j
  for (Eigen::Index k = 0; k < n; ++k) position[size_t(factored[size_t(k)])] = k;
  for (Eigen::Index j = 0; j < m; ++j) position[size_t(added[size_t(j)])] = n + j;
  // B is sparse (the factored coordinates next to the added ones): kept so, and dense only as
  // the solve's right-hand sides.
  Eigen::MatrixXd C = Eigen::MatrixXd::Zero(m, m), rightHandSides = Eigen::MatrixXd::Zero(n, m);
  std::vector<Eigen::Triplet<double>> entries;
  for (Eigen::Index j = 0; j < m; ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(S, added[size_t(j)]); it; ++it) {
      const Eigen::Index at = position[size_t(it.row())];
      if (at < 0) continue;  // a pinned coordinate
      if (at >= n) {
        C(at - n, j) = it.value();
      } else {
        rightHandSides(at, j) = it.value();
        entries.emplace_back(at, j, it.value());
      }
    }
  coupling_.resize(n, m);
  coupling_.setFromTriplets(entries.begin(), entries.end());
  if (n > 0) {
    factor.solve(rightHandSides, solved_);
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
  std::vector<int> position(size_t(S.rows()), -1);
  for (size_t j = 0; j < added.size(); ++j) position[size_t(added[j])] = int(j);
  const int m = int(added.size());
  Eigen::SparseMatrix<double> block(m, m);
  Eigen::Index entries = 0;
  for (const int dof : added) entries += S.col(dof).nonZeros();
  block.reserve(entries);
  for (int j = 0; j < m; ++j) {
    block.startVec(j);
    // S's rows come in increasing order, and so do their positions among `added` (increasing).
    for (Eigen::SparseMatrix<double>::InnerIterator it(S, added[size_t(j)]); it; ++it)
      if (const int i = position[size_t(it.row())]; i >= 0) block.insertBack(i, j) = it.value();
  }
  block.finalize();
  if (!uncoupled_.factor(block)) return false;
  added_ = m;
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
