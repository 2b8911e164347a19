#pragma once
// A simulation cell mesh as other programs write it: node positions and cells that are
// tetrahedra (4 nodes) or trilinear hexahedra (8 nodes). Pyramids and wedges from files are split
// into tetrahedra on input (splitPyramid / splitWedge), so every consumer sees only these two.
//
// Node order conventions (the VTK and Gmsh ones):
//  - tetrahedron 0,1,2,3 with det[X1-X0, X2-X0, X3-X0] > 0 (positive volume);
//  - hexahedron 0,1,2,3 the bottom face counter-clockwise seen from above, 4..7 the top face above
//    them; trilinear local coordinates (s,t,u) of the corners are 0:(0,0,0) 1:(1,0,0) 2:(1,1,0)
//    3:(0,1,0) 4:(0,0,1) 5:(1,0,1) 6:(1,1,1) 7:(0,1,1).

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "mesh/cell_complex.h"
#include "util/compressed_rows.h"

namespace sculpt {

struct VolumeMesh {
  Points positions;                 ///< #N by 3 node positions (metres)
  CompressedRows<uint32_t> cells;   ///< node ids per cell; a row of 4 is a tet, of 8 a hexahedron

  uint32_t numNodes() const { return static_cast<uint32_t>(positions.rows()); }
  uint32_t numCells() const { return cells.numRows(); }
  bool isTetrahedron(uint32_t cell) const { return cells.rowSize(cell) == 4; }
  void addTetrahedron(const std::array<uint32_t, 4>& nodes) {
    cells.values.insert(cells.values.end(), nodes.begin(), nodes.end());
    cells.closeRow();
  }
  void addHexahedron(const std::array<uint32_t, 8>& nodes) {
    cells.values.insert(cells.values.end(), nodes.begin(), nodes.end());
    cells.closeRow();
  }
};

/// Appends a tetrahedron, swapping its last two nodes when needed so that it is positively
/// oriented (builders that know the four nodes but not their order).
void addPositiveTetrahedron(VolumeMesh& mesh, const std::array<uint32_t, 4>& nodes);

/// Appends the two tetrahedra of a pyramid (base 0,1,2,3 counter-clockwise seen from the apex 4,
/// as in VTK and Gmsh). The base is cut along the diagonal through its smallest node id, so that
/// a neighbour sharing the quadrilateral cuts it the same way.
void splitPyramid(VolumeMesh& mesh, const std::array<uint32_t, 5>& nodes);

/// Appends the three tetrahedra of a wedge: triangle 0,1,2 counter-clockwise seen from triangle
/// 3,4,5 above it (Gmsh order; a VTK wedge lists 0,1,2 the other way round and must be reordered
/// to 0,2,1,3,5,4). Each quadrilateral side is cut along the diagonal through its smallest id.
void splitWedge(VolumeMesh& mesh, const std::array<uint32_t, 6>& nodes);

/// Whether findVolumeMeshProblem checks cell shapes (inverted tetrahedra, folded hexahedra).
/// Rest meshes need them; a deformed simulation frame may legitimately contain inverted cells
/// and is checked for structure only (finite coordinates, ids in range, no repeated node).
/// OrientationFree checks shapes but accepts cells whose node order is mirrored as a whole (a
/// tetrahedron of negative volume, a hexahedron negative at all eight corners): conventions
/// differ between programs; orientCellsPositively() then makes them positive.
enum class CellShapeCheck { Required, Skipped, OrientationFree };

/// Reorders the nodes of every mirrored cell (see CellShapeCheck::OrientationFree) so that it is
/// positively oriented: a tetrahedron swaps nodes 1 and 2, a hexahedron its two quadrilaterals
/// 0-3 and 4-7. Returns how many cells it reordered. The cells' shapes are unchanged.
uint32_t orientCellsPositively(VolumeMesh& mesh);

/// For a positively oriented mesh: the first pair of cells that lie on the same side of a face
/// they share (the mesh folds over itself there, as when a node is pushed through its
/// neighbours), as a sentence naming both cells, or an empty string. Cells of a conforming mesh
/// lie on opposite sides of every shared face whatever their files' orientation convention was,
/// so this tells a folded mesh from one whose cells were only mirrored.
std::string findFoldedFace(const VolumeMesh& mesh);

/// Signed volume of tetrahedron `cell` (det/6); positive for a correctly oriented cell.
double tetrahedronSignedVolume(const VolumeMesh& mesh, uint32_t cell);

/// The first problem that makes the mesh unusable, or an empty string: no nodes or no cells, a
/// non-finite coordinate, a node id out of range, a repeated node in a cell, a tetrahedron with
/// non-positive volume (inverted or degenerate), a hexahedron whose trilinear Jacobian is not
/// positive at some corner. The message names the cell ("cell 12 (tetrahedron): inverted, signed
/// volume -1.3e-05").
std::string findVolumeMeshProblem(const VolumeMesh& mesh,
                                  CellShapeCheck shapes = CellShapeCheck::Required);

}  // namespace sculpt
