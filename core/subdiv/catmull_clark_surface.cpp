#include "subdiv/catmull_clark_surface.h"

namespace sculpt {

SurfaceMesh catmullClarkRefine(const SurfaceMesh& surface, int levels, bool toLimit,
                               const SurfaceTags& tags) {
  return refineSurface(surface, SurfaceScheme::CatmullClark, levels, toLimit,
                       SurfaceBoundary::EdgeAndCorner, tags);
}

}  // namespace sculpt
