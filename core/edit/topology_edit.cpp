#include "edit/topology_edit.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <numeric>
#include <sstream>
#include <stdexcept>

#include "edit/edit_support.h"
#include "mesh/validation.h"

namespace sculpt {
namespace edit {

std::string firstError(const std::vector<ValidationIssue>& issues) {
  for (const ValidationIssue& issue : issues)
    if (issue.severity == ValidationIssue::Severity::Error) return issue.message;
  return {};
}

void reject(const std::string& sentence) { throw std::invalid_argument(sentence); }

Topology checkedTopology(const CellComplex& mesh) {
  if (const std::string error = firstError(validate(mesh)); !error.empty())
    reject("the mesh is invalid before the edit: " + error + ".");
  return buildTopology(mesh);
}

std::string number(double value) {
  std::ostringstream text;
  text.precision(6);
  text << value;
  return text.str();
}

std::string faceName(FaceRef face) {
  return "face " + std::to_string(face.face) + " of cell " + std::to_string(face.cell);
}

uint32_t boundaryFaceId(const CellComplex& mesh, const Topology& topology, FaceRef face) {
  if (face.cell >= mesh.numCells())
    reject("cell " + std::to_string(face.cell) + " is out of range (the mesh has " +
           std::to_string(mesh.numCells()) + " cells).");
  if (face.face >= mesh.numFacesOfCell(face.cell))
    reject(faceName(face) + " is out of range (the cell has " +
           std::to_string(mesh.numFacesOfCell(face.cell)) + " faces).");
  const uint32_t f = topology.cellFaces.row(face.cell)[face.face];
  if (!topology.faceIsBoundary[f]) reject(faceName(face) + " is not on the boundary.");
  return f;
}

std::vector<uint32_t> cellSelection(const CellComplex& mesh, std::span<const uint32_t> cells) {
  if (cells.empty()) reject("no cells are selected.");
  std::vector<uint32_t> sorted(cells.begin(), cells.end());
  std::sort(sorted.begin(), sorted.end());
  sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
  if (sorted.back() >= mesh.numCells())
    reject("cell " + std::to_string(sorted.back()) + " is out of range (the mesh has " +
           std::to_string(mesh.numCells()) + " cells).");
  return sorted;
}

Eigen::Vector3d position(const CellComplex& mesh, uint32_t v) {
  return mesh.positions.row(static_cast<Eigen::Index>(v)).transpose();
}

std::vector<int64_t> identityVertexMap(uint32_t numVertices) {
  std::vector<int64_t> map(numVertices);
  std::iota(map.begin(), map.end(), int64_t{0});
  return map;
}

Eigen::Vector3d areaVector(const CellComplex& mesh, std::span<const uint32_t> loop) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (size_t i = 0; i < loop.size(); ++i)
    sum += position(mesh, loop[i]).cross(position(mesh, loop[(i + 1) % loop.size()]));
  return 0.5 * sum;
}

TopologyEdit keepCells(const CellComplex& mesh, const std::vector<uint8_t>& keep,
                       const std::vector<uint32_t>& representative, const Points& positions) {
  // Number the representatives that kept cells use, in increasing old id.
  const uint32_t numOld = mesh.numVertices();
  std::vector<uint8_t> used(numOld, 0);
  for (uint32_t c = 0; c < mesh.numCells(); ++c)
    if (keep[c])
      for (uint32_t j = 0; j < mesh.numFacesOfCell(c); ++j)
        for (uint32_t v : mesh.cellFace(c, j)) used[representative[v]] = 1;
  std::vector<int64_t> newId(numOld, -1);
  int64_t count = 0;
  for (uint32_t v = 0; v < numOld; ++v)
    if (used[v]) newId[v] = count++;

  TopologyEdit edit;
  edit.newVertexOfOld.resize(numOld);
  for (uint32_t v = 0; v < numOld; ++v) edit.newVertexOfOld[v] = newId[representative[v]];
  CellComplex& out = edit.mesh;
  out.positions.resize(count, 3);
  for (uint32_t v = 0; v < numOld; ++v)
    if (used[v]) out.positions.row(newId[v]) = positions.row(v);
  std::vector<uint32_t> loop;
  for (uint32_t c = 0; c < mesh.numCells(); ++c) {
    if (!keep[c]) continue;
    for (uint32_t j = 0; j < mesh.numFacesOfCell(c); ++j) {
      loop.clear();
      for (uint32_t v : mesh.cellFace(c, j))
        loop.push_back(static_cast<uint32_t>(edit.newVertexOfOld[v]));
      out.addLoop(loop);
    }
    out.finishCell();
  }
  // Tags follow their vertices; finishEdit drops the ones that left the boundary.
  for (const auto& [a, b] : mesh.creases) {
    const int64_t na = edit.newVertexOfOld[a], nb = edit.newVertexOfOld[b];
    if (na >= 0 && nb >= 0 && na != nb)
      out.creases.push_back({static_cast<uint32_t>(na), static_cast<uint32_t>(nb)});
  }
  for (uint32_t v : mesh.corners)
    if (edit.newVertexOfOld[v] >= 0)
      out.corners.push_back(static_cast<uint32_t>(edit.newVertexOfOld[v]));
  return edit;
}

TopologyEdit finishEdit(TopologyEdit edit, std::string label) {
  CellComplex& mesh = edit.mesh;
  // Normalise, then keep only boundary tags (the edit may have buried some).
  for (auto& crease : mesh.creases)
    if (crease[0] > crease[1]) std::swap(crease[0], crease[1]);
  std::sort(mesh.creases.begin(), mesh.creases.end());
  mesh.creases.erase(std::unique(mesh.creases.begin(), mesh.creases.end()), mesh.creases.end());
  std::sort(mesh.corners.begin(), mesh.corners.end());
  mesh.corners.erase(std::unique(mesh.corners.begin(), mesh.corners.end()), mesh.corners.end());
  const Topology topology = buildTopology(mesh);
  std::erase_if(mesh.creases, [&](const std::array<uint32_t, 2>& crease) {
    const int64_t e = topology.findEdge(crease[0], crease[1]);
    return e < 0 || !topology.edgeIsBoundary[static_cast<size_t>(e)];
  });
  std::erase_if(mesh.corners, [&](uint32_t v) { return !topology.vertexIsBoundary[v]; });

  if (const std::string error = firstError(validate(mesh)); !error.empty())
    reject("the edited mesh would be invalid: " + error + ".");
  edit.label = std::move(label);
  return edit;
}

}  // namespace edit

std::vector<FaceRef> boundaryFaces(const CellComplex& mesh) {
  const Topology topology = buildTopology(mesh);
  std::vector<FaceRef> faces;
  for (uint32_t c = 0; c < mesh.numCells(); ++c) {
    const auto row = topology.cellFaces.row(c);
    for (uint32_t j = 0; j < row.size(); ++j)
      if (topology.faceIsBoundary[row[j]]) faces.push_back({c, j});
  }
  return faces;
}

}  // namespace sculpt
