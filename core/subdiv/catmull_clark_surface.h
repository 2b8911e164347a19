#pragma once
// Catmull–Clark subdivision of a polygon surface (OpenSubdiv's Far API, SCHEME_CATMARK): the
// window refines the boundary surface of a control mesh to a render level and embeds it in the
// subdivided solid, whose boundary follows the same Catmull–Clark rules
// (docs/design/mj-subdivision.md).

#include "mesh/surface_mesh.h"
#include "subdiv/surface_refiner.h"

namespace sculpt {

/// `levels` uniform Catmull–Clark refinements of a polygon mesh (faces of 3 or more corners),
/// with the vertices of the last level moved to the limit surface when `toLimit` is set
/// (OpenSubdiv's limit masks). Open boundaries interpolate their edges and their corners (a
/// boundary vertex on one face stays put); `tags` adds infinitely sharp creases and corners (the
/// crease and corner tags of a control mesh). The result has positions and faces only; after one
/// level or more every face is a quadrilateral (triangulate() gives the renderer triangles).
/// Counts: a closed quad mesh with V, E, F gives V + E + F vertices and 4F faces per level.
/// Throws std::invalid_argument for levels outside 0..8, a face with fewer than three corners, an
/// index out of range or a topology OpenSubdiv refuses.
SurfaceMesh catmullClarkRefine(const SurfaceMesh& surface, int levels, bool toLimit,
                               const SurfaceTags& tags = {});

}  // namespace sculpt
