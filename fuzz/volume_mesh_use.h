#pragma once
// What the deform command does with a volume mesh it has read (app/cli/deform_command.cpp):
// the volume readers are fuzzed with the most permissive check that still validates the
// cells' shapes, and an accepted mesh then goes through the same re-orientation and fold check.

#include "mesh/volume_mesh.h"

namespace sculpt::fuzz {

inline constexpr CellShapeCheck kVolumeShapeCheck = CellShapeCheck::OrientationFree;

inline void useVolumeMesh(VolumeMesh mesh) {
  orientCellsPositively(mesh);
  (void)findFoldedFace(mesh);
}

}  // namespace sculpt::fuzz
