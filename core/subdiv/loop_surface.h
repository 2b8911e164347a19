#pragma once
// Loop subdivision of a triangulated surface (OpenSubdiv's Far API): the window refines an
// imported surface such as the bunny to a render resolution before embedding it.

#include "mesh/surface_mesh.h"

namespace sculpt {

/// `levels` uniform Loop refinements of a triangle mesh (every face must be a triangle), with the
/// vertices of the last level moved to the limit surface when `toLimit` is set (OpenSubdiv's
/// limit stencils; a smoother render surface for the same triangle count). The result has
/// positions and triangles only (no normals or texture coordinates). Boundaries are kept
/// (OpenSubdiv's default boundary rules). Throws std::invalid_argument for a non-triangle face,
/// levels outside 0..8 or a topology OpenSubdiv refuses (e.g. an edge shared by three faces is
/// refined as non-manifold; OpenSubdiv accepts it).
SurfaceMesh loopRefine(const SurfaceMesh& surface, int levels, bool toLimit = false);

}  // namespace sculpt
