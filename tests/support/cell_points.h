#pragma once
// Points spread at random inside every cell of a volume mesh, `perCell` each, away from the
// cells' faces (local coordinates in [0.05, 0.95], a tetrahedron's pulled inside its long face):
// the embedded vertices of the deformer and field tests.

#include <cstdint>
#include <random>

#include "embed/cell_coordinates.h"
#include "mesh/volume_mesh.h"

namespace sculpt::test {

inline Points randomPointsInCells(const VolumeMesh& mesh, uint32_t perCell, std::mt19937& random) {
  std::uniform_real_distribution<double> uniform(0.05, 0.95);
  Points points(static_cast<Eigen::Index>(mesh.numCells()) * perCell, 3);
  for (uint32_t c = 0, row = 0; c < mesh.numCells(); ++c)
    for (uint32_t k = 0; k < perCell; ++k, ++row) {
      Eigen::Vector3d xi(uniform(random), uniform(random), uniform(random));
      if (mesh.isTetrahedron(c) && xi.sum() > 0.95) xi *= 0.9 / xi.sum();
      points.row(row) = cellPoint(mesh, c, xi).transpose();
    }
  return points;
}

}  // namespace sculpt::test
