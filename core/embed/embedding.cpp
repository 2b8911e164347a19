#include "embed/embedding.h"

#include <algorithm>
#include <atomic>
#include <mutex>
#include <stdexcept>
#include <string>

#include "embed/cell_locator.h"
#include "util/parallel_for.h"

namespace sculpt {

Embedding embedPoints(const VolumeMesh& mesh, const Points& points, ProgressReporter* progress) {
  if (mesh.numCells() == 0) throw std::invalid_argument("the cell mesh has no cells to embed in");
  const uint32_t n = static_cast<uint32_t>(points.rows());
  for (uint32_t p = 0; p < n; ++p)
    if (!points.row(p).allFinite())
      throw std::invalid_argument("point " + std::to_string(p) + " has a non-finite coordinate");

  const CellLocator locator(mesh);
  Embedding embedding;
  embedding.cells.assign(n, 0);
  embedding.local.setZero(n, 3);
  std::vector<uint32_t> outside(workerCount() + 1, 0);
  std::vector<double> farthest(workerCount() + 1, 0.0);
  std::atomic<uint32_t> done{0};
  std::atomic<bool> cancelled{false};
  std::mutex progressMutex;
  constexpr uint32_t kBlock = 4096;
  parallelChunks(n, 2 * kBlock, [&](uint32_t begin, uint32_t end, unsigned worker) {
    for (uint32_t blockStart = begin; blockStart < end; blockStart += kBlock) {
      if (cancelled.load(std::memory_order_relaxed)) return;
      const uint32_t blockEnd = std::min(end, blockStart + kBlock);
      for (uint32_t p = blockStart; p < blockEnd; ++p) {
        const CellLocation location = locator.locate(points.row(p).transpose());
        embedding.cells[p] = location.cell;
        embedding.local.row(p) = location.local.transpose();
        if (location.offset.squaredNorm() > 0.0) {
          const std::lock_guard lock(progressMutex);
          embedding.offsetPoints.push_back(p);
          embedding.offsetVectors.push_back(location.offset);
        }
        if (!location.inside) {
          ++outside[worker];
          farthest[worker] = std::max(farthest[worker], location.distance);
        }
      }
      const uint32_t finished = done.fetch_add(blockEnd - blockStart) + (blockEnd - blockStart);
      if (progress && worker == 0) {
        const std::lock_guard lock(progressMutex);
        if (!progress->report(static_cast<double>(finished) / n, "embedding"))
          cancelled.store(true);
      }
    }
  });
  // Workers append in any order; keep the list sorted by point for reproducible output.
  std::vector<size_t> order(embedding.offsetPoints.size());
  for (size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    return embedding.offsetPoints[a] < embedding.offsetPoints[b];
  });
  std::vector<uint32_t> points2;
  std::vector<Eigen::Vector3d> vectors2;
  for (size_t k : order) {
    points2.push_back(embedding.offsetPoints[k]);
    vectors2.push_back(embedding.offsetVectors[k]);
  }
  embedding.offsetPoints = std::move(points2);
  embedding.offsetVectors = std::move(vectors2);
  for (size_t w = 0; w < outside.size(); ++w) {
    embedding.outsideCount += outside[w];
    embedding.maxOutsideDistance = std::max(embedding.maxOutsideDistance, farthest[w]);
  }
  return embedding;
}

}  // namespace sculpt
