#include "subdiv/stencil_table.h"

#include <algorithm>
#include <cassert>
#include <numeric>

#include "subdiv/stencil_builder.h"
#include "util/parallel_for.h"

namespace sculpt {
namespace {
// Fewer rows than this run on the calling thread: below it a fork-join costs more than it saves.
constexpr uint32_t kParallelRows = 1024;
}  // namespace

StencilTable::StencilTable(uint32_t numColumns, std::vector<uint32_t> offsets,
                           std::vector<uint32_t> indices, std::vector<double> weights)
    : numColumns_(numColumns),
      offsets_(std::move(offsets)),
      indices_(std::move(indices)),
      weights_(std::move(weights)) {
  assert(!offsets_.empty() && offsets_.back() == indices_.size());
  assert(indices_.size() == weights_.size());
}

StencilTable StencilTable::identity(uint32_t n) {
  std::vector<uint32_t> offsets(n + 1), indices(n);
  std::iota(offsets.begin(), offsets.end(), 0u);
  std::iota(indices.begin(), indices.end(), 0u);
  return StencilTable(n, std::move(offsets), std::move(indices), std::vector<double>(n, 1.0));
}

void StencilTable::apply(const Points& src, Points& dst) const {
  assert(src.rows() == numColumns_);
  dst.resize(numRows(), 3);
  const double* in = src.data();
  double* out = dst.data();
  parallelChunks(numRows(), kParallelRows, [&](uint32_t begin, uint32_t end, unsigned) {
    for (uint32_t r = begin; r < end; ++r) {
      double x = 0, y = 0, z = 0;
      for (uint32_t k = offsets_[r]; k < offsets_[r + 1]; ++k) {
        const double w = weights_[k];
        const double* p = in + 3 * size_t(indices_[k]);
        x += w * p[0];
        y += w * p[1];
        z += w * p[2];
      }
      out[3 * size_t(r)] = x;
      out[3 * size_t(r) + 1] = y;
      out[3 * size_t(r) + 2] = z;
    }
  });
}

void StencilTable::applyTranspose(const Points& src, Points& dst) const {
  assert(src.rows() == numRows());
  // A scatter (rows write to shared columns): each worker accumulates its chunk of rows into a
  // buffer of its own, and the buffers are summed. This is on the FEM's per-step path (node
  // forces onto control points), where #columns is much smaller than #rows.
  std::vector<Points> partial(workerCount());
  const double* in = src.data();
  parallelChunks(numRows(), kParallelRows, [&](uint32_t begin, uint32_t end, unsigned worker) {
    Points& out = partial[worker];
    out.setZero(numColumns_, 3);
    double* sum = out.data();
    for (uint32_t r = begin; r < end; ++r) {
      const double x = in[3 * size_t(r)], y = in[3 * size_t(r) + 1], z = in[3 * size_t(r) + 2];
      for (uint32_t k = offsets_[r]; k < offsets_[r + 1]; ++k) {
        const double w = weights_[k];
        double* column = sum + 3 * size_t(indices_[k]);
        column[0] += w * x;
        column[1] += w * y;
        column[2] += w * z;
      }
    }
  });
  dst.setZero(numColumns_, 3);
  for (const Points& out : partial)
    if (out.rows() == dst.rows()) dst += out;
}

std::vector<double> StencilTable::rowSums() const {
  std::vector<double> sums(numRows(), 0.0);
  for (uint32_t r = 0; r < numRows(); ++r)
    for (uint32_t k = offsets_[r]; k < offsets_[r + 1]; ++k) sums[r] += weights_[k];
  return sums;
}

StencilTable StencilTable::compose(const StencilTable& outer, const StencilTable& inner) {
  assert(outer.numColumns() == inner.numRows());
  // Each worker merges rows with a dense accumulator over inner's columns.
  auto makeRowWriter = [&] {
    return [&, accumulator = std::vector<double>(inner.numColumns(), 0.0),
            touched = std::vector<uint8_t>(inner.numColumns(), 0),
            columns = std::vector<uint32_t>()](uint32_t r, std::vector<uint32_t>& indices,
                                               std::vector<double>& weights) mutable {
      columns.clear();
      for (uint32_t k = outer.offsets_[r]; k < outer.offsets_[r + 1]; ++k) {
        const uint32_t mid = outer.indices_[k];
        const double w = outer.weights_[k];
        for (uint32_t j = inner.offsets_[mid]; j < inner.offsets_[mid + 1]; ++j) {
          const uint32_t col = inner.indices_[j];
          if (!touched[col]) {
            touched[col] = 1;
            columns.push_back(col);
          }
          accumulator[col] += w * inner.weights_[j];
        }
      }
      std::sort(columns.begin(), columns.end());
      for (uint32_t col : columns) {
        indices.push_back(col);
        weights.push_back(accumulator[col]);
        accumulator[col] = 0.0;
        touched[col] = 0;
      }
    };
  };
  return buildStencilTableInParallel(outer.numRows(), inner.numColumns(), 32, makeRowWriter);
}

StencilChain::StencilChain(std::vector<StencilTable> levels) : levels_(std::move(levels)) {}

uint32_t StencilChain::numRows() const { return levels_.empty() ? 0 : levels_.back().numRows(); }
uint32_t StencilChain::numColumns() const {
  return levels_.empty() ? 0 : levels_.front().numColumns();
}

namespace {
// Intermediate levels of StencilChain products: per thread, so that any number of threads
// can apply chains at once, and kept between calls (no allocation per frame).
std::vector<Points>& chainScratch() {
  thread_local std::vector<Points> scratch;
  return scratch;
}
}  // namespace

void StencilChain::apply(const Points& src, Points& dst) const {
  applyLevels(src, dst, false);
}

void StencilChain::applyTranspose(const Points& src, Points& dst) const {
  applyLevels(src, dst, true);
}

void StencilChain::applyLevels(const Points& src, Points& dst, bool transpose) const {
  if (levels_.empty()) {
    dst = src;
    return;
  }
  const size_t count = levels_.size();
  std::vector<Points>& scratch = chainScratch();
  if (scratch.size() < count) scratch.resize(count);
  const Points* current = &src;
  for (size_t step = 0; step < count; ++step) {
    // S_1 first forwards; S_K^T first for the transpose.
    const StencilTable& level = levels_[transpose ? count - 1 - step : step];
    Points& out = step + 1 == count ? dst : scratch[step];
    if (transpose)
      level.applyTranspose(*current, out);
    else
      level.apply(*current, out);
    current = &out;
  }
}

}  // namespace sculpt
