#pragma once
// The rotation of a deformation gradient (polar decomposition F = R S), robust to inversion.

#include <Eigen/Core>

namespace sculpt {

/// R with F = R S, S symmetric. For an inverted or degenerate F (det F <= 0) the closest proper
/// rotation is returned (the singular vector of the smallest singular value is flipped), so an
/// inverted element is pushed back instead of being mirrored.
Eigen::Matrix3d polarRotation(const Eigen::Matrix3d& F);

}  // namespace sculpt
