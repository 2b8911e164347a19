#pragma once
// Builds a StencilTable row by row on all workers. Each worker appends its contiguous block of
// rows to its own arrays; the blocks are then joined in row order.

#include <cstdint>
#include <vector>

#include "subdiv/stencil_table.h"
#include "util/parallel_for.h"

namespace sculpt {

/// makeRowWriter() is called once per worker and returns a callable
/// `writer(row, indices, weights)` that appends row's entries (sorted by column) to the vectors.
/// entriesPerRow is a reservation hint.
template <typename MakeRowWriter>
StencilTable buildStencilTableInParallel(uint32_t numRows, uint32_t numColumns,
                                         size_t entriesPerRow, MakeRowWriter makeRowWriter) {
  struct Block {
    std::vector<uint32_t> sizes, indices;
    std::vector<double> weights;
  };
  std::vector<Block> blocks(workerCount());
  parallelChunks(numRows, 1024, [&](uint32_t begin, uint32_t end, unsigned worker) {
    Block& block = blocks[worker];
    block.sizes.reserve(end - begin);
    block.indices.reserve(size_t(end - begin) * entriesPerRow);
    block.weights.reserve(size_t(end - begin) * entriesPerRow);
    auto writer = makeRowWriter();
    for (uint32_t r = begin; r < end; ++r) {
      const size_t before = block.indices.size();
      writer(r, block.indices, block.weights);
      block.sizes.push_back(static_cast<uint32_t>(block.indices.size() - before));
    }
  });
  std::vector<uint32_t> offsets{0}, indices;
  std::vector<double> weights;
  size_t total = 0;
  for (const Block& block : blocks) total += block.indices.size();
  offsets.reserve(numRows + 1);
  indices.reserve(total);
  weights.reserve(total);
  for (const Block& block : blocks) {
    for (uint32_t size : block.sizes) offsets.push_back(offsets.back() + size);
    indices.insert(indices.end(), block.indices.begin(), block.indices.end());
    weights.insert(weights.end(), block.weights.begin(), block.weights.end());
  }
  return StencilTable(numColumns, std::move(offsets), std::move(indices), std::move(weights));
}

}  // namespace sculpt
