#include "mesh/hexahedron.h"

#include <algorithm>
#include <vector>

namespace sculpt {

std::optional<std::array<uint32_t, 4>> hexOppositeFace(const Topology& topology, uint32_t cell,
                                                      const std::array<uint32_t, 4>& face) {
  std::array<uint32_t, 4> opposite{};
  for (size_t i = 0; i < 4; ++i) {
    int found = 0;
    for (uint32_t e : topology.cellEdges.row(cell)) {
      const auto& ends = topology.edgeVertices[e];
      if (ends[0] != face[i] && ends[1] != face[i]) continue;
      const uint32_t other = ends[0] == face[i] ? ends[1] : ends[0];
      if (std::find(face.begin(), face.end(), other) != face.end()) continue;
      opposite[i] = other;
      ++found;
    }
    if (found != 1) return std::nullopt;
  }
  return opposite;
}

std::optional<std::array<uint32_t, 8>> vtkHexahedronOrder(const Topology& topology, uint32_t c) {
  if (!topology.isHexahedron(c)) return std::nullopt;
  // The outward loop of the first face, reversed, is a base whose normal points into the cell.
  const std::vector<uint32_t> loop = topology.outwardLoop(c, 0);
  if (loop.size() != 4) return std::nullopt;
  const std::array<uint32_t, 4> base{loop[0], loop[3], loop[2], loop[1]};
  const auto top = hexOppositeFace(topology, c, base);
  if (!top) return std::nullopt;
  return std::array<uint32_t, 8>{base[0],   base[1],   base[2],   base[3],
                                 (*top)[0], (*top)[1], (*top)[2], (*top)[3]};
}

}  // namespace sculpt
