#pragma once
// The triangles a renderer draws for a polygon surface.

#include <cstdint>
#include <vector>

#include "mesh/surface_mesh.h"

namespace sculpt {

/// Position indices of the surface's faces as triangles, 3 per triangle, each polygon fanned
/// from its first corner (a quadrilateral (a, b, c, d) gives (a, b, c) and (a, c, d)), keeping
/// the faces' winding and order. Faces with fewer than three corners add nothing.
std::vector<uint32_t> triangulate(const SurfaceMesh& surface);

}  // namespace sculpt
