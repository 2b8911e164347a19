#include "scene/material_picker.h"

#include "embed/cell_coordinates.h"

namespace sculpt {
namespace {

VolumeMesh withPositions(const VolumeMesh& mesh, const Points& nodes) {
  VolumeMesh deformed;
  deformed.cells = mesh.cells;
  deformed.positions = nodes;
  return deformed;
}

}  // namespace

MaterialPicker::MaterialPicker(const VolumeMesh& rest, const Points& nodes)
    : rest_(rest), deformed_(withPositions(rest, nodes)), locator_(deformed_) {}

std::optional<Eigen::Vector3d> MaterialPicker::restPoint(const Eigen::Vector3d& world,
                                                         double tolerance) const {
  if (!world.allFinite() || deformed_.numCells() == 0) return std::nullopt;
  const CellLocation at = locator_.locate(world);
  if (!at.inside && !(at.distance <= tolerance)) return std::nullopt;
  return cellPoint(rest_, at.cell, at.local);
}

}  // namespace sculpt
