#pragma once
// Walking inside a hexahedral cell: from a face to the opposite face along the cell's edges, and
// the cell's eight corners in the standard (VTK, trilinear-element) order.

#include <array>
#include <cstdint>
#include <optional>

#include "mesh/topology.h"

namespace sculpt {

/// For each of the four vertices of one face of hexahedron `cell`, the vertex at the other end of
/// its one cell edge that leaves that face (same order as `face`). nullopt when some face vertex
/// does not have exactly one such edge (the cell is not a hexahedron around that face).
std::optional<std::array<uint32_t, 4>> hexOppositeFace(const Topology& topology, uint32_t cell,
                                                      const std::array<uint32_t, 4>& face);

/// The vertices of hexahedral cell c in VTK order (also the corner order of the trilinear
/// element): 0-3 a face whose loop (by the right-hand rule) points into the cell, 4-7 the
/// vertices joined to 0-3 by the remaining cell edges. Nullopt when the cell is not a hexahedron.
std::optional<std::array<uint32_t, 8>> vtkHexahedronOrder(const Topology& topology, uint32_t c);

}  // namespace sculpt
