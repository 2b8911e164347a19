#include "sim/single_precision_factor.h"

#include <algorithm>
#include <cmath>

namespace sculpt {

void SinglePrecisionFactor::copy(const cholmod_factor& L) {
  n_ = 0;
  if (!L.is_super || !L.is_ll || L.xtype != CHOLMOD_REAL || L.dtype != CHOLMOD_DOUBLE ||
      L.itype != CHOLMOD_INT || L.n == 0 || !L.Perm)
    return;
  const size_t supernodes = L.nsuper;
  const int* super = static_cast<const int*>(L.super);
  const int* pi = static_cast<const int*>(L.pi);
  const int* px = static_cast<const int*>(L.px);
  const int* s = static_cast<const int*>(L.s);
  const double* x = static_cast<const double*>(L.x);
  const int* perm = static_cast<const int*>(L.Perm);
  permutation_.assign(perm, perm + L.n);
  firstColumn_.assign(super, super + supernodes + 1);
  rowsBegin_.assign(pi, pi + supernodes + 1);
  valuesBegin_.assign(px, px + supernodes + 1);
  rows_.assign(s, s + pi[supernodes]);
  // Stored as L / 2^e with 2^e near L's largest diagonal entry, so that single precision's
  // range (1e-38 to 1e38) holds the factor of any S, and a power of two changes no digit.
  double largest = 0.0;
  for (size_t sn = 0; sn < supernodes; ++sn)
    for (int c = 0; c < super[sn + 1] - super[sn]; ++c)
      largest = std::max(largest, std::abs(x[px[sn] + c * (pi[sn + 1] - pi[sn]) + c]));
  if (!(largest > 0.0) || !std::isfinite(largest)) return;
  std::frexp(largest, &exponent_);
  values_.resize(size_t(px[supernodes]));
  std::transform(x, x + px[supernodes], values_.begin(),
                 [&](double v) { return static_cast<float>(std::ldexp(v, -exponent_)); });
  if (!std::all_of(values_.begin(), values_.end(), [](float v) { return std::isfinite(v); }))
    return;
  n_ = static_cast<Eigen::Index>(L.n);
  work_.resize(n_);
}

// Solves (L L^T) Y = P R, in place in y (R permuted and scaled), supernode by supernode: the
// diagonal block, then the rows below it; a vector (the preconditioner's solve) or a matrix
// (many right-hand sides: each supernode's products become matrix-matrix products).
template <typename Work>
void SinglePrecisionFactor::solveInPlace(Work& y, Work& below) const {
  using Block = Eigen::Map<const Eigen::MatrixXf, 0, Eigen::OuterStride<>>;
  const size_t supernodes = firstColumn_.size() - 1;
  for (size_t sn = 0; sn < supernodes; ++sn) {
    const int first = firstColumn_[sn], columns = firstColumn_[sn + 1] - first;
    const int rows = rowsBegin_[sn + 1] - rowsBegin_[sn], belowRows = rows - columns;
    const Block block(values_.data() + valuesBegin_[sn], rows, columns, Eigen::OuterStride<>(rows));
    auto head = y.middleRows(first, columns);
    block.topRows(columns).template triangularView<Eigen::Lower>().solveInPlace(head);
    if (belowRows == 0) continue;
    below.noalias() = block.bottomRows(belowRows) * head;
    const int* index = rows_.data() + rowsBegin_[sn] + columns;
    for (int i = 0; i < belowRows; ++i) y.row(index[i]) -= below.row(i);
  }
  // L^T y = y, in reverse.
  for (size_t sn = supernodes; sn-- > 0;) {
    const int first = firstColumn_[sn], columns = firstColumn_[sn + 1] - first;
    const int rows = rowsBegin_[sn + 1] - rowsBegin_[sn], belowRows = rows - columns;
    const Block block(values_.data() + valuesBegin_[sn], rows, columns, Eigen::OuterStride<>(rows));
    auto head = y.middleRows(first, columns);
    if (belowRows > 0) {
      below.resize(belowRows, y.cols());
      const int* index = rows_.data() + rowsBegin_[sn] + columns;
      for (int i = 0; i < belowRows; ++i) below.row(i) = y.row(index[i]);
      head.noalias() -= block.bottomRows(belowRows).transpose() * below;
    }
    block.topRows(columns).template triangularView<Eigen::Lower>().transpose().solveInPlace(head);
  }
}

template <typename Dense, typename Work>
bool SinglePrecisionFactor::solveScaled(const Dense& r, Dense& z, Work& y, Work& below) const {
  // r / 2^f with 2^f near max |r|: (L L^T)^-1 r = 2^(f - 2e) (L' L'^T)^-1 (r / 2^f), L' = L / 2^e.
  const double largest = r.size() ? r.cwiseAbs().maxCoeff() : 0.0;
  if (!std::isfinite(largest)) return false;
  if (largest == 0.0) {
    z.setZero(n_, r.cols());
    return true;
  }
  int exponent = 0;
  std::frexp(largest, &exponent);
  y.resize(n_, r.cols());
  for (Eigen::Index k = 0; k < n_; ++k)
    y.row(k) = r.row(permutation_[size_t(k)]).unaryExpr([&](double v) {
      return static_cast<float>(std::ldexp(v, -exponent));
    });
  solveInPlace(y, below);
  if (!y.allFinite()) return false;
  z.resize(n_, r.cols());
  const int back = exponent - 2 * exponent_;
  for (Eigen::Index k = 0; k < n_; ++k)
    z.row(permutation_[size_t(k)]) =
        y.row(k).unaryExpr([&](float v) { return std::ldexp(static_cast<double>(v), back); });
  return true;
}

bool SinglePrecisionFactor::solve(const Eigen::VectorXd& r, Eigen::VectorXd& z) const {
  return solveScaled(r, z, work_, below_);
}

bool SinglePrecisionFactor::solve(const Eigen::MatrixXd& R, Eigen::MatrixXd& Z) const {
  // Row-major: a row of L's structure scatters to (and gathers from) one contiguous row.
  Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> y, below;
  return solveScaled(R, Z, y, below);
}

}  // namespace sculpt
