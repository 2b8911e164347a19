#include "io/tetgen_mesh.h"

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "io/input_file.h"
#include "io/text_scanner.h"
#include "io/volume_mesh_file.h"

namespace sculpt {
namespace {

struct TetGenNodes {
  Points positions;
  int64_t firstNumber = 0;  ///< 0 or 1: the number of the first node
};

/// A header number after the first; like TetGen, missing trailing ones take their defaults.
uint64_t headerCountOr(TextScanner& scanner, uint64_t missing, const char* what) {
  return scanner.atLineEnd() ? missing : scanner.count(what);
}

// "<#points> [dimension 3] [#attributes] [boundary markers 0|1]", then per point
// "<number> <x> <y> <z> [attributes] [boundary marker]".
TetGenNodes readNodes(std::string_view text, std::string_view sourceName) {
  TextScanner scanner(text, sourceName, '#');
  const uint64_t numPoints = scanner.count("the number of points");
  const uint64_t dimension = headerCountOr(scanner, 3, "the dimension");
  const uint64_t numAttributes = headerCountOr(scanner, 0, "the number of attributes");
  const uint64_t numMarkers = headerCountOr(scanner, 0, "the boundary marker flag (0 or 1)");
  if (dimension != 3) scanner.fail("dimension " + std::to_string(dimension) + " (must be 3)");
  if (numMarkers > 1) scanner.fail("the boundary marker flag must be 0 or 1");
  if (numPoints == 0) scanner.fail("no points (a .node file that goes with a .poly has none)");
  scanner.checkCount(numAttributes, 2, "attributes per point");
  const uint64_t valuesPerPoint = 4 + numAttributes + numMarkers;
  scanner.checkCount(numPoints, 2 * valuesPerPoint, "points");

  TetGenNodes nodes;
  nodes.positions.resize(static_cast<Eigen::Index>(numPoints), 3);
  for (uint64_t i = 0; i < numPoints; ++i) {
    int64_t number = 0;
    if (!scanner.readInteger(number))
      scanner.failExpected("the number of point " + std::to_string(i));
    if (i == 0) {
      if (number != 0 && number != 1)
        scanner.fail("the first point is numbered " + std::to_string(number) + " (must be 0 or 1)");
      nodes.firstNumber = number;
    } else if (number != nodes.firstNumber + static_cast<int64_t>(i)) {
      scanner.fail("point " + std::to_string(number) + " where point " +
                   std::to_string(nodes.firstNumber + static_cast<int64_t>(i)) +
                   " should be (numbers must be consecutive)");
    }
    const auto row = static_cast<Eigen::Index>(i);
    for (Eigen::Index k = 0; k < 3; ++k) {
      if (!scanner.readReal(nodes.positions(row, k))) {
        scanner.failExpected("a coordinate of point " + std::to_string(number));
      }
      // Here, where the line is known: the mesh check would blame the .ele file it reads last.
      if (!std::isfinite(nodes.positions(row, k))) {
        scanner.fail("coordinate " + std::to_string(k) + " of point " + std::to_string(number) +
                     " is not finite");
      }
    }
    for (uint64_t k = 0; k < numAttributes + numMarkers; ++k) {
      double ignored = 0.0;
      if (!scanner.readReal(ignored)) {
        scanner.failExpected("an attribute or boundary marker of point " + std::to_string(number));
      }
    }
  }
  return nodes;
}

// "<#tetrahedra> [nodes per tetrahedron 4|10] [#attributes]", then per tetrahedron
// "<number> <node> <node> <node> <node> [6 more nodes] [attributes]".
VolumeMesh readElements(std::string_view text, std::string_view sourceName, TetGenNodes nodes,
                        CellShapeCheck shapes) {
  TextScanner scanner(text, sourceName, '#');
  const uint64_t numTetrahedra = scanner.count("the number of tetrahedra");
  const uint64_t nodesPerTetrahedron =
      headerCountOr(scanner, 4, "the number of nodes per tetrahedron");
  const uint64_t numAttributes = headerCountOr(scanner, 0, "the number of region attributes");
  if (nodesPerTetrahedron != 4 && nodesPerTetrahedron != 10) {
    scanner.fail(std::to_string(nodesPerTetrahedron) + " nodes per tetrahedron (must be 4 or 10)");
  }
  scanner.checkCount(numAttributes, 2, "attributes per tetrahedron");
  scanner.checkCount(numTetrahedra, 2 * (1 + nodesPerTetrahedron + numAttributes), "tetrahedra");

  VolumeMesh mesh;
  mesh.positions = std::move(nodes.positions);
  const int64_t numNodes = static_cast<int64_t>(mesh.numNodes());
  mesh.cells.values.reserve(4 * numTetrahedra);
  mesh.cells.offsets.reserve(numTetrahedra + 1);
  std::vector<uint64_t> numberOfCell;
  numberOfCell.reserve(numTetrahedra);
  for (uint64_t t = 0; t < numTetrahedra; ++t) {
    int64_t number = 0;
    if (!scanner.readInteger(number)) {
      scanner.failExpected("the number of tetrahedron " + std::to_string(t) + " (of " +
                           std::to_string(numTetrahedra) + ")");
    }
    std::array<uint32_t, 4> corners{};
    for (uint64_t k = 0; k < nodesPerTetrahedron; ++k) {
      int64_t node = 0;
      if (!scanner.readInteger(node)) {
        scanner.failExpected("a node of tetrahedron " + std::to_string(number));
      }
      const int64_t id = node - nodes.firstNumber;
      if (id < 0 || id >= numNodes) {
        scanner.fail("tetrahedron " + std::to_string(number) + ": node id " + std::to_string(node) +
                     " out of range (the mesh has " + std::to_string(numNodes) +
                     " nodes numbered from " + std::to_string(nodes.firstNumber) + ")");
      }
      if (k < 4) corners[k] = static_cast<uint32_t>(id);  // a 10-node one: corners come first
    }
    for (uint64_t k = 0; k < numAttributes; ++k) {
      double ignored = 0.0;
      if (!scanner.readReal(ignored)) {
        scanner.failExpected("a region attribute of tetrahedron " + std::to_string(number));
      }
    }
    mesh.addTetrahedron(corners);
    numberOfCell.push_back(static_cast<uint64_t>(number));
  }
  throwOnVolumeMeshProblem(mesh, numberOfCell, "tetrahedron", sourceName, shapes);
  return mesh;
}

}  // namespace

VolumeMesh parseTetGenMesh(std::string_view nodeText, std::string_view eleText,
                           std::string_view nodeSourceName, std::string_view eleSourceName,
                           CellShapeCheck shapes) {
  return readElements(eleText, eleSourceName, readNodes(nodeText, nodeSourceName), shapes);
}

VolumeMesh readTetGenMesh(const std::filesystem::path& path, CellShapeCheck shapes) {
  std::filesystem::path nodePath = path;
  std::filesystem::path elePath = path;
  nodePath.replace_extension(".node");
  elePath.replace_extension(".ele");
  const std::string nodeText = readInputFile(nodePath, kVolumeMeshInput);
  const std::string eleText = readInputFile(elePath, kVolumeMeshInput);
  return parseTetGenMesh(nodeText, eleText, nodePath.string(), elePath.string(), shapes);
}

}  // namespace sculpt
