#include "mesh/volume_mesh.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include "util/short_number.h"

namespace sculpt {
namespace {

Eigen::Vector3d nodePosition(const VolumeMesh& mesh, uint32_t node) {
  return mesh.positions.row(node).transpose();
}

double determinant(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  return a.dot(b.cross(c));
}

std::string cellLabel(uint32_t cell, const char* kind) {
  return "cell " + std::to_string(cell) + " (" + kind + ")";
}

// Trilinear corner coordinates of the hexahedron (volume_mesh.h) and, per corner, its neighbours
// along s, t and u: the Jacobian at a corner is made of the three edges leaving it.
constexpr int kHexCornerCoordinates[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                             {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
constexpr int kHexNeighbour[8][3] = {{1, 3, 4}, {0, 2, 5}, {3, 1, 6}, {2, 0, 7},
                                     {5, 7, 0}, {4, 6, 1}, {7, 5, 2}, {6, 4, 3}};

double hexCornerJacobian(const VolumeMesh& mesh, std::span<const uint32_t> nodes, int corner) {
  const Eigen::Vector3d origin = nodePosition(mesh, nodes[static_cast<size_t>(corner)]);
  Eigen::Vector3d axis[3];
  for (int k = 0; k < 3; ++k) {
    // d/ds of the trilinear map at a corner is the edge towards the neighbour, negated on the
    // s = 1 side.
    const double sign = kHexCornerCoordinates[corner][k] == 0 ? 1.0 : -1.0;
    const int neighbour = kHexNeighbour[corner][k];
    axis[k] = sign * (nodePosition(mesh, nodes[static_cast<size_t>(neighbour)]) - origin);
  }
  return determinant(axis[0], axis[1], axis[2]);
}

std::string hexahedronProblem(const VolumeMesh& mesh, uint32_t cell, bool mirroredAllowed) {
  const std::span<const uint32_t> nodes = mesh.cells.row(cell);
  int negative = 0;
  int firstBad = -1;
  double firstBadValue = 0.0;
  for (int corner = 0; corner < 8; ++corner) {
    const double det = hexCornerJacobian(mesh, nodes, corner);
    if (det < 0.0) ++negative;
    if (!(det > 0.0) && firstBad < 0) {
      firstBad = corner;
      firstBadValue = det;
    }
  }
  if (firstBad < 0 || (mirroredAllowed && negative == 8)) return {};
  const std::string where = " at corner " + std::to_string(firstBad);
  const std::string value = "trilinear Jacobian determinant " + shortNumber(firstBadValue) + where;
  const std::string label = cellLabel(cell, "hexahedron") + ": ";
  if (negative == 8) return label + "inverted, " + value;
  if (firstBadValue == 0.0) return label + "degenerate, " + value;
  return label + "twisted or not convex, " + value;
}

// The split of a quadrilateral side (a, b, c, d in loop order): true for the diagonal a-c.
bool cutsThroughFirstDiagonal(uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
  return std::min(a, c) < std::min(b, d);
}

}  // namespace

void splitPyramid(VolumeMesh& mesh, const std::array<uint32_t, 5>& v) {
  // With the base counter-clockwise seen from the apex, (base triangle, apex) is positive.
  if (cutsThroughFirstDiagonal(v[0], v[1], v[2], v[3])) {
    mesh.addTetrahedron({v[0], v[1], v[2], v[4]});
    mesh.addTetrahedron({v[0], v[2], v[3], v[4]});
  } else {
    mesh.addTetrahedron({v[1], v[2], v[3], v[4]});
    mesh.addTetrahedron({v[1], v[3], v[0], v[4]});
  }
}

void splitWedge(VolumeMesh& mesh, const std::array<uint32_t, 6>& nodes) {
  // Dompierre, Labbé, Vallet, Camarero, "How to subdivide pyramids, prisms and hexahedra into
  // tetrahedra" (1999). The node order is Gmsh's: the triangle 0,1,2 is counter-clockwise seen
  // from 3,4,5, i.e. tetrahedron (0,1,2,3) is positive. (VTK lists its wedge the other way round;
  // its reader reorders.)
  //
  // Relabel by an orientation-preserving symmetry of the wedge so that the smallest node id is
  // at position 0; the two sides through it are then cut through it, and only the side opposite
  // (1,2,5,4) is left to choose. Every choice gives three positive tetrahedra.
  static constexpr int kRotation[6][6] = {{0, 1, 2, 3, 4, 5}, {1, 2, 0, 4, 5, 3},
                                          {2, 0, 1, 5, 3, 4}, {3, 5, 4, 0, 2, 1},
                                          {4, 3, 5, 1, 0, 2}, {5, 4, 3, 2, 1, 0}};
  const auto smallest = std::min_element(nodes.begin(), nodes.end()) - nodes.begin();
  std::array<uint32_t, 6> v{};
  for (size_t k = 0; k < 6; ++k) v[k] = nodes[static_cast<size_t>(kRotation[smallest][k])];

  if (cutsThroughFirstDiagonal(v[1], v[2], v[5], v[4])) {  // diagonal 1-5
    mesh.addTetrahedron({v[0], v[1], v[2], v[5]});
    mesh.addTetrahedron({v[0], v[1], v[5], v[4]});
  } else {  // diagonal 2-4
    mesh.addTetrahedron({v[0], v[1], v[2], v[4]});
    mesh.addTetrahedron({v[0], v[4], v[2], v[5]});
  }
  mesh.addTetrahedron({v[0], v[4], v[5], v[3]});
}

void addPositiveTetrahedron(VolumeMesh& mesh, const std::array<uint32_t, 4>& nodes) {
  mesh.addTetrahedron(nodes);
  if (tetrahedronSignedVolume(mesh, mesh.numCells() - 1) < 0.0) {
    auto& values = mesh.cells.values;
    std::swap(values[values.size() - 1], values[values.size() - 2]);
  }
}

double tetrahedronSignedVolume(const VolumeMesh& mesh, uint32_t cell) {
  const std::span<const uint32_t> v = mesh.cells.row(cell);
  const Eigen::Vector3d origin = nodePosition(mesh, v[0]);
  return determinant(nodePosition(mesh, v[1]) - origin, nodePosition(mesh, v[2]) - origin,
                     nodePosition(mesh, v[3]) - origin) /
         6.0;
}

std::string findVolumeMeshProblem(const VolumeMesh& mesh, CellShapeCheck shapes) {
  if (mesh.numNodes() == 0) return "the mesh has no nodes";
  if (mesh.numCells() == 0) return "the mesh has no cells";
  for (uint32_t node = 0; node < mesh.numNodes(); ++node) {
    if (!mesh.positions.row(node).allFinite()) {
      return "node " + std::to_string(node) + ": coordinate is not finite";
    }
  }
  for (uint32_t cell = 0; cell < mesh.numCells(); ++cell) {
    const std::span<const uint32_t> nodes = mesh.cells.row(cell);
    const std::string label = "cell " + std::to_string(cell);
    if (nodes.size() != 4 && nodes.size() != 8) {
      return label + ": has " + std::to_string(nodes.size()) + " nodes (expected 4 or 8)";
    }
    for (size_t i = 0; i < nodes.size(); ++i) {
      if (nodes[i] >= mesh.numNodes()) {
        return label + ": node id " + std::to_string(nodes[i]) + " out of range (the mesh has " +
               std::to_string(mesh.numNodes()) + " nodes)";
      }
      if (std::find(nodes.begin(), nodes.begin() + static_cast<std::ptrdiff_t>(i), nodes[i]) !=
          nodes.begin() + static_cast<std::ptrdiff_t>(i)) {
        return label + ": node " + std::to_string(nodes[i]) + " appears twice";
      }
    }
    if (shapes == CellShapeCheck::Skipped) continue;
    if (nodes.size() == 8) {
      if (std::string problem =
              hexahedronProblem(mesh, cell, shapes == CellShapeCheck::OrientationFree);
          !problem.empty())
        return problem;
      continue;
    }
    const double volume = tetrahedronSignedVolume(mesh, cell);
    if (shapes == CellShapeCheck::OrientationFree ? !(std::abs(volume) > 0.0) : !(volume > 0.0)) {
      return cellLabel(cell, "tetrahedron") + ": " + (volume < 0.0 ? "inverted" : "degenerate") +
             ", signed volume " + shortNumber(volume);
    }
  }
  return {};
}

uint32_t orientCellsPositively(VolumeMesh& mesh) {
  uint32_t reordered = 0;
  for (uint32_t cell = 0; cell < mesh.numCells(); ++cell) {
    uint32_t* nodes = mesh.cells.values.data() + mesh.cells.offsets[cell];
    const uint32_t count = mesh.cells.rowSize(cell);
    if (count == 4 && tetrahedronSignedVolume(mesh, cell) < 0.0) {
      std::swap(nodes[1], nodes[2]);
      ++reordered;
    } else if (count == 8) {
      const std::span<const uint32_t> row(nodes, 8);
      bool allNegative = true;
      for (int corner = 0; corner < 8 && allNegative; ++corner)
        allNegative = hexCornerJacobian(mesh, row, corner) < 0.0;
      if (allNegative) {
        std::swap_ranges(nodes, nodes + 4, nodes + 4);
        ++reordered;
      }
    }
  }
  return reordered;
}

std::string findFoldedFace(const VolumeMesh& mesh) {
  static constexpr int kTetFaces[4][3] = {{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}};
  static constexpr int kHexFaces[6][4] = {{0, 1, 2, 3}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                          {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  // Faces keyed by their sorted node ids (4 slots; a triangle's last is UINT32_MAX).
  using Key = std::array<uint32_t, 4>;
  std::vector<std::pair<Key, uint32_t>> faces;
  for (uint32_t cell = 0; cell < mesh.numCells(); ++cell) {
    const auto nodes = mesh.cells.row(cell);
    const bool tet = nodes.size() == 4;
    for (int f = 0; f < (tet ? 4 : 6); ++f) {
      Key key{UINT32_MAX, UINT32_MAX, UINT32_MAX, UINT32_MAX};
      for (int k = 0; k < (tet ? 3 : 4); ++k)
        key[static_cast<size_t>(k)] =
            nodes[static_cast<size_t>(tet ? kTetFaces[f][k] : kHexFaces[f][k])];
      std::sort(key.begin(), key.end());
      faces.emplace_back(key, cell);
    }
  }
  std::sort(faces.begin(), faces.end());
  const auto centroid = [&](std::span<const uint32_t> ids) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (uint32_t id : ids) sum += mesh.positions.row(id).transpose();
    return Eigen::Vector3d(sum / static_cast<double>(ids.size()));
  };
  for (size_t i = 0; i + 1 < faces.size(); ++i) {
    if (faces[i].first != faces[i + 1].first) continue;
    const Key& key = faces[i].first;
    const uint32_t a = faces[i].second, b = faces[i + 1].second;
    const size_t count = key[3] == UINT32_MAX ? 3 : 4;
    const std::span<const uint32_t> ids(key.data(), count);
    // The face's plane: least-squares normal through its centroid (the cross product of the
    // diagonals for a quadrilateral, of two edges for a triangle; the node order does not matter
    // for the side test below).
    const Eigen::Vector3d p0 = mesh.positions.row(ids[0]).transpose();
    const Eigen::Vector3d p1 = mesh.positions.row(ids[1]).transpose();
    const Eigen::Vector3d p2 = mesh.positions.row(ids[2]).transpose();
    const Eigen::Vector3d normal = (p1 - p0).cross(p2 - p0);
    const Eigen::Vector3d centre = centroid(ids);
    const double sideA = normal.dot(centroid(mesh.cells.row(a)) - centre);
    const double sideB = normal.dot(centroid(mesh.cells.row(b)) - centre);
    if (sideA * sideB > 0.0)
      return cellLabel(a, mesh.cells.rowSize(a) == 4 ? "tetrahedron" : "hexahedron") + " and " +
             cellLabel(b, mesh.cells.rowSize(b) == 4 ? "tetrahedron" : "hexahedron") +
             " lie on the same side of their shared face: the mesh is folded (inverted cells)";
  }
  return {};
}

}  // namespace sculpt
