#pragma once
// The solid's surface as the simulation has deformed it, queried for the point nearest a
// position in space and whether that position is inside. A stylus touching the surface uses it to
// find where it is in contact and which way the surface pushes it out; the hit also gives the
// rest point under it, so a material brush can paint where the stylus touches.
//
// Two surfaces: the solid's own boundary (the finest level's boundary faces as triangles of
// lattice nodes, sim/load_forms.h boundaryTriangles), or a surface embedded in the solid (the
// detail surface of a caged scene, which is what the user sees and expects to touch): each of its
// vertices moves as the material point at its rest position. Inside means a winding number above
// one half (the solid angles of the triangles, summed, over 4 pi), which holds near concave edges
// and for either orientation, where the side of the nearest face's plane does not.
//
// A query is a scan over the triangles (O(triangles)): a few thousand per step for the models of
// an interactive session, cheaper than one step's element pass.

#include <array>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "fem/fem_model.h"
#include "sim/material_point.h"

namespace sculpt {

struct BoundaryHit {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();  ///< nearest surface point (deformed, m)
  /// Unit vector out of the solid at the hit: from the position to the point when inside (the way
  /// a stylus is pushed out), the outward face normal otherwise.
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  /// Distance to the point, negative inside the solid (the depth of a stylus in it).
  double signedDistance = 0.0;
  uint32_t triangle = 0;
  Eigen::Vector3d barycentric = Eigen::Vector3d::Zero();  ///< of `point` in the triangle
};

/// The point of triangle (a, b, c) nearest p, as barycentric coordinates (they sum to 1).
Eigen::Vector3d closestPointOnTriangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                       const Eigen::Vector3d& b, const Eigen::Vector3d& c);

class DeformedBoundary {
 public:
  /// The solid's own boundary.
  explicit DeformedBoundary(const FemModel& model);
  /// A surface (rest vertices #V by 3, three indices per triangle) embedded in the solid.
  DeformedBoundary(const FemModel& model, const MaterialPointLocator& locator,
                   const Points& restVertices, const std::vector<uint32_t>& triangles);
  size_t numTriangles() const { return triangles_.size(); }
  /// The surface point nearest `position` for node positions `nodes`; nullopt without a
  /// surface (or for a non-finite position).
  std::optional<BoundaryHit> nearest(const Points& nodes, const Eigen::Vector3d& position) const;
  /// The rest position of a hit's point (the same barycentric point of the rest triangle).
  Eigen::Vector3d restPoint(const BoundaryHit& hit) const;

 private:
  void deformedVertices(const Points& nodes, Points& out) const;

  std::vector<std::array<uint32_t, 3>> triangles_;
  Points rest_;  ///< rest vertex positions
  /// Embedded surfaces: each vertex's node weights (empty for the solid's own boundary, whose
  /// vertices are lattice nodes).
  std::vector<std::vector<std::pair<uint32_t, double>>> weights_;
};

}  // namespace sculpt
