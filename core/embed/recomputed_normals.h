#pragma once
// Normals of a deformed surface recomputed from its faces, for deformations without a useful
// gradient (the attribute method) or when the analytic normals are not wanted.

#include <span>

#include "mesh/surface_mesh.h"

namespace sculpt {

/// Area-weighted vertex normals of the deformed faces, one per normal of `surface`.
///
/// Normal j is the normalised sum of the area vectors (Newell's method, so polygons are allowed)
/// of the faces that have a corner at its anchor position (normalAnchors) using normal j. With
/// one normal per position this is the usual area-weighted vertex normal at the anchor; where a
/// file splits normals (creases, flat shading), each keeps to the faces that use it, so sharp
/// edges stay sharp. The orientation follows the file: when the same sum over the rest positions
/// points against the rest normal, the result is flipped. A normal without anchor, or whose faces
/// have no area (collapsed), keeps its rest value.
/// @param[in] surface   the surface at rest: faces, #VN by 3 rest normals
/// @param[in] deformed  #V by 3 deformed positions (same order as surface.positions)
/// @param[in] anchors   #VN anchor positions, normalAnchors(surface)
/// @return #VN by 3 normals (unit length where recomputed)
Points recomputedNormals(const SurfaceMesh& surface, const Points& deformed,
                         std::span<const uint32_t> anchors);

/// One area-weighted normal per position of `surface` (whatever normals it had are ignored):
/// the smooth normals of a surface read without normals, such as a Loop-refined mesh.
Points vertexNormals(const SurfaceMesh& surface);

}  // namespace sculpt
