#pragma once
// Points of the material: an element of the FemMesh and local coordinates in it. A material
// point moves with the solid, so loads and constraints can be attached anywhere (the paper only
// attaches them to Gauss points; docs/design/local-frame-fem.md "Loads and constraints").
//
// The position of a point is a fixed linear combination of the nodes (the element's shape
// functions at its local coordinates) and therefore of the control points (composed with the
// node stencils): x(point) = sum_i w_i p_i.

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "fem/fem_mesh.h"

namespace sculpt {

/// A point of the solid: an element and local coordinates in it ([0,1]^3; for a pyramid element
/// the degenerate-hexahedron coordinates, w = 1 being the apex).
struct MaterialPoint {
  uint32_t element = 0;
  Eigen::Vector3d local{0.5, 0.5, 0.5};
};

/// Weights of the point onto nodes. Tricubic: the 64 B-spline products B_a(u) B_b(v) B_g(w) in
/// the order a*16 + b*4 + g of FemMesh::tricubicNodes. Linear: the 8 trilinear weights in VTK
/// order, repeated ids (a pyramid's apex) merged into their first occurrence. The weights sum to
/// 1. Throws std::invalid_argument when the element is out of range.
std::vector<std::pair<uint32_t, double>> nodeWeights(const FemMesh& mesh,
                                                     const MaterialPoint& point);

/// The node weights composed with the node stencils onto control points (sorted by control id,
/// merged): x(point) = sum w_i p_i.
std::vector<std::pair<uint32_t, double>> controlWeights(const FemMesh& mesh,
                                                        const MaterialPoint& point);

/// Position of the point for node positions `nodes` (#nodes by 3).
Eigen::Vector3d materialPointPosition(const FemMesh& mesh, const Points& nodes,
                                      const MaterialPoint& point);

/// Position and parametric Jacobian d x / d local of element `element` at `local` for node
/// positions `nodes`.
Eigen::Vector3d elementMap(const FemMesh& mesh, const Points& nodes, uint32_t element,
                           const Eigen::Vector3d& local, Eigen::Matrix3d* jacobian = nullptr);

/// Finds material points from rest positions. Construction stores one bounding box per element
/// (the box of its nodes: both element kinds lie in the convex hull of their nodes) and a
/// uniform grid over them; keep one when locating many points.
class MaterialPointLocator {
 public:
  explicit MaterialPointLocator(const FemMesh& mesh);

  /// The material point at rest position X. Candidates are the elements whose box contains X
  /// (from the grid), nearest box centre first; each is inverted by Newton's method and the
  /// first whose inverse lies in [0,1]^3 is returned. A point in no element (outside the solid, or
  /// in a gap between non-conforming elements) snaps to the nearest element, with local coordinates
  /// of the nearest point of that element (a Gauss-Newton search confined to [0,1]^3), found by
  /// branch and bound over the boxes sorted by distance. nullopt only for an empty mesh or a
  /// non-finite X.
  std::optional<MaterialPoint> locate(const Eigen::Vector3d& restPosition) const;

  /// Distance from the rest position to the returned point's rest position is below this (in
  /// metres) when the point counts as inside an element.
  double insideTolerance() const { return insideTolerance_; }

 private:
  struct Box {
    Eigen::Vector3d lo, hi;
  };
  // Newton inversion of element e's map at X; true when it converges inside [0,1]^3.
  bool invert(uint32_t e, const Eigen::Vector3d& X, Eigen::Vector3d& local) const;
  // Closest local coordinates in [0,1]^3 of element e to X; returns the squared distance.
  double closestLocal(uint32_t e, const Eigen::Vector3d& X, Eigen::Vector3d& local) const;
  double boxDistanceSquared(uint32_t e, const Eigen::Vector3d& X) const;

  const FemMesh& mesh_;
  std::vector<Box> boxes_;
  Eigen::Vector3d gridLo_ = Eigen::Vector3d::Zero(), gridCell_ = Eigen::Vector3d::Ones();
  Eigen::Vector3i gridSize_ = Eigen::Vector3i::Zero();
  std::vector<uint32_t> gridBegin_;     // #grid cells + 1
  std::vector<uint32_t> gridElements_;  // elements whose box overlaps each grid cell
  double insideTolerance_ = 0.0;
};

/// One-off form of MaterialPointLocator::locate (builds the boxes and grid, O(#elements)).
std::optional<MaterialPoint> locateMaterialPoint(const FemMesh& mesh,
                                                 const Eigen::Vector3d& restPosition);

}  // namespace sculpt
