#pragma once
// What the stand-in and the elements' own rest stiffness share: a node matrix kept as 3x3
// blocks row by row, assembled from symmetric element matrices and reduced to the control
// points, and a linear element's rest stiffness.

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cstdint>
#include <numeric>
#include <span>
#include <vector>

#include "fem/fem_mesh.h"
#include "fem/mass_matrix.h"
#include "fem/node_slots.h"

namespace sculpt {

/// A matrix of 3x3 blocks row by row (a node matrix, or the reduction's products): row n couples
/// its point's coordinates with point column[k]'s through block[k], k in [begin[n], begin[n + 1]).
struct NodeBlockRows {
  std::vector<uint32_t> begin{0};
  std::vector<uint32_t> column;
  std::vector<Eigen::Matrix3d> block;
  uint32_t numNodes() const { return uint32_t(begin.size() - 1); }
};

/// A symmetric node matrix being assembled from symmetric element matrices, zero at first, of
/// which only the blocks on and above the diagonal are kept: row n holds, in increasing order,
/// n itself and every node m > n it shares an element with (reduceSymmetricNodeBlocks needs no
/// others, and they would double the memory, whose first touch is dear: docs/memory.md).
struct SymmetricNodeBlocks {
  NodeBlockRows K;
  NodeSlots around;  ///< the elements around each node, which the pattern was made from
};

/// where[m] = the place of node m in n's row, for every m in it.
inline void placeUpperRow(const SymmetricNodeBlocks& nodes, uint32_t n,
                          std::vector<uint32_t>& where) {
  for (uint32_t k = nodes.K.begin[n]; k < nodes.K.begin[n + 1]; ++k) where[nodes.K.column[k]] = k;
}

/// The pattern of elements whose nodes are nodesOf(e), e < numElements, leaving out those with
/// skip[e] (none when skip is empty).
template <class NodesOf>
SymmetricNodeBlocks symmetricNodePattern(uint32_t numNodes, uint32_t numElements,
                                         const NodesOf& nodesOf,
                                         std::span<const uint8_t> skip = {}) {
  SymmetricNodeBlocks result;
  result.around = nodeSlots(numNodes, numElements, nodesOf, skip);
  const NodeSlots& around = result.around;
  NodeBlockRows& K = result.K;
  K.begin.reserve(size_t(numNodes) + 1);
  std::vector<uint32_t> seenBy(numNodes, ~0u);
  for (uint32_t n = 0; n < numNodes; ++n) {
    const size_t rowBegin = K.column.size();
    for (uint32_t k = around.begin[n]; k < around.begin[n + 1]; ++k)
      for (uint32_t m : nodesOf(around.slots[k].first))
        if (m >= n && seenBy[m] != n) {
          seenBy[m] = n;
          K.column.push_back(m);
        }
    std::sort(K.column.begin() + std::ptrdiff_t(rowBegin), K.column.end());
    K.begin.push_back(uint32_t(K.column.size()));
  }
  K.block.assign(K.column.size(), Eigen::Matrix3d::Zero());
  return result;
}

/// Adds the blocks on and above the diagonal of a symmetric element matrix on nodes `ids` (at
/// most kTricubicNodes): blockOf(a, b) couples the element's nodes a and b. `where` (one entry
/// per node) is scratch.
template <class BlockOf>
void addUpperBlocks(SymmetricNodeBlocks& nodes, std::span<const uint32_t> ids,
                    const BlockOf& blockOf, std::vector<uint32_t>& where) {
  const int count = int(ids.size());
  std::array<int, kTricubicNodes> order;
  std::iota(order.begin(), order.begin() + count, 0);
  std::sort(order.begin(), order.begin() + count, [&](int a, int b) {
    return ids[size_t(a)] < ids[size_t(b)];
  });
  NodeBlockRows& K = nodes.K;
  for (int i = 0; i < count; ++i) {
    const int a = order[size_t(i)];
    const uint32_t n = ids[size_t(a)];
    placeUpperRow(nodes, n, where);  // without a search per node
    for (int j = i; j < count; ++j) {
      const int b = order[size_t(j)];
      Eigen::Matrix3d& target = K.block[where[ids[size_t(b)]]];
      target += blockOf(a, b);
      // A node in two places of the element (a pyramid's apex) gets both blocks between them.
      if (j != i && ids[size_t(b)] == n) target += blockOf(b, a);
    }
  }
}

/// S = (A x I3)^T K (A x I3), 3N by 3N (control point i, coordinate c at row 3i + c), for the
/// symmetric K whose blocks on and above the diagonal `nodes` holds.
SparseMatrix reduceSymmetricNodeBlocks(const SymmetricNodeBlocks& nodes, const SparseMatrix& A);

/// A trilinear or pyramid element's rest stiffness from its own Gauss points: 24 x 24, node a's
/// coordinate c at row 3a + c.
Eigen::Matrix<double, 24, 24> linearElementStiffness(const FemMesh& mesh,
                                                     std::span<const LameParameters> lame,
                                                     uint32_t e);

}  // namespace sculpt
