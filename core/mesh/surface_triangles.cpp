#include "mesh/surface_triangles.h"

#include <algorithm>

namespace sculpt {

std::vector<uint32_t> triangulate(const SurfaceMesh& surface) {
  std::vector<uint32_t> triangles;
  triangles.reserve(3 * (surface.faces.values.size() - std::min<size_t>(surface.faces.values.size(),
                                                                          2 * surface.numFaces())));
  for (uint32_t f = 0; f < surface.numFaces(); ++f) {
    const auto corners = surface.faces.row(f);
    for (size_t i = 2; i < corners.size(); ++i) {
      triangles.push_back(corners[0].position);
      triangles.push_back(corners[i - 1].position);
      triangles.push_back(corners[i].position);
    }
  }
  return triangles;
}

}  // namespace sculpt
