#pragma once
// The solid's boundary as the simulation has deformed it: the finest level's boundary faces as
// triangles of lattice nodes (sim/load_forms.h boundaryTriangles), queried for the point nearest
// a position in space. A stylus touching the surface uses it to find where it is in contact and
// which way the surface faces there; the hit also gives the rest point under it, so a material
// brush can paint where the stylus touches.
//
// A query is a scan over the triangles (O(boundary faces)): a few thousand per step for the
// models of an interactive session, cheaper than one step's element pass.

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "fem/fem_model.h"

namespace sculpt {

struct BoundaryHit {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();   ///< nearest boundary point (deformed, m)
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();  ///< outward unit normal of its triangle
  /// (position - point) . normal: negative inside the solid (the depth of a stylus in it).
  double signedDistance = 0.0;
  uint32_t triangle = 0;
  Eigen::Vector3d barycentric = Eigen::Vector3d::Zero();  ///< of `point` in the triangle
};

/// The point of triangle (a, b, c) nearest p, as barycentric coordinates (they sum to 1).
Eigen::Vector3d closestPointOnTriangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                       const Eigen::Vector3d& b, const Eigen::Vector3d& c);

class DeformedBoundary {
 public:
  explicit DeformedBoundary(const FemModel& model);
  size_t numTriangles() const { return triangles_.size(); }
  /// The boundary point nearest `position` for node positions `nodes`; nullopt without a
  /// boundary (or for a non-finite position).
  std::optional<BoundaryHit> nearest(const Points& nodes, const Eigen::Vector3d& position) const;
  /// The rest position of a hit's point (the same barycentric point of the rest triangle).
  Eigen::Vector3d restPoint(const BoundaryHit& hit) const;

 private:
  const FemModel& model_;
  std::vector<std::array<uint32_t, 3>> triangles_;
};

}  // namespace sculpt
