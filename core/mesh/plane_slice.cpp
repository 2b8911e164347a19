#include "mesh/plane_slice.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>

#include <Eigen/Geometry>

namespace sculpt {
namespace {

/// The Kuhn split of a VTK hexahedron: the 6 monotone paths from corner 0 to corner 6, one axis
/// at a time. Every face is cut along the diagonal through its corner nearest to corner 0.
constexpr std::array<std::array<int, 4>, 6> kHexTetrahedra = {
    {{0, 1, 2, 6}, {0, 1, 5, 6}, {0, 3, 2, 6}, {0, 3, 7, 6}, {0, 4, 5, 6}, {0, 4, 7, 6}}};

/// Accumulates the slice polygon by polygon. Cut points are keyed by their edge (or by the node
/// when the node lies on the plane) so that neighbouring tetrahedra share them.
class SliceBuilder {
 public:
  SliceBuilder(const Points& nodes, const Eigen::Vector3d& normal,
               const std::vector<double>& height, std::span<const double> nodeValues)
      : nodes_(nodes), normal_(normal), height_(height), nodeValues_(nodeValues) {}

  /// Starts a cell. With per-cell values, its vertices are its own (the value jumps across faces).
  void beginCell(bool ownVertices, double cellValue) {
    if (ownVertices) vertexOfKey_.clear();
    cellValue_ = cellValue;
  }

  /// Marching tetrahedra: nodes strictly above the plane against the others.
  void cutTetrahedron(const std::array<uint32_t, 4>& tet) {
    std::array<uint32_t, 4> above{}, below{};
    int numAbove = 0, numBelow = 0;
    for (uint32_t n : tet) (height_[n] > 0.0 ? above[numAbove++] : below[numBelow++]) = n;
    if (numAbove == 1) {
      addTriangle(cut(above[0], below[0]), cut(above[0], below[1]), cut(above[0], below[2]));
    } else if (numAbove == 3) {
      addTriangle(cut(above[0], below[0]), cut(above[1], below[0]), cut(above[2], below[0]));
    } else if (numAbove == 2) {
      // The four cut edges in cyclic order around the quadrilateral.
      const uint32_t ac = cut(above[0], below[0]), ad = cut(above[0], below[1]);
      const uint32_t bd = cut(above[1], below[1]), bc = cut(above[1], below[0]);
      addTriangle(ac, ad, bd);
      addTriangle(ac, bd, bc);
    }
  }

  PlaneSlice finish() const {
    PlaneSlice slice;
    slice.positions.reserve(3 * points_.size());
    for (const Eigen::Vector3d& p : points_)
      for (int d = 0; d < 3; ++d) slice.positions.push_back(static_cast<float>(p[d]));
    slice.values.reserve(values_.size());
    for (double v : values_) slice.values.push_back(static_cast<float>(v));
    slice.triangles = triangles_;
    return slice;
  }

 private:
  /// The vertex where the plane crosses edge (above, below).
  uint32_t cut(uint32_t above, uint32_t below) {
    const bool onPlane = height_[below] == 0.0;
    const uint64_t key = onPlane
                             ? (uint64_t{below} << 32 | below)
                             : (uint64_t{std::min(above, below)} << 32 | std::max(above, below));
    const auto [it, inserted] =
        vertexOfKey_.try_emplace(key, static_cast<uint32_t>(points_.size()));
    if (!inserted) return it->second;
    const Eigen::Vector3d a = nodes_.row(above).transpose(), b = nodes_.row(below).transpose();
    const double t = onPlane ? 1.0 : height_[above] / (height_[above] - height_[below]);
    points_.push_back(onPlane ? b : Eigen::Vector3d(a + t * (b - a)));
    values_.push_back(
        nodeValues_.empty()
            ? cellValue_
            : (onPlane ? nodeValues_[below]
                       : nodeValues_[above] + t * (nodeValues_[below] - nodeValues_[above])));
    return it->second;
  }

