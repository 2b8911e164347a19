#pragma once
// Embedding a point set (the vertices of a detailed surface) in the rest state of a VolumeMesh:
// each point gets a cell and local coordinates there. Points outside the mesh take the nearest
// cell with extrapolated coordinates; none is dropped and none becomes NaN.

#include <cstdint>
#include <vector>

#include "mesh/cell_complex.h"
#include "mesh/volume_mesh.h"
#include "util/progress.h"

namespace sculpt {

struct Embedding {
  std::vector<uint32_t> cells;  ///< per point, in input order
  Points local;                 ///< per point: (beta1, beta2, beta3) or trilinear (s, t, u)
  uint32_t outsideCount = 0;    ///< points that lie outside every cell
  /// Points far outside a distorted hexahedron (see CellLocation::offset): their local
  /// coordinates are the nearest point of the cell, and offsetVectors[k] = X - X(local).
  std::vector<uint32_t> offsetPoints;
  std::vector<Eigen::Vector3d> offsetVectors;
  double maxOutsideDistance = 0.0;  ///< largest distance of such a point to its cell (upper bound)

  uint32_t numPoints() const { return static_cast<uint32_t>(cells.size()); }
};

/// Embeds `points` in `mesh` (rest state). Runs on all worker threads; reports progress and stops
/// early (returning a partial result with the remaining points in cell 0) when cancelled. Throws
/// std::invalid_argument for a mesh without cells or a non-finite point.
Embedding embedPoints(const VolumeMesh& mesh, const Points& points,
                      ProgressReporter* progress = nullptr);

}  // namespace sculpt
