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

}  // namespace sculpt
