#pragma once
// A hexahedral control cage built automatically around an imported surface, the way
// MacCracken–Joy used lattices for free-form deformation: the voxels of a regular grid that lie
// inside the surface or touch it, grown by a margin, become the hexahedral cells of one control
// complex. The margin pays for the shrinkage of the subdivided solid inside its control hull, so
// that the level-K solid still contains every surface vertex.
//
// Steps:
//  1. A regular grid of cubes of side `cellSize` over the surface's bounding box, padded by the
//     margin plus one empty layer.
//  2. Voxels that overlap a surface triangle (exact separating-axis test on a slightly enlarged
//     box; polygons are fanned) are marked.
//  3. The unmarked voxels fall into face-connected regions; a region is inside when the
//     generalized winding number of the surface at its voxel centres exceeds 1/2. Each region is
//     sampled; a region whose samples disagree (a hole wider than a cell lets inside and outside
//     meet) is decided voxel by voxel. The winding number tolerates small holes and
//     slightly open surfaces.
//  4. The marked set is dilated by `marginCells` (26-neighbourhood).
//  5. Lattice vertices around which the voxel set is not a manifold (two voxels sharing only an
//     edge or only a vertex, or a pinched vertex) get their whole 2x2x2 block of voxels filled,
//     repeatedly, so validate() accepts the complex (validation.h rejects such edges as
//     NonManifoldBoundaryEdge and such vertices as NonManifoldBoundaryVertex).
//  6. Each voxel becomes a hexahedron (VTK order, outward face loops); only used lattice points
//     become vertices.

#include <array>
#include <cstdint>

#include "mesh/cell_complex.h"
#include "mesh/surface_mesh.h"

namespace sculpt {

struct CageSettings {
  /// Side of a cubic cell (surface units). 0: the longest bounding-box side / 12.
  double cellSize = 0.0;
  /// Layers of cells added around the voxels that hold the surface (26-neighbourhood dilation).
  int marginCells = 1;
  /// Refusal threshold for the number of grid voxels (nx * ny * nz, not only the kept ones).
  uint64_t maxCells = 2'000'000;
};

struct Cage {
  CellComplex control;                 ///< hexahedral cells (VTK order), shared vertices
  double cellSize = 0.0;               ///< side of a cell
  std::array<uint32_t, 3> gridSize{};  ///< voxels of the grid along x, y, z
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();  ///< min corner of the grid
};

/// Builds the control cage around `surface` (positions #V by 3, polygon faces).
/// Throws std::invalid_argument for a surface without vertices or faces, a face index out of
/// range, a non-finite coordinate, a cell size <= 0 or non-finite (or a surface of zero extent
/// with cellSize 0), a negative margin, or a grid of more than settings.maxCells voxels.
Cage buildSurfaceCage(const SurfaceMesh& surface, const CageSettings& settings = {});

}  // namespace sculpt
