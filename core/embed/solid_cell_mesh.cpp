#include "embed/solid_cell_mesh.h"

#include <algorithm>

#include "mesh/hexahedron.h"

namespace sculpt {

Points SolidCellMesh::nodePositions(const Points& vertexPositions) const {
  Points nodes(numVertices + centreVertices.numRows(), 3);
  nodes.topRows(numVertices) = vertexPositions.topRows(numVertices);
  for (uint32_t k = 0; k < centreVertices.numRows(); ++k) {
    Eigen::RowVector3d sum = Eigen::RowVector3d::Zero();
    for (uint32_t v : centreVertices.row(k)) sum += vertexPositions.row(v);
    nodes.row(numVertices + k) = sum / static_cast<double>(centreVertices.rowSize(k));
  }
  return nodes;
}

SolidCellMesh solidCellMesh(const CellComplex& complex, const Topology& topology) {
  SolidCellMesh solid;
  solid.numVertices = complex.numVertices();
  // Centre nodes first (positions are needed to orient the tetrahedra).
  std::vector<uint32_t> splitCells;
  for (uint32_t c = 0; c < complex.numCells(); ++c) {
    if (vtkHexahedronOrder(topology, c)) continue;
    splitCells.push_back(c);
    std::vector<uint32_t> vertices;
    for (uint32_t j = 0; j < complex.numFacesOfCell(c); ++j)
      for (uint32_t v : complex.cellFace(c, j)) vertices.push_back(v);
    std::sort(vertices.begin(), vertices.end());
    vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
    solid.centreVertices.values.insert(solid.centreVertices.values.end(), vertices.begin(),
                                       vertices.end());
    solid.centreVertices.closeRow();
  }
  solid.mesh.positions = solid.nodePositions(complex.positions);

  uint32_t nextSplit = 0;
  for (uint32_t c = 0; c < complex.numCells(); ++c) {
    if (const auto hex = vtkHexahedronOrder(topology, c)) {
      solid.mesh.addHexahedron(*hex);
      continue;
    }
    const uint32_t centre = solid.numVertices + nextSplit++;
    for (uint32_t j = 0; j < complex.numFacesOfCell(c); ++j) {
      const auto face = complex.cellFace(c, j);
      // Fan from the smallest vertex id: a neighbour split the same way cuts the face alike.
      const size_t n = face.size();
      const size_t first =
          static_cast<size_t>(std::min_element(face.begin(), face.end()) - face.begin());
      for (size_t k = 1; k + 1 < n; ++k)
        addPositiveTetrahedron(
            solid.mesh, {face[first], face[(first + k) % n], face[(first + k + 1) % n], centre});
    }
  }
  return solid;
}

}  // namespace sculpt
