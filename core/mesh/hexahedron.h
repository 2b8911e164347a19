#pragma once
// Walking inside a hexahedral cell: from a face to the opposite face along the cell's edges.

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

}  // namespace sculpt
