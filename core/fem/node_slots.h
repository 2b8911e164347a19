#pragma once
// Which elements each node belongs to, and in which place: what the node-by-node assemblies
// (the mass matrices, the elements' own stiffness) gather a node's row from.

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "fem/fem_mesh.h"

namespace sculpt {

/// For node n, slots [begin[n], begin[n + 1]) as (element, local node) in increasing element
/// order. A node repeated in an element (a pyramid's apex) has a slot for each of its places.
struct NodeSlots {
  std::vector<uint32_t> begin;
  std::vector<std::pair<uint32_t, uint32_t>> slots;
};

/// The slots of the elements e with !skip(e) (every element when skip is empty).
NodeSlots nodeSlots(const FemMesh& mesh, std::span<const uint8_t> skip = {});

/// The same for elements whose nodes are nodesOf(e) (a range of node numbers), such as the
/// stand-in's cell corners.
template <class NodesOf>
NodeSlots nodeSlots(uint32_t numNodes, uint32_t numElements, const NodesOf& nodesOf,
                    std::span<const uint8_t> skip = {}) {
  auto skipped = [&](uint32_t e) { return !skip.empty() && skip[e]; };
  NodeSlots result;
  result.begin.assign(size_t(numNodes) + 1, 0);
  for (uint32_t e = 0; e < numElements; ++e)
    if (!skipped(e))
      for (uint32_t n : nodesOf(e)) ++result.begin[n + 1];
  for (uint32_t n = 0; n < numNodes; ++n) result.begin[n + 1] += result.begin[n];
  result.slots.resize(result.begin.back());
  std::vector<uint32_t> next(result.begin.begin(), result.begin.end() - 1);
  for (uint32_t e = 0; e < numElements; ++e) {
    if (skipped(e)) continue;
    uint32_t local = 0;
    for (uint32_t n : nodesOf(e)) result.slots[next[n]++] = {e, local++};
  }
  return result;
}

}  // namespace sculpt
