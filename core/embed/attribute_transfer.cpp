#include "embed/attribute_transfer.h"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <unordered_map>
#include <vector>

namespace sculpt {
namespace {

/// A hash grid over the nodes with cells of the query radius: a query visits 27 buckets.
class NodeGrid {
 public:
  NodeGrid(const Points& nodes, double spacing) : nodes_(nodes), spacing_(spacing) {
    for (uint32_t i = 0; i < nodes.rows(); ++i) buckets_[key(cellOf(nodes.row(i)))].push_back(i);
  }
  template <typename Visit>
  void forEachNear(const Eigen::RowVector3d& X, int ring, Visit&& visit) const {
    const Eigen::Vector3i c = cellOf(X);
    for (int dz = -ring; dz <= ring; ++dz)
      for (int dy = -ring; dy <= ring; ++dy)
        for (int dx = -ring; dx <= ring; ++dx) {
          const auto it = buckets_.find(key(c + Eigen::Vector3i(dx, dy, dz)));
          if (it == buckets_.end()) continue;
          for (uint32_t node : it->second) visit(node);
        }
  }

 private:
  Eigen::Vector3i cellOf(const Eigen::RowVector3d& X) const {
    Eigen::Vector3i c;
    for (int d = 0; d < 3; ++d) {
      const double v = std::floor(X[d] / spacing_);
      c[d] = static_cast<int>(std::clamp(v, -1e9, 1e9));
    }
    return c;
  }
  static uint64_t key(const Eigen::Vector3i& c) {
    const auto u = [](int v) { return static_cast<uint64_t>(static_cast<uint32_t>(v)) & 0x1fffff; };
    return u(c[0]) | (u(c[1]) << 21) | (u(c[2]) << 42);
  }
  const Points& nodes_;
  double spacing_;
  std::unordered_map<uint64_t, std::vector<uint32_t>> buckets_;
};

}  // namespace

double defaultAttributeRadius(double meanEdgeLength) { return 1.5 * meanEdgeLength; }

CompressedRows<NodeWeight> attributeTransferWeights(const Points& restNodes, const Points& points,
                                                    double radius) {
  if (!(radius > 0.0) || !std::isfinite(radius))
    throw std::invalid_argument("the attribute transfer radius must be a positive number");
  if (restNodes.rows() == 0) throw std::invalid_argument("no nodes to transfer from");
  const NodeGrid grid(restNodes, radius);
  CompressedRows<NodeWeight> rows;
  rows.offsets.reserve(points.rows() + 1);
  const double r2 = radius * radius;
  for (Eigen::Index p = 0; p < points.rows(); ++p) {
    const Eigen::RowVector3d X = points.row(p);
    const size_t first = rows.values.size();
    double sum = 0.0;
    grid.forEachNear(X, 1, [&](uint32_t node) {
      const double d2 = (restNodes.row(node) - X).squaredNorm();
      if (d2 >= r2) return;
      const double k = 1.0 - d2 / r2;
      rows.values.push_back({node, k * k});
      sum += k * k;
    });
    if (rows.values.size() == first) {
      // Nothing within the radius: widen the search ring by ring for the nearest node.
      uint32_t nearest = 0;
      double best = std::numeric_limits<double>::infinity();
      for (int ring = 2; !std::isfinite(best) && ring < 64; ++ring)
        grid.forEachNear(X, ring, [&](uint32_t node) {
          const double d2 = (restNodes.row(node) - X).squaredNorm();
          if (d2 < best) best = d2, nearest = node;
        });
      if (!std::isfinite(best))
        for (uint32_t node = 0; node < restNodes.rows(); ++node) {
          const double d2 = (restNodes.row(node) - X).squaredNorm();
          if (d2 < best) best = d2, nearest = node;
        }
      rows.values.push_back({nearest, 1.0});
      sum = 1.0;
    }
    for (size_t k = first; k < rows.values.size(); ++k) rows.values[k].weight /= sum;
    rows.closeRow();
  }
  return rows;
}

}  // namespace sculpt
