#include "embed/cell_locator.h"

#include <algorithm>
#include <limits>
#include <queue>

#include "embed/cell_coordinates.h"

namespace sculpt {
namespace {

constexpr uint32_t kLeafSize = 4;
constexpr double kInsideTolerance = 1e-9;

/// The point of the cell's parameter domain nearest to xi (clamped), for a distance estimate.
Eigen::Vector3d clampToCell(bool tetrahedron, Eigen::Vector3d xi) {
  if (!tetrahedron) return xi.cwiseMax(0.0).cwiseMin(1.0);
  xi = xi.cwiseMax(0.0);
  const double sum = xi.sum();
  if (sum > 1.0) xi /= sum;
  return xi;
}

}  // namespace

CellLocator::CellLocator(const VolumeMesh& mesh) : mesh_(mesh) {
  const uint32_t n = mesh.numCells();
  cellBoxes_.resize(n);
  std::vector<Eigen::Vector3d> centres(n);
  for (uint32_t c = 0; c < n; ++c) {
    Eigen::AlignedBox3d box;
    for (uint32_t node : mesh.cells.row(c)) box.extend(mesh.positions.row(node).transpose());
    cellBoxes_[c] = box;
    centres[c] = box.center();
  }
  // Barycentric coordinates are V^-1 (X - X0): inverting once per tetrahedron here makes each
  // candidate test a 3x3 product.
  tetInverse_.assign(n, Eigen::Matrix3d::Identity());
  for (uint32_t c = 0; c < n; ++c)
    if (mesh.isTetrahedron(c))
      tetInverse_[c] = cellJacobian(mesh, c, Eigen::Vector3d::Zero()).inverse();
  order_.resize(n);
  for (uint32_t c = 0; c < n; ++c) order_[c] = c;
  nodes_.reserve(2 * (n / kLeafSize + 1));
  if (n > 0) build(0, n, centres);
}

uint32_t CellLocator::build(uint32_t begin, uint32_t end, std::vector<Eigen::Vector3d>& centres) {
  const uint32_t index = static_cast<uint32_t>(nodes_.size());
  nodes_.emplace_back();
  Eigen::AlignedBox3d box, centreBox;
  for (uint32_t i = begin; i < end; ++i) {
    box.extend(cellBoxes_[order_[i]]);
    centreBox.extend(centres[order_[i]]);
  }
  nodes_[index].box = box;
  if (end - begin <= kLeafSize) {
    nodes_[index].first = begin;
    nodes_[index].count = end - begin;
    return index;
  }
  // Median split along the longest extent of the cell centres.
  int axis = 0;
  centreBox.sizes().maxCoeff(&axis);
  const uint32_t middle = begin + (end - begin) / 2;
  std::nth_element(order_.begin() + begin, order_.begin() + middle, order_.begin() + end,
                   [&](uint32_t a, uint32_t b) { return centres[a][axis] < centres[b][axis]; });
  const uint32_t left = build(begin, middle, centres);
  const uint32_t right = build(middle, end, centres);
  nodes_[index].left = left;
  nodes_[index].right = right;
  return index;
}

CellLocation CellLocator::evaluate(uint32_t cell, const Eigen::Vector3d& X) const {
  CellLocation location;
  location.cell = cell;
  const bool tetrahedron = mesh_.isTetrahedron(cell);
  location.local =
      tetrahedron
          ? Eigen::Vector3d(tetInverse_[cell] *
                            (X - mesh_.positions.row(mesh_.cells.row(cell)[0]).transpose()))
          : cellLocalCoordinates(mesh_, cell, X);
  location.inside = localExcursion(tetrahedron, location.local) <= kInsideTolerance;
  if (location.inside) return location;
  if (!tetrahedron) {
    const Eigen::Vector3d residual = X - cellPoint(mesh_, cell, location.local);
    const double scale = cellBoxes_[cell].sizes().norm();
    if (residual.norm() > 1e-9 * scale) {
      location.local = clampToCell(false, location.local);
      location.offset = X - cellPoint(mesh_, cell, location.local);
      location.distance = location.offset.norm();
      return location;
    }
  }
  location.distance =
      (cellPoint(mesh_, cell, clampToCell(tetrahedron, location.local)) - X).norm();
  return location;
}

bool CellLocator::findContaining(const Eigen::Vector3d& X, CellLocation& location) const {
  // Depth-first over boxes that contain X; the first cell whose local coordinates are inside wins.
  // Median splits keep the depth below 33 for any uint32 cell count, and a pop pushes at most
  // two entries, so 72 slots cannot overflow.
  uint32_t stack[72];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    if (!node.box.contains(X)) continue;
    if (node.count == 0) {
      stack[top++] = node.right;
      stack[top++] = node.left;
      continue;
    }
    for (uint32_t i = node.first; i < node.first + node.count; ++i) {
      const uint32_t cell = order_[i];
      if (!cellBoxes_[cell].contains(X)) continue;
      const CellLocation candidate = evaluate(cell, X);
      if (candidate.inside) {
        location = candidate;
        return true;
      }
    }
  }
  return false;
}

void CellLocator::findNearest(const Eigen::Vector3d& X, CellLocation& location) const {
  // Best-first over boxes by their distance to X; a cell's distance estimate is never below its
  // box distance, so the search stops once the nearest unvisited box is farther than the best.
  using Entry = std::pair<double, uint32_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
  queue.emplace(nodes_[0].box.exteriorDistance(X), 0);
  location.distance = std::numeric_limits<double>::infinity();
  bool found = false;
  while (!queue.empty()) {
    const auto [boxDistance, index] = queue.top();
    queue.pop();
    if (found && boxDistance >= location.distance) break;
    const Node& node = nodes_[index];
    if (node.count == 0) {
      queue.emplace(nodes_[node.left].box.exteriorDistance(X), node.left);
      queue.emplace(nodes_[node.right].box.exteriorDistance(X), node.right);
      continue;
    }
    for (uint32_t i = node.first; i < node.first + node.count; ++i) {
      const uint32_t cell = order_[i];
      if (found && cellBoxes_[cell].exteriorDistance(X) >= location.distance) continue;
      const CellLocation candidate = evaluate(cell, X);
      if (!found || candidate.distance < location.distance) {
        location = candidate;
        found = true;
      }
    }
  }
}

CellLocation CellLocator::locate(const Eigen::Vector3d& X) const {
  CellLocation location;
  if (nodes_.empty()) return location;
  if (!findContaining(X, location)) findNearest(X, location);
  return location;
}

}  // namespace sculpt
