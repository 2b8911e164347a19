#include "mesh/cell_shape.h"

#include <algorithm>
#include <utility>
#include <vector>

namespace sculpt {
namespace {

// True when the all-quad cell has two poles of valence k > 3 and every other vertex has valence
// 3, with 2k faces and 2k + 2 vertices: the k-gonal trapezohedron.
bool isTrapezohedron(const Topology& topology, uint32_t c) {
  const auto faces = topology.cellFaces.row(c);
  const size_t numVertices = topology.cellVertices.rowSize(c);
  if (faces.size() % 2 != 0 || faces.size() < 8 || numVertices != faces.size() + 2) return false;
  // Valence of a vertex within the cell = number of the cell's faces around it. Cells are small,
  // so a linear scan over (vertex, count) pairs beats a map.
  std::vector<std::pair<uint32_t, int>> valence;
  for (uint32_t f : faces) {
    if (topology.faceVertices.rowSize(f) != 4) return false;
    for (uint32_t v : topology.faceVertices.row(f)) {
      auto it = std::find_if(valence.begin(), valence.end(),
                             [v](const auto& entry) { return entry.first == v; });
      if (it == valence.end()) {
        valence.emplace_back(v, 1);
      } else {
        ++it->second;
      }
    }
  }
  const int k = static_cast<int>(faces.size() / 2);
  int poles = 0;
  for (const auto& [v, count] : valence) {
    if (count == k) {
      ++poles;
    } else if (count != 3) {
      return false;
    }
  }
  return poles == 2;
}

}  // namespace

CellShape classifyCellShape(const Topology& topology, uint32_t c) {
  if (topology.isHexahedron(c)) return CellShape::Hexahedron;
  const auto faces = topology.cellFaces.row(c);
  const size_t numVertices = topology.cellVertices.rowSize(c);
  int triangles = 0;
  int quads = 0;
  for (uint32_t f : faces) {
    const uint32_t n = topology.faceVertices.rowSize(f);
    if (n == 3) {
      ++triangles;
    } else if (n == 4) {
      ++quads;
    }
  }
  const auto numFaces = static_cast<int>(faces.size());
  if (numFaces == 4 && triangles == 4 && numVertices == 4) return CellShape::Tetrahedron;
  if (numFaces == 5 && quads == 1 && triangles == 4 && numVertices == 5) return CellShape::Pyramid;
  if (numFaces == 5 && quads == 3 && triangles == 2 && numVertices == 6) return CellShape::Prism;
  if (quads == numFaces && isTrapezohedron(topology, c)) return CellShape::Trapezohedron;
  return CellShape::Polyhedron;
}

const char* cellShapeName(CellShape shape) {
  switch (shape) {
    case CellShape::Tetrahedron:
      return "tet";
    case CellShape::Pyramid:
      return "pyramid";
    case CellShape::Prism:
      return "prism";
    case CellShape::Hexahedron:
      return "hex";
    case CellShape::Trapezohedron:
      return "trapezohedron";
    case CellShape::Polyhedron:
      return "polyhedron";
  }
  return "polyhedron";
}

}  // namespace sculpt
