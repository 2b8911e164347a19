#pragma once
// Standard cell shapes in VTK vertex order, turned into face loops that wind counter-clockwise
// when seen from outside (for a positively oriented VTK cell).

#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include <cstdint>

namespace sculpt {

enum class StandardCell { Tetrahedron, Hexahedron, Prism, Pyramid };

/// Parses "tet", "hex", "prism" or "pyramid" (also "tetra", "hexahedron", "wedge").
std::optional<StandardCell> parseStandardCell(std::string_view name);
/// Number of vertices of the shape: 4, 8, 6, 5.
int standardCellVertexCount(StandardCell shape);
/// Outward face loops of the shape over the given vertex ids (VTK order).
std::vector<std::vector<uint32_t>> standardCellFaces(StandardCell shape,
                                                     std::span<const uint32_t> vertices);

}  // namespace sculpt
