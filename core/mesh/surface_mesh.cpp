#include "mesh/surface_mesh.h"

namespace sculpt {

std::vector<uint32_t> normalAnchors(const SurfaceMesh& surface) {
  std::vector<uint32_t> anchors(static_cast<size_t>(surface.normals.rows()),
                                SurfaceCorner::kNoIndex);
  // Corners are stored face after face, so the first hit is the first corner in face order.
  for (const SurfaceCorner& corner : surface.faces.values) {
    if (corner.normal >= anchors.size()) continue;  // kNoIndex, or an index the file lacked
    if (anchors[corner.normal] == SurfaceCorner::kNoIndex) anchors[corner.normal] = corner.position;
  }
  return anchors;
}

}  // namespace sculpt
