#include "fem/node_slots.h"

namespace sculpt {

NodeSlots nodeSlots(const FemMesh& mesh, std::span<const uint8_t> skip) {
  const uint32_t numNodes = mesh.numNodes(), numElements = mesh.numElements();
  auto skipped = [&](uint32_t e) { return !skip.empty() && skip[e]; };
  NodeSlots result;
  result.begin.assign(size_t(numNodes) + 1, 0);
  for (uint32_t e = 0; e < numElements; ++e)
    if (!skipped(e))
      for (uint32_t n : mesh.elementNodes(e)) ++result.begin[n + 1];
  for (uint32_t n = 0; n < numNodes; ++n) result.begin[n + 1] += result.begin[n];
  result.slots.resize(result.begin.back());
  std::vector<uint32_t> next(result.begin.begin(), result.begin.end() - 1);
  for (uint32_t e = 0; e < numElements; ++e) {
    if (skipped(e)) continue;
    const std::span<const uint32_t> ids = mesh.elementNodes(e);
    for (uint32_t local = 0; local < ids.size(); ++local)
      result.slots[next[ids[local]]++] = {e, local};
  }
  return result;
}

}  // namespace sculpt
