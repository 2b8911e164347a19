#include "mesh/standard_cell.h"

#include <array>

namespace sculpt {

std::optional<StandardCell> parseStandardCell(std::string_view name) {
  if (name == "tet" || name == "tetra" || name == "tetrahedron") return StandardCell::Tetrahedron;
  if (name == "hex" || name == "hexahedron") return StandardCell::Hexahedron;
  if (name == "prism" || name == "wedge") return StandardCell::Prism;
  if (name == "pyramid") return StandardCell::Pyramid;
  return std::nullopt;
}

int standardCellVertexCount(StandardCell shape) {
  switch (shape) {
    case StandardCell::Tetrahedron: return 4;
    case StandardCell::Hexahedron: return 8;
    case StandardCell::Prism: return 6;
    case StandardCell::Pyramid: return 5;
  }
  return 0;
}

std::vector<std::vector<uint32_t>> standardCellFaces(StandardCell shape,
                                                     std::span<const uint32_t> v) {
  // Local loops per shape, in VTK numbering. VTK's hexahedron and pyramid list the base so that
  // its normal points into the cell; VTK's wedge lists (0,1,2) with an outward normal.
  using Loops = std::vector<std::vector<int>>;
  static const Loops tet = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}};
  static const Loops hex = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                            {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  static const Loops prism = {{0, 1, 2}, {3, 5, 4}, {0, 3, 4, 1}, {1, 4, 5, 2}, {2, 5, 3, 0}};
  static const Loops pyramid = {{0, 3, 2, 1}, {0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}};
  const Loops* local = nullptr;
  switch (shape) {
    case StandardCell::Tetrahedron: local = &tet; break;
    case StandardCell::Hexahedron: local = &hex; break;
    case StandardCell::Prism: local = &prism; break;
    case StandardCell::Pyramid: local = &pyramid; break;
  }
  std::vector<std::vector<uint32_t>> faces;
  for (const auto& loop : *local) {
    std::vector<uint32_t> face;
    for (int i : loop) face.push_back(v[static_cast<size_t>(i)]);
    faces.push_back(std::move(face));
  }
  return faces;
}

}  // namespace sculpt
