#pragma once
// Whether a triangle surface bounds its solid with every triangle facing out. Seen from outside,
// the triangles of such a surface that face away from the eye are hidden behind those that face
// it, so a renderer may skip them (back-face culling) and draw the same picture.

#include <cstdint>
#include <span>

#include "mesh/cell_complex.h"

namespace sculpt {

/// True when the triangles (3 position indices each) form closed shells, every edge shared by
/// exactly two triangles that run along it in opposite directions, and each shell winds
/// counter-clockwise seen from outside (it encloses a positive volume). Positions that coincide
/// exactly count as one vertex, so that a surface split along texture seams still closes. False
/// for an empty surface, an open one, a degenerate triangle, an edge shared by three or more
/// triangles, and a shell that faces in (as the inner wall of a hollow solid does).
bool isClosedOutwardSurface(const Points& positions, std::span<const uint32_t> triangles);

}  // namespace sculpt
