#include "sim/system_preconditioner.h"

#include "sim/linear_stiffness.h"

namespace sculpt {

bool SystemPreconditioner::update(const FemModel& model, double massScale, double dampingScale,
                                  double stiffnessScale, const std::vector<int>& freeDofs) {
  const uint64_t version = model.materialVersion();
  const bool sameSystem = scales_[0] == massScale && scales_[1] == dampingScale &&
                          scales_[2] == stiffnessScale && freeDofs_ == freeDofs;
  ++solvesSinceRefresh_;
  // Painting changes the materials many times per second. A preconditioner a few strokes old
  // costs a few CG iterations, not accuracy, so material changes refactor at most every
  // kMaterialRefreshInterval solves.
  if (sameSystem && (materialVersion_ == version || solvesSinceRefresh_ < kMaterialRefreshInterval))
    return valid_;
  solvesSinceRefresh_ = 0;
  if (stiffnessVersion_ != version || stiffness_.rows() == 0) {
    stiffness_ = reducedLinearStiffness(model);
    stiffnessVersion_ = version;
  }
  scales_[0] = massScale;
  scales_[1] = dampingScale;
  scales_[2] = stiffnessScale;
  materialVersion_ = version;
  freeDofs_ = freeDofs;

  SparseMatrix S = stiffnessScale * stiffness_;
  if (massScale != 0) S += massScale * kroneckerIdentity3(model.reducedMass());
  if (dampingScale != 0) S += dampingScale * kroneckerIdentity3(model.reducedDamping());

  // Restrict to the free coordinates.
  std::vector<int> freeIndex(size_t(S.rows()), -1);
  for (size_t k = 0; k < freeDofs.size(); ++k) freeIndex[size_t(freeDofs[k])] = int(k);
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(size_t(S.nonZeros()));
  double diagonalSum = 0;
  for (int col = 0; col < S.outerSize(); ++col)
    for (SparseMatrix::InnerIterator it(S, col); it; ++it) {
      const int r = freeIndex[size_t(it.row())], c = freeIndex[size_t(it.col())];
      if (r < 0 || c < 0) continue;
      triplets.emplace_back(r, c, it.value());
      if (r == c) diagonalSum += it.value();
    }
  const int n = int(freeDofs.size());
  SparseMatrix restricted(n, n);
  restricted.setFromTriplets(triplets.begin(), triplets.end());

  // A solid held by nothing but springs has rigid modes in K~lin: shift them slightly.
  const double meanDiagonal = n > 0 ? diagonalSum / n : 1.0;
  for (double shift : {0.0, 1e-10, 1e-6}) {
    SparseMatrix shifted = restricted;
    if (shift > 0) {
      for (int i = 0; i < n; ++i) shifted.coeffRef(i, i) += shift * meanDiagonal;
    }
    factor_.compute(shifted);
    valid_ = factor_.info() == Eigen::Success;
    if (valid_) break;
  }
  return valid_;
}

void SystemPreconditioner::apply(const Eigen::VectorXd& r, Eigen::VectorXd& z) const {
  if (valid_) z = factor_.solve(r);
  else z = r;
}

}  // namespace sculpt
