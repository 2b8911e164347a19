#pragma once
// The interpolants of one cell, evaluated exactly in double precision: the reference that the
// fast per-frame kernels are checked against, and the source of deformed normals.
//
//   f(X) = sum_a beta_a(xi) (x_a + alpha F_a (X - X_a)),   X = X(xi) the rest point,
//
// with alpha = 0 (linear), 1/2 (Phong, eq. 19 of James 2020) or 1 (vertex model f_V); beta are
// barycentric weights on tetrahedra and trilinear weights on hexahedra (the paper's section 3.3).

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "mesh/volume_mesh.h"

namespace sculpt {

/// Per-frame data the interpolants read: deformed node positions and node gradients.
struct NodeFrame {
  const Points* positions = nullptr;                    ///< #nodes by 3
  const std::vector<Eigen::Matrix3d>* gradients = nullptr;  ///< F_i per node (unused if alpha = 0)
};

struct InterpolantValue {
  Eigen::Vector3d position;
  Eigen::Matrix3d gradient;  ///< d f / d X
};

/// f and its gradient at local coordinates xi of `cell`.
InterpolantValue evaluateCellInterpolant(const VolumeMesh& rest, const NodeFrame& frame,
                                         uint32_t cell, const Eigen::Vector3d& xi, double alpha);

/// f only (cheaper).
Eigen::Vector3d interpolatePosition(const VolumeMesh& rest, const NodeFrame& frame, uint32_t cell,
                                    const Eigen::Vector3d& xi, double alpha);

/// A rest normal carried by the deformation gradient G: cof(G) N = det(G) G^-T N, normalised.
/// Returns the rest normal when G is singular (a collapsed point has no defined normal).
Eigen::Vector3d deformNormal(const Eigen::Matrix3d& gradient, const Eigen::Vector3d& restNormal);

}  // namespace sculpt
