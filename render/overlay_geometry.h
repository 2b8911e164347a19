#pragma once
// CPU builders of the overlay line lists drawn by LineRenderer: the ground grid, the axes, the
// edges of the simulation cells coloured by element type, and the control-mesh edges. Pure
// geometry, no GL (testable without a context) and no physics: element types come in as plain
// integers (the frozen values of fem/fem_mesh.h ElementType).

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "mesh/cell_complex.h"
#include "mesh/volume_mesh.h"

namespace sculpt::render {

/// Vertices with a colour each: consecutive pairs are segments (GL_LINES), or each vertex is a
/// point (GL_POINTS). Feed to LineRenderer::setLines / setPoints as (xyz, rgb).
struct LineList {
  std::vector<float> xyz;  ///< 3 floats per vertex
  std::vector<float> rgb;  ///< 3 floats per vertex, linear [0,1]

  uint32_t numVertices() const { return static_cast<uint32_t>(xyz.size() / 3); }
  uint32_t numSegments() const { return numVertices() / 2; }
  void addVertex(const glm::vec3& p, const glm::vec3& colour);
  void addSegment(const glm::vec3& a, const glm::vec3& b, const glm::vec3& colour);
  void append(const LineList& other);
};

/// Colour of a level-K cell by element type: 0 tricubic (regular) calm blue, 1 trilinear
/// (extraordinary) orange, 2 pyramid / centre-split magenta; other values grey.
glm::vec3 elementTypeColour(int type);

/// A square grid in the horizontal plane y = centre.y, centred on (centre.x, centre.z): lines
/// every `spacing` out to `halfExtent` on each side (the outermost at the largest multiple of
/// spacing that fits), 2 (2 n + 1) segments for n = floor(halfExtent / spacing). The two centre
/// lines are brighter. Throws std::invalid_argument for non-positive or non-finite sizes, or more
/// than 1000 lines a side.
LineList groundGrid(const glm::vec3& centre, float halfExtent, float spacing);

/// Three segments from `origin`, `length` long: x red, y green, z blue.
LineList axes(const glm::vec3& origin, float length);

/// A distinct edge of a cell mesh: its node ids (a < b) and a colour index.
struct CellEdge {
  uint32_t a = 0, b = 0;
  uint8_t colourIndex = 0;
};

/// Every distinct edge of the cells once (a hexahedron's 12 VTK edges, a tetrahedron's 6),
/// sorted by node ids. An edge takes the highest colour index among the cells that share it, so
/// that extraordinary and pyramid cells stand out among regular ones. Depends on topology only:
/// compute once per mesh, then call edgeLines() with each frame's node positions.
/// @param cellColourIndex  #cells indices (or all 0 when empty)
/// Throws std::invalid_argument on a size mismatch, a cell that is neither a tetrahedron nor a
/// hexahedron, or a node id out of range.
std::vector<CellEdge> distinctCellEdges(const VolumeMesh& mesh,
                                        std::span<const uint8_t> cellColourIndex);

/// Segments for `edges` at `nodes` (#nodes by 3, possibly deformed), coloured by
/// palette[colourIndex], or elementTypeColour(colourIndex) when the palette is empty.
/// Throws std::invalid_argument for a node id beyond `nodes` or an index outside the palette.
LineList edgeLines(std::span<const CellEdge> edges, const Points& nodes,
                   std::span<const glm::vec3> palette = {});

/// distinctCellEdges then edgeLines, in one call (O(cells log cells): for meshes that change or
/// small ones; cache distinctCellEdges for per-frame drawing of large meshes).
LineList cellEdges(const VolumeMesh& mesh, const Points& nodes,
                   std::span<const uint8_t> cellColourIndex,
                   std::span<const glm::vec3> palette = {});

/// The given edges (vertex pairs) between `positions` (xyz per vertex), all in one colour.
/// Throws std::invalid_argument for a vertex id out of range or a ragged position array.
LineList controlEdges(std::span<const std::array<uint32_t, 2>> edges,
                      std::span<const float> positions, const glm::vec3& colour);

}  // namespace sculpt::render
