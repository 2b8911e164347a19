#pragma once
// Topology of a cell complex: unique faces and edges with full adjacency, boundary
// classification and sharp-feature tags. Built once per level from a CellComplex; positions
// are not needed (and not stored).

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "mesh/cell_complex.h"
#include "util/compressed_rows.h"

namespace sculpt {

inline constexpr int32_t kNoCell = -1;

/// A structural problem found while building the topology (reported by validation).
struct TopologyProblem {
  enum class Kind { DegenerateFace, FaceSharedByMoreThanTwoCells, InconsistentFaceOrientation };
  Kind kind;
  uint32_t cell;   ///< the cell whose face shows the problem
  uint32_t face;   ///< index of the face within that cell
  std::string message;
};

struct Topology {
  uint32_t numVertices = 0;

  /// #F face loops. The stored orientation is the outward one of faceCells[f][0].
  CompressedRows<uint32_t> faceVertices;
  /// #F rows parallel to faceVertices: edge i joins faceVertices[i] and faceVertices[i+1].
  CompressedRows<uint32_t> faceEdges;
  /// #F pairs: [0] sees the stored loop as outward, [1] is the other cell or kNoCell.
  std::vector<std::array<int32_t, 2>> faceCells;

  /// #E vertex pairs with [0] < [1].
  std::vector<std::array<uint32_t, 2>> edgeVertices;
  /// #E rows: faces around the edge in cyclic order. For a boundary edge the walk starts and
  /// ends on its boundary faces.
  CompressedRows<uint32_t> edgeFaces;
  /// #E rows: cells around the edge; cell i lies between edgeFaces[i] and edgeFaces[i+1].
  CompressedRows<uint32_t> edgeCells;

  /// #C rows: faces of the cell, and whether the cell sees the stored loop reversed.
  CompressedRows<uint32_t> cellFaces;
  std::vector<uint8_t> cellFaceReversed;  ///< parallel to cellFaces.values
  CompressedRows<uint32_t> cellVertices;  ///< #C rows of distinct vertices (first-seen order)
  CompressedRows<uint32_t> cellEdges;     ///< #C rows of distinct edges

  CompressedRows<uint32_t> vertexEdges;  ///< #V rows
  CompressedRows<uint32_t> vertexFaces;  ///< #V rows
  CompressedRows<uint32_t> vertexCells;  ///< #V rows

  std::vector<uint8_t> faceIsBoundary;    ///< #F: exactly one cell
  std::vector<uint8_t> edgeIsBoundary;    ///< #E: lies on a boundary face
  std::vector<uint8_t> vertexIsBoundary;  ///< #V: lies on a boundary face
  std::vector<uint8_t> edgeIsCrease;      ///< #E: tagged sharp (boundary edges only)
  std::vector<uint8_t> vertexIsCorner;    ///< #V: tagged corner (boundary vertices only)

  /// Problems met while building (empty for a well-formed complex).
  std::vector<TopologyProblem> problems;

  uint32_t numFaces() const { return faceVertices.numRows(); }
  uint32_t numEdges() const { return static_cast<uint32_t>(edgeVertices.size()); }
  uint32_t numCells() const { return cellFaces.numRows(); }

  /// Edge id joining a and b, or -1 when there is none.
  int64_t findEdge(uint32_t a, uint32_t b) const;
  /// Slot of face f within cell c's face list, or -1 when f is not a face of c.
  int faceSlot(uint32_t c, uint32_t f) const;
  /// Vertex loop of the face in slot `slot` of cell c, as c sees it from outside (the stored
  /// loop, reversed when c sees it the other way).
  std::vector<uint32_t> outwardLoop(uint32_t c, uint32_t slot) const;
  /// True when cell c is a hexahedron: 6 quadrilateral faces, 8 vertices, 12 edges.
  bool isHexahedron(uint32_t c) const;
};

/// Builds the topology. All vertex ids of `complex` must be < numVertices() (validate first).
/// Tags on edges that do not exist are ignored here; validation reports them.
Topology buildTopology(const CellComplex& complex);

}  // namespace sculpt
