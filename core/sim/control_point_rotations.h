#pragma once
// A rotation per control point, from the elements' co-rotation frames: the preconditioner turns
// the residual into each point's frame before its solve and the result back after it
// (system_preconditioner.h). A point takes the rotation nearest the weighted mean of the
// rotations of the elements around it: those with a corner node that its stencils reach,
// weighted by the stencil weights.

#include <Eigen/Core>
#include <vector>

#include "fem/fem_model.h"

namespace sculpt {

class ControlPointRotations {
 public:
  explicit ControlPointRotations(const FemModel& model);

  /// From one rotation per element of the model's mesh.
  void update(const std::vector<Eigen::Matrix3d>& elementRotations);
  /// One per control point (identities before the first update).
  const std::vector<Eigen::Matrix3d>& rotations() const { return rotations_; }

 private:
  using RowSparseMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;
  RowSparseMatrix weights_;  // control points by elements
  std::vector<Eigen::Matrix3d> rotations_;
};

}  // namespace sculpt
