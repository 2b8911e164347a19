#include "mesh/cell_geometry.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace sculpt {
namespace {

// Divergence theorem over the cell's faces, each fanned from its centroid, against a reference
// point: exact for any reference point of a closed surface, so the vertex average of the loops
// (repeats included) serves.
template <typename Position>
double divergenceVolume(const CellComplex& mesh, uint32_t c, Position position) {
  Eigen::Vector3d reference = Eigen::Vector3d::Zero();
  uint32_t count = 0;
  for (uint32_t j = 0; j < mesh.numFacesOfCell(c); ++j)
    for (uint32_t v : mesh.cellFace(c, j)) {
      reference += position(v);
      ++count;
    }
  if (count == 0) return 0.0;
  reference /= count;
  double volume = 0.0;
  for (uint32_t j = 0; j < mesh.numFacesOfCell(c); ++j) {
    auto loop = mesh.cellFace(c, j);
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    for (uint32_t v : loop) centre += position(v);
    centre /= double(loop.size());
    for (size_t i = 0; i < loop.size(); ++i) {
      const Eigen::Vector3d a = position(loop[i]) - reference;
      const Eigen::Vector3d b = position(loop[(i + 1) % loop.size()]) - reference;
      volume += (centre - reference).dot(a.cross(b)) / 6.0;
    }
  }
  return volume;
}

// Cell c's vertices in its bounding box, each axis mapped onto [0, 1]. The coordinates are first
// scaled by a power of two (exactly) so that the largest magnitude on each axis lies in [1, 2):
// the extents then cannot overflow, and differences of nearby coordinates stay exact.
class UnitBoxCell {
 public:
  UnitBoxCell(const CellComplex& mesh, uint32_t c) {
    for (uint32_t j = 0; j < mesh.numFacesOfCell(c); ++j)
      for (uint32_t v : mesh.cellFace(c, j)) ids_.push_back(v);
    std::sort(ids_.begin(), ids_.end());
    ids_.erase(std::unique(ids_.begin(), ids_.end()), ids_.end());
    points_.resize(ids_.size());
    for (size_t i = 0; i < ids_.size(); ++i) {
      points_[i] = mesh.positions.row(ids_[i]).transpose();
      finite_ &= points_[i].allFinite();
    }
    if (!finite_ || ids_.empty()) return;
    for (Eigen::Index k = 0; k < 3; ++k) {
      double largest = 0.0;
      for (const Eigen::Vector3d& p : points_) largest = std::max(largest, std::abs(p[k]));
      const int exponent = largest > 0.0 ? std::ilogb(largest) : 0;
      double lo = std::numeric_limits<double>::infinity(), hi = -lo;
      for (Eigen::Vector3d& p : points_) {
        p[k] = std::ldexp(p[k], -exponent);
        lo = std::min(lo, p[k]);
        hi = std::max(hi, p[k]);
      }
      const double extent = hi - lo;
      flat_ |= !(extent > 0.0);
      if (flat_) return;
      for (Eigen::Vector3d& p : points_) p[k] = (p[k] - lo) / extent;
    }
    centre_ = Eigen::Vector3d::Zero();
    for (const Eigen::Vector3d& p : points_) centre_ += p;
    centre_ /= static_cast<double>(points_.size());
  }

  bool finite() const { return finite_; }
  /// Some axis has zero extent (or the cell has no vertices).
  bool flat() const { return flat_ || ids_.empty(); }
  size_t numVertices() const { return ids_.size(); }
  /// The cell's i-th vertex (by increasing id) and the place of vertex v among them.
  uint32_t vertex(size_t i) const { return ids_[i]; }
  size_t index(uint32_t v) const {
    return static_cast<size_t>(std::lower_bound(ids_.begin(), ids_.end(), v) - ids_.begin());
  }
  /// Vertex v (a vertex of the cell) in the unit box.
  const Eigen::Vector3d& at(uint32_t v) const { return points_[index(v)]; }
  /// The average of the cell's vertices, inside a convex cell.
  const Eigen::Vector3d& centre() const { return centre_; }

 private:
  std::vector<uint32_t> ids_;  // sorted, distinct
  std::vector<Eigen::Vector3d> points_;
  Eigen::Vector3d centre_ = Eigen::Vector3d::Zero();
  bool finite_ = true;
  bool flat_ = false;
};

}  // namespace

double cellVolume(const CellComplex& mesh, uint32_t c) {
  return divergenceVolume(
      mesh, c, [&](uint32_t v) -> Eigen::Vector3d { return mesh.positions.row(v).transpose(); });
}

double relativeCellVolume(const CellComplex& mesh, uint32_t c) {
  const UnitBoxCell box(mesh, c);
  if (!box.finite()) return std::numeric_limits<double>::quiet_NaN();
  if (box.flat()) return 0.0;
  return divergenceVolume(mesh, c, [&](uint32_t v) { return box.at(v); });
}

std::optional<InvertedCorner> findInvertedCorner(const CellComplex& mesh, uint32_t c,
                                                 double tolerance) {
  const UnitBoxCell box(mesh, c);
  if (!box.finite() || box.flat()) return std::nullopt;  // volume checks report these
  // Each face's part of a corner, the quad (v, midpoint to the next vertex, face centre,
  // midpoint from the previous one), taken against the cell's centre.
  std::vector<double> cornerVolume(box.numVertices(), 0.0);
  const Eigen::Vector3d& centre = box.centre();
  for (uint32_t j = 0; j < mesh.numFacesOfCell(c); ++j) {
    const auto loop = mesh.cellFace(c, j);
    Eigen::Vector3d faceCentre = Eigen::Vector3d::Zero();
    for (uint32_t v : loop) faceCentre += box.at(v);
    faceCentre = faceCentre / double(loop.size()) - centre;
    for (size_t i = 0; i < loop.size(); ++i) {
      const Eigen::Vector3d at = box.at(loop[i]) - centre;
      const Eigen::Vector3d before =
          0.5 * (box.at(loop[(i + loop.size() - 1) % loop.size()]) + box.at(loop[i])) - centre;
      const Eigen::Vector3d after =
          0.5 * (box.at(loop[i]) + box.at(loop[(i + 1) % loop.size()])) - centre;
      cornerVolume[box.index(loop[i])] +=
          (at.dot(after.cross(faceCentre)) + at.dot(faceCentre.cross(before))) / 6.0;
    }
  }
  const auto worst = std::min_element(cornerVolume.begin(), cornerVolume.end());
  if (*worst > tolerance) return std::nullopt;
  return InvertedCorner{box.vertex(static_cast<size_t>(worst - cornerVolume.begin())), *worst};
}

}  // namespace sculpt
