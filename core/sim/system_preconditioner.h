#pragma once
// Cholesky factor of S = a M~ + b D~ + c K~lin on the free coordinates, the preconditioner of
// the implicit and static solves. Refactored when a, b, c or the set of free coordinates
// change, and (at most every few solves) after material edits.

#include <Eigen/SparseCholesky>
#include <vector>

#include "fem/fem_model.h"

namespace sculpt {

class SystemPreconditioner {
 public:
  /// Makes the factor current. Returns false when S cannot be factored even with a small
  /// diagonal shift (then apply() is the identity).
  bool update(const FemModel& model, double massScale, double dampingScale, double stiffnessScale,
              const std::vector<int>& freeDofs);
  /// z = S^-1 r on the free coordinates.
  void apply(const Eigen::VectorXd& r, Eigen::VectorXd& z) const;

 private:
  Eigen::SimplicialLLT<SparseMatrix> factor_;
  bool valid_ = false;
  double scales_[3] = {-1, -1, -1};
  uint64_t materialVersion_ = ~uint64_t(0);
  std::vector<int> freeDofs_;
  SparseMatrix stiffness_;  // K~lin, rebuilt with the materials
  uint64_t stiffnessVersion_ = ~uint64_t(0);
  int solvesSinceRefresh_ = 0;
  static constexpr int kMaterialRefreshInterval = 8;
};

}  // namespace sculpt
