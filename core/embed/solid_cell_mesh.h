#pragma once
// The subdivided solid as a cell mesh for embedding: the level-K cells of a MacCracken–Joy
// refinement, so that the application's surface follows the solid with the same deformer that
// serves tetrahedral meshes from other programs.
//
// Most level-K cells are hexahedra. The cells around the apex of a pyramid (and any general
// polyhedron of a control mesh) are not; like the FEM (docs/fem.md) they get a virtual centre
// node, the mean of their vertices, and one tetrahedron per face triangle around it (quadrilaterals
// cut through their smallest vertex id). Such faces are shared with a bilinear hexahedron face, so
// the interpolant is continuous up to the small bilinear-vs-two-triangles gap there.

#include <cstdint>
#include <vector>

#include "mesh/cell_complex.h"
#include "mesh/topology.h"
#include "mesh/volume_mesh.h"
#include "util/compressed_rows.h"

namespace sculpt {

struct SolidCellMesh {
  VolumeMesh mesh;  ///< nodes: the complex's vertices, then one centre node per split cell
  CompressedRows<uint32_t> centreVertices;  ///< per centre node, the vertices it averages
  uint32_t numVertices = 0;                 ///< vertices of the complex (the first nodes)

  /// Node positions for vertex positions of the complex (#vertices by 3): the vertices followed by
  /// the centre nodes. This is what a frame passes to the deformer.
  Points nodePositions(const Points& vertexPositions) const;
};

/// The complex's cells as a cell mesh. Hexahedra in VTK order, tetrahedra positively oriented,
/// other cells split around a centre node.
SolidCellMesh solidCellMesh(const CellComplex& complex, const Topology& topology);

}  // namespace sculpt
