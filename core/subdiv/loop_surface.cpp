#include "subdiv/loop_surface.h"

#include "subdiv/surface_refiner.h"

namespace sculpt {

SurfaceMesh loopRefine(const SurfaceMesh& surface, int levels, bool toLimit) {
  return refineSurface(surface, SurfaceScheme::Loop, levels, toLimit, SurfaceBoundary::EdgeOnly);
}

}  // namespace sculpt
