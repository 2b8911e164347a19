#include "mesh/validation.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <string>

#include "mesh/cell_geometry.h"
#include "mesh/topology.h"
#include "util/short_number.h"

namespace sculpt {
namespace {

using Kind = ValidationIssue::Kind;
using Severity = ValidationIssue::Severity;
using Element = ValidationIssue::Element;

// A cell whose volume is at most this fraction of its bounding box's is flat: rounding in the
// unit box is a few 1e-16, and a real cell this thin is useless to simulate anyway.
constexpr double kFlatVolume = 1e-12;

std::string edgeName(uint32_t a, uint32_t b) {
  return "edge (" + std::to_string(a) + ", " + std::to_string(b) + ")";
}

// Union-find root with path halving.
uint32_t findRoot(std::vector<uint32_t>& parent, uint32_t i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

// One directed edge of a cell's face: the undirected edge's key, +1 or -1 for its direction,
// and the face (its index within the cell).
struct CellEdgeUse {
  uint64_t key;
  int direction;
  uint32_t face;
  bool operator<(const CellEdgeUse& other) const {
    return key != other.key ? key < other.key : face < other.face;
  }
};

// A closed, consistently oriented cell must also bound a ball, as MacCracken-Joy cells do: its
// faces one connected surface (two disjoint tetrahedra listed as one cell are closed too) of
// Euler characteristic V - E + F = 2. Connected through edges, a closed orientable surface has
// V - E + F <= 2, with equality only for a sphere; a handle or a vertex where the surface
// pinches lowers it.
void checkCellIsBall(uint32_t c, uint32_t numFaces, const std::vector<CellEdgeUse>& uses,
                     std::vector<uint32_t>& parent, std::vector<ValidationIssue>& issues) {
  parent.resize(numFaces);
  std::iota(parent.begin(), parent.end(), 0u);
  std::vector<uint32_t> vertices;
  for (size_t i = 0; i + 1 < uses.size(); i += 2) {  // closed: each edge is a pair of uses
    parent[findRoot(parent, uses[i].face)] = findRoot(parent, uses[i + 1].face);
    vertices.push_back(uint32_t(uses[i].key >> 32));
    vertices.push_back(uint32_t(uses[i].key));
  }
  std::sort(vertices.begin(), vertices.end());
  vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
  uint32_t surfaces = 0;
  for (uint32_t f = 0; f < numFaces; ++f) surfaces += findRoot(parent, f) == f;
  const std::string cell = "cell " + std::to_string(c);
  if (surfaces > 1) {
    issues.push_back({Kind::CellNotBall, Severity::Error, Element::Cell, c,
                      cell + " is not one solid: its faces form " + std::to_string(surfaces) +
                          " separate closed surfaces (list each part as a cell of its own)"});
    return;
  }
  const auto euler = int64_t(vertices.size()) - int64_t(uses.size() / 2) + int64_t(numFaces);
  if (euler != 2)
    issues.push_back({Kind::CellNotBall, Severity::Error, Element::Cell, c,
                      cell + " is not a solid ball: its faces form a closed surface with " +
                          "vertices - edges + faces = " + std::to_string(euler) +
                          " (a ball's is 2; the cell has a hole through it or pinches at a "
                          "vertex)"});
}

// Within each cell every edge must be used exactly twice, once in each direction.
void checkCellsClosed(const CellComplex& mesh, std::vector<ValidationIssue>& issues) {
  std::vector<CellEdgeUse> uses;
  std::vector<uint32_t> parent;
  for (uint32_t c = 0; c < mesh.numCells(); ++c) {
    uses.clear();
    bool repeatedVertex = false;
    for (uint32_t j = 0; j < mesh.numFacesOfCell(c); ++j) {
      auto loop = mesh.cellFace(c, j);
      for (size_t i = 0; i < loop.size(); ++i) {
        const uint32_t a = loop[i], b = loop[(i + 1) % loop.size()];
        if (a == b) {
          repeatedVertex = true;
          continue;
        }
        const uint64_t key = (uint64_t(std::min(a, b)) << 32) | std::max(a, b);
        uses.push_back({key, a < b ? 1 : -1, j});
      }
    }
    std::sort(uses.begin(), uses.end());
    bool reportedOpen = false, reportedOrientation = false;
    for (size_t i = 0; i < uses.size();) {
      size_t j = i;
      int forward = 0, backward = 0;
      for (; j < uses.size() && uses[j].key == uses[i].key; ++j)
        (uses[j].direction > 0 ? forward : backward)++;
      const uint32_t a = uint32_t(uses[i].key >> 32), b = uint32_t(uses[i].key);
      if (forward + backward != 2 && !reportedOpen) {
        issues.push_back({Kind::CellNotClosed, Severity::Error, Element::Cell, c,
                          "cell " + std::to_string(c) + " is not closed: its faces use " +
                              edgeName(a, b) + " " + std::to_string(forward + backward) +
                              " time(s) instead of twice"});
        reportedOpen = true;
      } else if (forward + backward == 2 && forward != 1 && !reportedOrientation) {
        issues.push_back({Kind::InconsistentOrientation, Severity::Error, Element::Cell, c,
                          "cell " + std::to_string(c) + " has inconsistently oriented faces: " +
                              edgeName(a, b) + " runs the same way in both of its faces"});
        reportedOrientation = true;
      }
      i = j;
    }
    // A degenerate face (reported by the topology) would miscount the surface.
    if (!reportedOpen && !reportedOrientation && !repeatedVertex && !uses.empty())
      checkCellIsBall(c, mesh.numFacesOfCell(c), uses, parent, issues);
  }
}

// Each boundary edge has two boundary faces; each boundary vertex one fan of boundary faces.
void checkBoundaryManifold(const Topology& t, std::vector<ValidationIssue>& issues) {
  for (uint32_t e = 0; e < t.numEdges(); ++e) {
    const auto& ev = t.edgeVertices[e];
    if (t.edgeIsBoundary[e]) {
      uint32_t boundaryFaces = 0;
      for (uint32_t f : t.edgeFaces.row(e)) boundaryFaces += t.faceIsBoundary[f];
      if (boundaryFaces != 2)
        issues.push_back({Kind::NonManifoldBoundaryEdge, Severity::Error, Element::Edge, ev[0],
                          "boundary " + edgeName(ev[0], ev[1]) + " has " +
                              std::to_string(boundaryFaces) +
                              " boundary faces instead of 2 (non-manifold boundary)"});
    } else if (t.edgeFaces.rowSize(e) < 3) {
      issues.push_back({Kind::InteriorEdgeValenceTwo, Severity::Error, Element::Edge, ev[0],
                        "interior " + edgeName(ev[0], ev[1]) + " has only " +
                            std::to_string(t.edgeFaces.rowSize(e)) +
                            " faces around it (at least 3 are needed)"});
    }
  }
  // Boundary fans: boundary faces at v joined through boundary edges at v.
  std::vector<uint32_t> faces, parent;
  for (uint32_t v = 0; v < t.numVertices; ++v) {
    if (!t.vertexIsBoundary[v]) continue;
    faces.clear();
    for (uint32_t f : t.vertexFaces.row(v))
      if (t.faceIsBoundary[f]) faces.push_back(f);
    parent.resize(faces.size());
    std::iota(parent.begin(), parent.end(), 0u);
    for (size_t i = 0; i < faces.size(); ++i)
      for (size_t j = i + 1; j < faces.size(); ++j)
        for (uint32_t e : t.faceEdges.row(faces[i])) {
          const auto& ev = t.edgeVertices[e];
          if (ev[0] != v && ev[1] != v) continue;
          auto other = t.faceEdges.row(faces[j]);
          if (std::find(other.begin(), other.end(), e) != other.end())
            parent[findRoot(parent, uint32_t(i))] = findRoot(parent, uint32_t(j));
        }
    uint32_t fans = 0;
    for (size_t i = 0; i < faces.size(); ++i) fans += findRoot(parent, uint32_t(i)) == i;
    if (fans > 1)
      issues.push_back({Kind::NonManifoldBoundaryVertex, Severity::Error, Element::Vertex, v,
                        "vertex " + std::to_string(v) + " has " + std::to_string(fans) +
                            " separate fans of boundary faces (non-manifold boundary)"});
  }
}

void checkTags(const CellComplex& mesh, const Topology& t, std::vector<ValidationIssue>& issues) {
  for (const auto& crease : mesh.creases) {
    const int64_t e = t.findEdge(crease[0], crease[1]);
    if (e < 0)
      issues.push_back(
          {Kind::BadTag, Severity::Error, Element::Edge, crease[0],
           "crease " + edgeName(crease[0], crease[1]) + " is not an edge of the mesh"});
    else if (!t.edgeIsBoundary[size_t(e)])
      issues.push_back({Kind::BadTag, Severity::Error, Element::Edge, crease[0],
                        "crease " + edgeName(crease[0], crease[1]) +
                            " is an interior edge (creases must lie on the boundary)"});
  }
  for (uint32_t v : mesh.corners) {
    if (v >= t.numVertices)
      issues.push_back({Kind::BadTag, Severity::Error, Element::Vertex, v,
                        "corner vertex " + std::to_string(v) + " does not exist"});
    else if (!t.vertexIsBoundary[v])
      issues.push_back({Kind::BadTag, Severity::Error, Element::Vertex, v,
                        "corner vertex " + std::to_string(v) +
                            " is an interior vertex (corners must lie on the boundary)"});
  }
}

}  // namespace

std::vector<ValidationIssue> validate(const CellComplex& mesh) {
  std::vector<ValidationIssue> issues;
  const uint32_t numVertices = mesh.numVertices();
  if (numVertices == 0 || mesh.numCells() == 0) {
    issues.push_back({Kind::EmptyMesh, Severity::Error, Element::Mesh, 0,
                      "the mesh has no " + std::string(numVertices == 0 ? "vertices" : "cells")});
    return issues;
  }
  for (uint32_t v = 0; v < numVertices; ++v)
    if (!mesh.positions.row(v).allFinite())
      issues.push_back({Kind::NonFiniteCoordinate, Severity::Error, Element::Vertex, v,
                        "vertex " + std::to_string(v) + " has a non-finite coordinate"});

  bool indicesInRange = true;
  for (uint32_t c = 0; c < mesh.numCells(); ++c) {
    if (mesh.numFacesOfCell(c) == 0) {
      issues.push_back({Kind::CellNotClosed, Severity::Error, Element::Cell, c,
                        "cell " + std::to_string(c) + " has no faces"});
      indicesInRange = false;
    }
    for (uint32_t j = 0; j < mesh.numFacesOfCell(c); ++j)
      for (uint32_t v : mesh.cellFace(c, j))
        if (v >= numVertices) {
          issues.push_back({Kind::IndexOutOfRange, Severity::Error, Element::Cell, c,
                            "cell " + std::to_string(c) + ", face " + std::to_string(j) +
                                ": vertex index " + std::to_string(v) + " is out of range (" +
                                std::to_string(numVertices) + " vertices)"});
          indicesInRange = false;
          break;
        }
  }
  if (!indicesInRange) return issues;  // nothing further can be built safely

  const Topology t = buildTopology(mesh);
  for (const auto& p : t.problems) {
    const Kind kind = p.kind == TopologyProblem::Kind::DegenerateFace ? Kind::DegenerateFace
                      : p.kind == TopologyProblem::Kind::FaceSharedByMoreThanTwoCells
                          ? Kind::FaceSharedByMoreThanTwoCells
                          : Kind::InconsistentOrientation;
    issues.push_back({kind, Severity::Error, Element::Cell, p.cell, p.message});
  }
  checkCellsClosed(mesh, issues);
  checkBoundaryManifold(t, issues);
  checkTags(mesh, t, issues);

  // Volumes and corners, in each cell's own bounding box (mesh/cell_geometry.h) so that tiny,
  // huge and anisotropic cells are judged alike. Cells with a non-finite vertex were reported
  // above and have no meaningful volume; corners mean nothing in a cell whose faces were found
  // not to bound one solid.
  std::vector<bool> shapeReported(mesh.numCells(), false);
  for (const ValidationIssue& issue : issues)
    if (issue.element == Element::Cell) shapeReported[issue.index] = true;
  for (uint32_t c = 0; c < mesh.numCells(); ++c) {
    bool finite = true;
    for (uint32_t v : t.cellVertices.row(c)) finite &= mesh.positions.row(v).allFinite();
    if (!finite) continue;
    const std::string cell = "cell " + std::to_string(c);
    const double volume = relativeCellVolume(mesh, c);
    if (!(volume > kFlatVolume)) {
      issues.push_back({Kind::NonPositiveVolume, Severity::Error, Element::Cell, c,
                        volume < -kFlatVolume
                            ? cell + " has negative volume (" + shortNumber(volume) +
                                  " of its bounding box's); faces must wind counter-clockwise "
                                  "seen from outside"
                            : cell + " has zero volume: it is flat"});
    } else if (const auto corner =
                   shapeReported[c] ? std::nullopt : findInvertedCorner(mesh, c, kFlatVolume)) {
      issues.push_back({Kind::InvertedCorner, Severity::Error, Element::Cell, c,
                        cell + " is inverted at vertex " + std::to_string(corner->vertex) +
                            ": the cell's corner there has " +
                            (corner->volume < 0.0 ? "negative" : "zero") + " volume (" +
                            shortNumber(corner->volume) +
                            " of the cell's bounding box's), as when a corner is pushed through "
                            "the cell; its subdivision would be inside out"});
    }
  }

  for (uint32_t v = 0; v < numVertices; ++v)
    if (t.vertexCells.rowSize(v) == 0)
      issues.push_back({Kind::UnusedVertex, Severity::Warning, Element::Vertex, v,
                        "vertex " + std::to_string(v) + " is not used by any cell"});
  return issues;
}

std::string firstErrorMessage(const std::vector<ValidationIssue>& issues) {
  for (const ValidationIssue& issue : issues)
    if (issue.severity == Severity::Error) return issue.message;
  return {};
}

bool isValid(const std::vector<ValidationIssue>& issues) {
  return std::none_of(issues.begin(), issues.end(),
                      [](const ValidationIssue& i) { return i.severity == Severity::Error; });
}

}  // namespace sculpt
