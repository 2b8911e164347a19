#pragma once
// Points between the view's glm vectors and the simulation's Eigen matrices (one row a point).

#include <Eigen/Core>
#include <glm/glm.hpp>

#include "mesh/cell_complex.h"

namespace sculpt::app {

inline Eigen::Vector3d toEigen(const glm::vec3& v) { return Eigen::Vector3d(v.x, v.y, v.z); }

/// Row i of a point matrix (control points, nodes) as a glm vector.
inline glm::vec3 pointRow(const Points& points, uint32_t i) {
  return glm::vec3(points(i, 0), points(i, 1), points(i, 2));
}

}  // namespace sculpt::app
