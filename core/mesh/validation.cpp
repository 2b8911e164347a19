#include "mesh/validation.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <string>

#include <Eigen/Geometry>

#include "mesh/topology.h"

namespace sculpt {
namespace {

using Kind = ValidationIssue::Kind;
using Severity = ValidationIssue::Severity;
using Element = ValidationIssue::Element;

std::string edgeName(uint32_t a, uint32_t b) {
  return "edge (" + std::to_string(a) + ", " + std::to_string(b) + ")";
}

// Union-find root with path halving.
uint32_t findRoot(std::vector<uint32_t>& parent, uint32_t i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

// Within each cell every edge must be used exactly twice, once in each direction.
void checkCellsClosed(const CellComplex& mesh, std::vector<ValidationIssue>& issues) {
  std::vector<std::pair<uint64_t, int>> directed;
  for (uint32_t c = 0; c < mesh.numCells(); ++c) {
    directed.clear();
    for (uint32_t j = 0; j < mesh.numFacesOfCell(c); ++j) {
      auto loop = mesh.cellFace(c, j);
      for (size_t i = 0; i < loop.size(); ++i) {
        const uint32_t a = loop[i], b = loop[(i + 1) % loop.size()];
        if (a == b) continue;
        const uint64_t key = (uint64_t(std::min(a, b)) << 32) | std::max(a, b);
        directed.push_back({key, a < b ? 1 : -1});
      }
    }
    std::sort(directed.begin(), directed.end());
    bool reportedOpen = false, reportedOrientation = false;
    for (size_t i = 0; i < directed.size();) {
      size_t j = i;
      int forward = 0, backward = 0;
      for (; j < directed.size() && directed[j].first == directed[i].first; ++j)
        (directed[j].second > 0 ? forward : backward)++;
      const uint32_t a = uint32_t(directed[i].first >> 32), b = uint32_t(directed[i].first);
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
      issues.push_back({Kind::BadTag, Severity::Error, Element::Edge, crease[0],
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

double cellVolume(const CellComplex& mesh, uint32_t c) {
  // Cell centroid = plain vertex average of the loops' vertices (repeats do not matter here:
  // the divergence-theorem sum is exact for any reference point of a closed surface).
  Eigen::Vector3d reference = Eigen::Vector3d::Zero();
  uint32_t count = 0;
  for (uint32_t j = 0; j < mesh.numFacesOfCell(c); ++j)
    for (uint32_t v : mesh.cellFace(c, j)) {
      reference += mesh.positions.row(v).transpose();
      ++count;
    }
  if (count == 0) return 0.0;
  reference /= count;
  double volume = 0.0;
  for (uint32_t j = 0; j < mesh.numFacesOfCell(c); ++j) {
    auto loop = mesh.cellFace(c, j);
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    for (uint32_t v : loop) centre += mesh.positions.row(v).transpose();
    centre /= double(loop.size());
    for (size_t i = 0; i < loop.size(); ++i) {
      const Eigen::Vector3d a = mesh.positions.row(loop[i]).transpose() - reference;
      const Eigen::Vector3d b = mesh.positions.row(loop[(i + 1) % loop.size()]).transpose() - reference;
      volume += (centre - reference).dot(a.cross(b)) / 6.0;
    }
  }
  return volume;
}

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

  // Volumes, relative to the size of each cell so that tiny but valid cells pass. Cells with a
  // non-finite vertex were reported above and have no meaningful volume.
  for (uint32_t c = 0; c < mesh.numCells(); ++c) {
    bool finite = true;
    for (uint32_t v : t.cellVertices.row(c)) finite &= mesh.positions.row(v).allFinite();
    if (!finite) continue;
    Eigen::Vector3d lo = Eigen::Vector3d::Constant(INFINITY), hi = -lo;
    for (uint32_t v : t.cellVertices.row(c)) {
      lo = lo.cwiseMin(mesh.positions.row(v).transpose());
      hi = hi.cwiseMax(mesh.positions.row(v).transpose());
    }
    const double size = (hi - lo).norm();
    const double volume = cellVolume(mesh, c);
    if (!(volume > 1e-12 * size * size * size))
      issues.push_back({Kind::NonPositiveVolume, Severity::Error, Element::Cell, c,
                        "cell " + std::to_string(c) + " has " +
                            (std::abs(volume) <= 1e-12 * size * size * size ? "zero" : "negative") +
                            " volume (" + std::to_string(volume) +
                            "); faces must wind counter-clockwise seen from outside"});
  }

  for (uint32_t v = 0; v < numVertices; ++v)
    if (t.vertexCells.rowSize(v) == 0)
      issues.push_back({Kind::UnusedVertex, Severity::Warning, Element::Vertex, v,
                        "vertex " + std::to_string(v) + " is not used by any cell"});
  return issues;
}

bool isValid(const std::vector<ValidationIssue>& issues) {
  return std::none_of(issues.begin(), issues.end(),
                      [](const ValidationIssue& i) { return i.severity == Severity::Error; });
}

}  // namespace sculpt
