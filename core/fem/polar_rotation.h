#pragma once
// The rotation of a deformation gradient (polar decomposition F = R S), robust to inversion.

#include <Eigen/Core>

namespace sculpt {

/// R with F = R S, S symmetric. For an inverted or degenerate F (det F <= 0) the closest proper
/// rotation is returned (the singular vector of the smallest singular value is flipped), so an
/// inverted element is pushed back instead of being mirrored.
Eigen::Matrix3d polarRotation(const Eigen::Matrix3d& F);

/// The same rotation, found from a nearby rotation `guess` (last step's R of the element):
/// Newton's method on the rotation vector, usually one or two 3x3 solves instead of the five or
/// six inverses of the cold iteration. Falls back to polarRotation(F) when the guess is far, F is
/// inverted or nearly degenerate, or the iteration does not settle; the result agrees with
/// polarRotation(F) to about 1e-14.
Eigen::Matrix3d polarRotation(const Eigen::Matrix3d& F, const Eigen::Matrix3d& guess);

/// rotations[k] = polarRotation(F[k], guess[k]) for k < count (1 to 4), the four solved
/// together in the lanes of 4-wide vectors.
void polarRotations(const Eigen::Matrix3d* F, const Eigen::Matrix3d* guess, int count,
                    Eigen::Matrix3d* rotations);

}  // namespace sculpt
