#include "mesh/closed_surface.h"

#include <algorithm>
#include <bit>
#include <numeric>
#include <utility>
#include <vector>

#include <Eigen/Geometry>

namespace sculpt {
namespace {

// Each position's representative: the first index of the positions equal to it. Grouped by a
// hash of the coordinates, so that the cost stays linear in practice (a display surface has
// hundreds of thousands of vertices).
std::vector<uint32_t> weldedIndices(const Points& positions) {
  const auto count = static_cast<uint32_t>(positions.rows());
  std::vector<std::pair<uint64_t, uint32_t>> hashed(count);
  for (uint32_t v = 0; v < count; ++v) {
    uint64_t h = 0x9e3779b97f4a7c15ull;
    for (int d = 0; d < 3; ++d) {  // + 0.0: -0 and +0 are the same coordinate
      h ^= std::bit_cast<uint64_t>(positions(v, d) + 0.0);
      h *= 0xff51afd7ed558ccdull;
      h ^= h >> 33;
    }
    hashed[v] = {h, v};
  }
  std::sort(hashed.begin(), hashed.end());
  std::vector<uint32_t> welded(count);
  for (size_t first = 0; first < hashed.size();) {
    size_t end = first + 1;
    while (end < hashed.size() && hashed[end].first == hashed[first].first) ++end;
    for (size_t k = first; k < end; ++k) {  // runs are one vertex long unless positions repeat
      const uint32_t v = hashed[k].second;
      welded[v] = v;
      for (size_t j = first; j < k; ++j)
        if (positions.row(hashed[j].second) == positions.row(v)) {
          welded[v] = welded[hashed[j].second];
          break;
        }
    }
    first = end;
  }
  return welded;
}

uint32_t findRoot(std::vector<uint32_t>& parent, uint32_t v) {
  while (parent[v] != v) v = parent[v] = parent[parent[v]];
  return v;
}

}  // namespace

bool isClosedOutwardSurface(const Points& positions, std::span<const uint32_t> triangles) {
  if (triangles.empty() || triangles.size() % 3 != 0) return false;
  for (const uint32_t v : triangles)
    if (v >= positions.rows()) return false;
  const std::vector<uint32_t> welded = weldedIndices(positions);
  const size_t numTriangles = triangles.size() / 3;
  const auto corner = [&](size_t t, int k) { return welded[triangles[3 * t + k]]; };

  // Closed and consistently wound: each directed edge once, and its reverse once as well. The
  // edges leaving each vertex, sorted (counting sort by vertex, then each vertex's few).
  std::vector<uint32_t> firstEdge(positions.rows() + 1, 0);
  for (size_t t = 0; t < numTriangles; ++t)
    for (int k = 0; k < 3; ++k) {
      if (corner(t, k) == corner(t, (k + 1) % 3)) return false;  // degenerate
      ++firstEdge[corner(t, k) + 1];
    }
  std::partial_sum(firstEdge.begin(), firstEdge.end(), firstEdge.begin());
  std::vector<uint32_t> target(triangles.size());
  std::vector<uint32_t> filled(firstEdge.begin(), firstEdge.end() - 1);
  for (size_t t = 0; t < numTriangles; ++t)
    for (int k = 0; k < 3; ++k) target[filled[corner(t, k)]++] = corner(t, (k + 1) % 3);
  const auto leaving = [&](uint32_t v) {
    return std::span<uint32_t>(target.data() + firstEdge[v], target.data() + firstEdge[v + 1]);
  };
  for (uint32_t v = 0; v < positions.rows(); ++v) {
    const std::span<uint32_t> edges = leaving(v);
    std::sort(edges.begin(), edges.end());
    if (std::adjacent_find(edges.begin(), edges.end()) != edges.end()) return false;
  }
  for (uint32_t v = 0; v < positions.rows(); ++v)
    for (const uint32_t to : leaving(v)) {
      const std::span<uint32_t> back = leaving(to);
      if (!std::binary_search(back.begin(), back.end(), v)) return false;
    }

  // Each shell (triangles joined through their vertices) encloses a positive volume: the sum of
  // the signed volumes of the tetrahedra from a point (any: the shell is closed) to its
  // triangles, the point on the surface so that far-off coordinates do not cancel.
  std::vector<uint32_t> parent(positions.rows());
  std::iota(parent.begin(), parent.end(), 0u);
  for (size_t t = 0; t < numTriangles; ++t)
    for (int k = 1; k < 3; ++k)
      parent[findRoot(parent, corner(t, k))] = findRoot(parent, corner(t, 0));
  std::vector<double> volume(positions.rows(), 0.0);
  const Eigen::Vector3d apex = positions.row(triangles[0]);
  for (size_t t = 0; t < numTriangles; ++t) {
    const Eigen::Vector3d a = positions.row(triangles[3 * t]).transpose() - apex;
    const Eigen::Vector3d b = positions.row(triangles[3 * t + 1]).transpose() - apex;
    const Eigen::Vector3d c = positions.row(triangles[3 * t + 2]).transpose() - apex;
    volume[findRoot(parent, corner(t, 0))] += a.dot(b.cross(c)) / 6.0;
  }
  for (size_t t = 0; t < numTriangles; ++t)
    if (!(volume[findRoot(parent, corner(t, 0))] > 0.0)) return false;
  return true;
}

}  // namespace sculpt
