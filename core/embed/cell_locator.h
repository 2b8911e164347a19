#pragma once
// Point location in a VolumeMesh: a bounding-volume hierarchy over the cells' rest bounding
// boxes, so a query visits O(log n) boxes instead of every cell.

#include <cstdint>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "mesh/volume_mesh.h"

namespace sculpt {

/// Where a point sits: its cell, local coordinates there, and whether it is inside that cell.
/// For points outside the mesh, `cell` is the nearest cell and `local` the extrapolated
/// coordinates; `distance` is then an upper bound of the distance to that cell (0 inside).
struct CellLocation {
  uint32_t cell = 0;
  Eigen::Vector3d local = Eigen::Vector3d::Zero();
  bool inside = false;
  double distance = 0.0;
  /// X - X(local): zero except far outside a distorted hexahedron, whose trilinear map may have
  /// no preimage there; `local` is then the nearest point of the cell and the deformer extends
  /// the map affinely by its gradient times this offset.
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();
};

class CellLocator {
 public:
  /// Builds the hierarchy (O(n log n)). The mesh must outlive the locator.
  explicit CellLocator(const VolumeMesh& mesh);

  /// Locates X. Inside tolerance: local coordinates may exceed the cell by 1e-9.
  CellLocation locate(const Eigen::Vector3d& X) const;

 private:
  struct Node {
    Eigen::AlignedBox3d box;
    uint32_t first = 0;   ///< leaf: first entry in order_
    uint32_t count = 0;   ///< leaf: number of cells; inner node: 0
    uint32_t left = 0, right = 0;  ///< inner node: children
  };
  uint32_t build(uint32_t begin, uint32_t end, std::vector<Eigen::Vector3d>& centres);
  bool findContaining(const Eigen::Vector3d& X, CellLocation& location) const;
  void findNearest(const Eigen::Vector3d& X, CellLocation& location) const;
  CellLocation evaluate(uint32_t cell, const Eigen::Vector3d& X) const;

  const VolumeMesh& mesh_;
  std::vector<Eigen::AlignedBox3d> cellBoxes_;
  std::vector<Eigen::Matrix3d> tetInverse_;  ///< V^-1 per tetrahedron (identity for hexahedra)
  std::vector<uint32_t> order_;  ///< cell ids, grouped by leaf
  std::vector<Node> nodes_;
};

}  // namespace sculpt
