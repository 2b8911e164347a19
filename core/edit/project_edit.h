#pragma once
// Applying a topology edit (topology_edit.h) to a Project: the control mesh is replaced and
// everything that refers to its vertices or its volume is carried over.

#include "edit/topology_edit.h"
#include "project/project.h"

namespace sculpt {

/// Replaces project.controlMesh by edit.mesh (tags included), maps the pins through
/// edit.newVertexOfOld (removed vertices lose their pin, new vertices are unpinned), and, when
/// materials are painted, resamples them by position onto the Gauss points of the new mesh at
/// the samples' level (level <= 0: trilinear elements on the control cells): each new Gauss
/// point takes the material of the nearest old sample (resampleMaterials).
/// Throws std::invalid_argument (one sentence) when the edit does not fit the project (its
/// vertex map has the wrong size or points outside the new mesh), the new mesh is invalid, or no
/// elements can be built for the materials; the project is then unchanged.
void applyTopologyEdit(Project& project, const TopologyEdit& edit);

}  // namespace sculpt
