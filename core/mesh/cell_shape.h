#pragma once
// Combinatorial shape of a cell (tetrahedron, pyramid, ...), for reports and file export. The
// shape is read from the face structure only; positions play no part.

#include <cstdint>

#include "mesh/topology.h"

namespace sculpt {

/// Frozen values: written to VTK files as the `shape` cell field.
enum class CellShape : uint8_t {
  Tetrahedron = 0,    ///< 4 triangles
  Pyramid = 1,        ///< 1 quadrilateral and 4 triangles
  Prism = 2,          ///< 2 triangles and 3 quadrilaterals over 6 vertices
  Hexahedron = 3,     ///< 6 quadrilaterals, 8 vertices, 12 edges
  Trapezohedron = 4,  ///< 2k quads around two poles of valence k > 3 (MJ, pyramid apices)
  Polyhedron = 5,     ///< anything else
};

inline constexpr int kNumCellShapes = 6;

/// Classifies cell c of the topology.
CellShape classifyCellShape(const Topology& topology, uint32_t c);

/// Short lower-case name: "tet", "pyramid", "prism", "hex", "trapezohedron", "polyhedron".
const char* cellShapeName(CellShape shape);

}  // namespace sculpt
