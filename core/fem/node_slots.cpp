#include "fem/node_slots.h"

namespace sculpt {

NodeSlots nodeSlots(const FemMesh& mesh, std::span<const uint8_t> skip) {
  return nodeSlots(
      mesh.numNodes(), mesh.numElements(), [&](uint32_t e) { return mesh.elementNodes(e); },
      skip);
}

}  // namespace sculpt
