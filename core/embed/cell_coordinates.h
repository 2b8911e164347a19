#pragma once
// Local coordinates inside the cells of a VolumeMesh, in the rest state.
//
// A point's local coordinates are xi = (beta1, beta2, beta3) in a tetrahedron (beta0 = 1 - sum)
// and the trilinear (s, t, u) in a hexahedron. Both extend past the cell: points outside it get
// extrapolated coordinates, which the interpolants then extrapolate smoothly.

#include <array>
#include <cstdint>

#include <Eigen/Core>

#include "mesh/volume_mesh.h"

namespace sculpt {

/// The node weights of a cell at local coordinates xi: 4 barycentric or 8 trilinear weights.
/// Returns the number of nodes (4 or 8). Weights sum to 1 for any xi.
int cellNodeWeights(bool tetrahedron, const Eigen::Vector3d& xi, double weights[8]);

/// The rest position at local coordinates xi of `cell`.
Eigen::Vector3d cellPoint(const VolumeMesh& mesh, uint32_t cell, const Eigen::Vector3d& xi);

/// d X / d xi of `cell` at xi (columns are the three local directions).
Eigen::Matrix3d cellJacobian(const VolumeMesh& mesh, uint32_t cell, const Eigen::Vector3d& xi);

/// How far xi lies outside the cell's parameter domain (0 inside; for a tetrahedron the most
/// negative barycentric weight, for a hexahedron the largest excursion beyond [0, 1]).
double localExcursion(bool tetrahedron, const Eigen::Vector3d& xi);

/// Local coordinates of X in `cell`: exact for a tetrahedron; Newton inversion of the trilinear
/// map for a hexahedron, with a damped fall-back that always returns finite coordinates (for
/// points far outside a distorted hexahedron the answer is the best the iteration found).
Eigen::Vector3d cellLocalCoordinates(const VolumeMesh& mesh, uint32_t cell,
                                     const Eigen::Vector3d& X);

/// The rest centroid of a cell (mean of its nodes; for a hexahedron also the image of xi = 1/2).
Eigen::Vector3d cellCentroid(const VolumeMesh& mesh, uint32_t cell);

/// The centre local coordinates: (1/4, 1/4, 1/4) or (1/2, 1/2, 1/2).
inline Eigen::Vector3d cellCentreCoordinates(bool tetrahedron) {
  return Eigen::Vector3d::Constant(tetrahedron ? 0.25 : 0.5);
}

}  // namespace sculpt
