#pragma once
// The boundary surface of a cell complex: its boundary faces (faces of exactly one cell) as a
// polygon surface wound counter-clockwise seen from outside, over only the vertices they use.
// The OBJ writer writes it and the window refines it into the embedded surface of a control mesh.

#include <array>
#include <cstdint>
#include <vector>

#include "mesh/cell_complex.h"
#include "mesh/surface_mesh.h"
#include "mesh/topology.h"

namespace sculpt {

struct BoundarySurface {
  /// #B by 3 positions (the boundary vertices in increasing complex index) and the boundary
  /// faces in the topology's face order, outward (positions only in the corners).
  SurfaceMesh surface;
  /// #B: the complex vertex of each surface vertex (increasing).
  std::vector<uint32_t> complexVertex;
  /// The complex's crease and corner tags that lie on the boundary, in surface vertex indices.
  std::vector<std::array<uint32_t, 2>> creases;
  std::vector<uint32_t> corners;
};

/// The boundary of `complex` (with its `topology`). A complex without cells gives an empty
/// surface.
BoundarySurface boundarySurface(const CellComplex& complex, const Topology& topology);

}  // namespace sculpt
