#pragma once
// Regularity of level-k cells (docs/design/mj-subdivision.md §6.1) and the 4x4x4 control block of a
// regular cell in a consistent (u, v, w) frame.

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "mesh/topology.h"

namespace sculpt {

/// Frozen values (written to files and reports).
enum class CellRegularity : uint8_t {
  Regular = 0,        ///< hexahedron whose 8 corners are regular: a tricubic B-spline patch
  Extraordinary = 1,  ///< hexahedron touching the boundary or an extraordinary vertex or edge
  Irregular = 2,      ///< not a hexahedron (trapezohedron, tetrahedron, general polyhedron)
};

/// True when v is interior, has exactly 8 incident hexahedra and every incident edge has 4 cells.
bool isRegularVertex(const Topology& topology, uint32_t v);

/// Classifies every cell.
std::vector<CellRegularity> classifyCells(const Topology& topology);

/// 64 vertex ids P[a][b][g] at index a*16 + b*4 + g of a regular cell, a along u. The cell is
/// [1,2]^3 in block indices; u runs from the first vertex of the cell's first face (outward loop)
/// to the previous vertex of that loop, v to the next one, w into the cell: (u, v, w) is
/// right-handed for a positively oriented cell. Returns nullopt when the cell is not regular.
using ControlBlock = std::array<uint32_t, 64>;
std::optional<ControlBlock> regularControlBlock(const Topology& topology, uint32_t cell);

}  // namespace sculpt
