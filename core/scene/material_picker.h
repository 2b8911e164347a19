#pragma once
// Picking on the CPU: which material sits at a world position of the deformed solid. The
// level-K cells of a scene, deformed by a frame's node positions, get a cell locator
// (embed/cell_locator.h); a point found in a deformed cell at local coordinates xi is the rest
// point of the same cell at xi. The cells are trilinear (or linear on tetrahedra) in the node
// positions; the drawn surface is Phong-deformed within them, so a point on it lies in the cell
// that holds it within a fraction of a cell, and the nearest cell answers there.
//
// Building is O(cells log cells) (a few milliseconds for a few thousand cells); build one per
// frame that is picked in, not per query.

#include <optional>

#include <Eigen/Core>

#include "embed/cell_locator.h"
#include "mesh/volume_mesh.h"

namespace sculpt {

class MaterialPicker {
 public:
  /// `rest`: the cells at rest; `nodes`: their node positions now (#rest nodes by 3). `rest`
  /// must outlive the picker.
  MaterialPicker(const VolumeMesh& rest, const Points& nodes);
  MaterialPicker(const MaterialPicker&) = delete;
  MaterialPicker& operator=(const MaterialPicker&) = delete;

  /// The rest position of the material at `world`; nullopt when it lies farther than
  /// `tolerance` (m) outside every deformed cell.
  std::optional<Eigen::Vector3d> restPoint(const Eigen::Vector3d& world, double tolerance) const;

 private:
  const VolumeMesh& rest_;
  VolumeMesh deformed_;
  CellLocator locator_;
};

}  // namespace sculpt