  /// Adds a triangle wound counter-clockwise about the normal; drops degenerate ones (a cell edge
  /// or corner touching the plane).
  void addTriangle(uint32_t a, uint32_t b, uint32_t c) {
    const double turn = (points_[b] - points_[a]).cross(points_[c] - points_[a]).dot(normal_);
    if (turn == 0.0) return;
    if (turn < 0.0) std::swap(b, c);
    triangles_.insert(triangles_.end(), {a, b, c});
  }

  const Points& nodes_;
  const Eigen::Vector3d normal_;
  const std::vector<double>& height_;
  std::span<const double> nodeValues_;
  double cellValue_ = 0.0;
  std::unordered_map<uint64_t, uint32_t> vertexOfKey_;
  std::vector<Eigen::Vector3d> points_;
  std::vector<double> values_;
  std::vector<uint32_t> triangles_;
};

void checkInputs(const VolumeMesh& mesh, const Points& nodes, const Eigen::Vector3d& normal,
                 double offset, std::span<const double> nodeValues,
                 std::span<const double> cellValues) {
  if (!normal.allFinite() || normal.squaredNorm() == 0.0)
    throw std::invalid_argument("slicePlane: the plane normal must be finite and non-zero");
  if (!std::isfinite(offset))
    throw std::invalid_argument("slicePlane: the plane offset must be finite");
  if (nodes.rows() != static_cast<Eigen::Index>(mesh.numNodes()))
    throw std::invalid_argument("slicePlane: " + std::to_string(nodes.rows()) +
                                " node positions for a mesh of " + std::to_string(mesh.numNodes()) +
                                " nodes");
  if (!nodes.allFinite())
    throw std::invalid_argument("slicePlane: a node position is not finite");
  if (!nodeValues.empty() && !cellValues.empty())
    throw std::invalid_argument("slicePlane: give node values or cell values, not both");
  if (!nodeValues.empty() && nodeValues.size() != mesh.numNodes())
    throw std::invalid_argument("slicePlane: " + std::to_string(nodeValues.size()) +
                                " node values for " + std::to_string(mesh.numNodes()) + " nodes");
  if (!cellValues.empty() && cellValues.size() != mesh.numCells())
    throw std::invalid_argument("slicePlane: " + std::to_string(cellValues.size()) +
                                " cell values for " + std::to_string(mesh.numCells()) + " cells");
}

}  // namespace

PlaneSlice slicePlane(const VolumeMesh& mesh, const Points& nodes, const Eigen::Vector3d& normal,
                      double offset, std::span<const double> nodeValues,
                      std::span<const double> cellValues) {
  checkInputs(mesh, nodes, normal, offset, nodeValues, cellValues);
  // Signed height of every node above the plane (in units of |normal|).
  std::vector<double> height(mesh.numNodes());
  for (uint32_t n = 0; n < mesh.numNodes(); ++n)
    height[n] = nodes.row(n).dot(normal.transpose()) - offset;

  SliceBuilder builder(nodes, normal, height, nodeValues);
  for (uint32_t c = 0; c < mesh.numCells(); ++c) {
    const auto cell = mesh.cells.row(c);
    if (cell.size() != 4 && cell.size() != 8)
      throw std::invalid_argument("slicePlane: cell " + std::to_string(c) + " has " +
                                  std::to_string(cell.size()) +
                                  " nodes; only tetrahedra (4) and hexahedra (8) can be sliced");
    // Skip cells entirely on one side.
    bool anyAbove = false, anyBelow = false;
    for (uint32_t n : cell) {
      if (n >= mesh.numNodes())
        throw std::invalid_argument("slicePlane: cell " + std::to_string(c) + " names node " +
                                    std::to_string(n) + " of " + std::to_string(mesh.numNodes()));
      (height[n] > 0.0 ? anyAbove : anyBelow) = true;
    }
    if (!anyAbove || !anyBelow) continue;

    builder.beginCell(!cellValues.empty(), cellValues.empty() ? 0.0 : cellValues[c]);
    if (cell.size() == 4) {
      builder.cutTetrahedron({cell[0], cell[1], cell[2], cell[3]});
    } else {
      for (const auto& t : kHexTetrahedra)
        builder.cutTetrahedron({cell[t[0]], cell[t[1]], cell[t[2]], cell[t[3]]});
    }
  }
  return builder.finish();
}

}  // namespace sculpt
