#include "mesh/hexahedron.h"

#include <algorithm>

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

}  // namespace sculpt
