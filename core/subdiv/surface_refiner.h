#pragma once
// Uniform refinement of a polygon surface through OpenSubdiv's Far API, shared by the Loop
// (loop_surface.h) and Catmull–Clark (catmull_clark_surface.h) front ends: topology descriptor,
// sharp tags, level-by-level primvar interpolation and, optionally, the limit positions.

#include <array>
#include <cstdint>
#include <vector>

#include "mesh/surface_mesh.h"

namespace sculpt {

enum class SurfaceScheme { Loop, CatmullClark };

/// Infinitely sharp features of a surface to refine (indices into its positions): crease edges
/// stay curves of the limit surface, corner vertices stay where they are.
struct SurfaceTags {
  std::vector<std::array<uint32_t, 2>> creases;
  std::vector<uint32_t> corners;
};

/// How the open boundary of a surface is refined (OpenSubdiv's Sdc vertex boundary rules).
enum class SurfaceBoundary {
  EdgeOnly,       ///< boundary edges are B-spline curves; corners are smoothed (Loop's default)
  EdgeAndCorner,  ///< as EdgeOnly, and boundary vertices on one face only stay put
};

/// `levels` uniform refinements of `surface` (positions and faces; normals and texture
/// coordinates are ignored) with `scheme`; the vertices of the last level are moved to the limit
/// surface when `toLimit` is set and levels > 0. The result has positions and faces only: the
/// refined faces of the scheme (triangles for Loop, quadrilaterals for Catmull–Clark after one
/// level). Throws std::invalid_argument for levels outside 0..8, a face with fewer than three
/// corners (or not three for Loop), an index out of range (faces or tags), or a topology
/// OpenSubdiv refuses.
SurfaceMesh refineSurface(const SurfaceMesh& surface, SurfaceScheme scheme, int levels,
                          bool toLimit, SurfaceBoundary boundary, const SurfaceTags& tags = {});

}  // namespace sculpt
