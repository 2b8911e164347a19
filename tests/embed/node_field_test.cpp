// Per-cell fields carried to the nodes (embed/node_field.h) against values worked out by hand:
// the volume-weighted mean of the incident cells, each cell's share at a node being the
// integral of the node's shape function over the cell.

#include "embed/node_field.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "embed/cell_coordinates.h"
#include "mesh/lattice_mesh.h"

namespace sculpt {
namespace {

// Appends node (x, y, z) to `mesh`, returning its id.
uint32_t addNode(VolumeMesh& mesh, double x, double y, double z) {
  const Eigen::Index row = mesh.positions.rows();
  mesh.positions.conservativeResize(row + 1, 3);
  mesh.positions.row(row) << x, y, z;
  return static_cast<uint32_t>(row);
}

// The node at (x, y, z), added when there is none yet.
uint32_t nodeAt(VolumeMesh& mesh, double x, double y, double z) {
  for (Eigen::Index i = 0; i < mesh.positions.rows(); ++i)
    if (mesh.positions(i, 0) == x && mesh.positions(i, 1) == y && mesh.positions(i, 2) == z)
      return static_cast<uint32_t>(i);
  return addNode(mesh, x, y, z);
}

// The box [x0, x1] x [y0, y1] x [z0, z1] as a hexahedron (VTK order), sharing existing nodes.
void addBox(VolumeMesh& mesh, double x0, double x1, double y0, double y1, double z0, double z1) {
  mesh.addHexahedron({nodeAt(mesh, x0, y0, z0), nodeAt(mesh, x1, y0, z0), nodeAt(mesh, x1, y1, z0),
                      nodeAt(mesh, x0, y1, z0), nodeAt(mesh, x0, y0, z1), nodeAt(mesh, x1, y0, z1),
                      nodeAt(mesh, x1, y1, z1), nodeAt(mesh, x0, y1, z1)});
}

std::vector<float> nodeValues(const VolumeMesh& mesh, const std::vector<float>& cellValues) {
  std::vector<float> out;
  nodeFieldFromCells(nodeFieldWeights(mesh), cellValues, out);
  return out;
}

TEST(NodeField, TwoBoxesOfDifferentVolumeShareTheirFaceAtTheVolumeWeightedMean) {
  // A 1 m^3 box of 3e6 Pa beside a 2 m^3 box of 3e8 Pa (the x extents 1 and 2).
  VolumeMesh mesh;
  addBox(mesh, 0, 1, 0, 1, 0, 1);
  addBox(mesh, 1, 3, 0, 1, 0, 1);
  ASSERT_EQ(mesh.numNodes(), 12u);
  const std::vector<float> nodes = nodeValues(mesh, {3e6f, 3e8f});
  const double shared = (1.0 * 3e6 + 2.0 * 3e8) / 3.0;  // 2.01e8
  for (uint32_t i = 0; i < mesh.numNodes(); ++i) {
    const double x = mesh.positions(i, 0);
    const double expected = x == 0.0 ? 3e6 : x == 3.0 ? 3e8 : shared;
    EXPECT_FLOAT_EQ(nodes[i], static_cast<float>(expected)) << "node at x = " << x;
  }
}

TEST(NodeField, ADistortedHexahedronWeighsEachCornerByItsShapeFunctionsIntegral) {
  // Below: a frustum, the square [0,1]^2 at z = 0 widening to [0,2] x [0,1] at z = 1; the map is
  // X = s (1 + u), Y = t, Z = u with det J = 1 + u, so a bottom corner's share is
  // 1/4 * int (1-u)(1+u) du = 1/6 and a top corner's 1/4 * int u (1+u) du = 5/24 (sum 3/2, the
  // volume). Above: the box [0,2] x [0,1] x [1,2], volume 2, 1/4 at each corner.
  VolumeMesh mesh;
  mesh.addHexahedron({nodeAt(mesh, 0, 0, 0), nodeAt(mesh, 1, 0, 0), nodeAt(mesh, 1, 1, 0),
                      nodeAt(mesh, 0, 1, 0), nodeAt(mesh, 0, 0, 1), nodeAt(mesh, 2, 0, 1),
                      nodeAt(mesh, 2, 1, 1), nodeAt(mesh, 0, 1, 1)});
  addBox(mesh, 0, 2, 0, 1, 1, 2);
  const std::vector<float> nodes = nodeValues(mesh, {1.0f, 4.0f});
  const double shared = (5.0 / 24.0 * 1.0 + 1.0 / 4.0 * 4.0) / (5.0 / 24.0 + 1.0 / 4.0);  // 29/11
  for (uint32_t i = 0; i < mesh.numNodes(); ++i) {
    const double z = mesh.positions(i, 2);
    const double expected = z == 0.0 ? 1.0 : z == 2.0 ? 4.0 : shared;
    EXPECT_FLOAT_EQ(nodes[i], static_cast<float>(expected)) << "node at z = " << z;
  }
}

TEST(NodeField, ATetrahedronAndAHexahedronShareNodesByAQuarterAndAnEighthOfTheirVolumes) {
  // The unit cube (value 1) with the tetrahedron (0,0,1) (1,0,1) (0,1,1) (0,0,2) on top
  // (volume 1/6, value 5): at the three shared nodes (1/8 * 1 + 1/24 * 5) / (1/8 + 1/24) = 2.
  VolumeMesh mesh;
  addBox(mesh, 0, 1, 0, 1, 0, 1);
  const uint32_t apex = addNode(mesh, 0, 0, 2);
  mesh.addTetrahedron({nodeAt(mesh, 0, 0, 1), nodeAt(mesh, 1, 0, 1), nodeAt(mesh, 0, 1, 1), apex});
  ASSERT_GT(tetrahedronSignedVolume(mesh, 1), 0.0);
  const std::vector<float> nodes = nodeValues(mesh, {1.0f, 5.0f});
  const auto at = [&](double x, double y, double z) { return nodes[nodeAt(mesh, x, y, z)]; };
  EXPECT_FLOAT_EQ(at(0, 0, 1), 2.0f);
  EXPECT_FLOAT_EQ(at(1, 0, 1), 2.0f);
  EXPECT_FLOAT_EQ(at(0, 1, 1), 2.0f);
  EXPECT_FLOAT_EQ(at(1, 1, 1), 1.0f) << "a node of the cube alone";
  EXPECT_FLOAT_EQ(at(0, 0, 0), 1.0f);
  EXPECT_FLOAT_EQ(nodes[apex], 5.0f) << "a node of the tetrahedron alone";
}

TEST(NodeField, AConstantFieldStaysExactlyConstantOnJitteredTetAndHexLattices) {
  LatticeSpec spec;
  spec.cubes = {4, 3, 3};
  spec.spacing = 0.1;
  for (bool hexahedra : {false, true}) {
    VolumeMesh mesh = hexahedra ? hexLattice(spec) : tetLattice(spec);
    jitterLattice(mesh, spec, 0.2, 7);
    for (const float value : {3.0e7f, 1234.5f, 0.1f}) {
      const std::vector<float> nodes = nodeValues(mesh, std::vector<float>(mesh.numCells(), value));
      for (uint32_t i = 0; i < mesh.numNodes(); ++i) ASSERT_EQ(nodes[i], value) << "node " << i;
    }
  }
}

TEST(NodeField, ALinearFieldSampledAtCellCentresIsExactInsideAndHalfACellOffOnTheBoundary) {
  // f = 2 + 3 x - y + 0.5 z sampled at the cell centroids of a lattice of h = 0.5. Around an
  // inside node the cells are centrally symmetric, so their mean centroid is the node: f exactly.
  // On the boundary the cells are on one side: at the corner (0,0,0) the mean centroid is the
  // node + h/2 (1,1,1), so f + (3 - 1 + 0.5) h/2; on the x = 0 face of the hex lattice away from
  // the edges, the node + h/2 along x, so f + 3 h/2.
  const Eigen::Vector3d gradient(3.0, -1.0, 0.5);
  const auto f = [&](const Eigen::Vector3d& X) { return 2.0 + gradient.dot(X); };
  LatticeSpec spec;
  spec.cubes = {4, 4, 4};
  spec.spacing = 0.5;
  const double h = spec.spacing;
  for (bool hexahedra : {false, true}) {
    const VolumeMesh mesh = hexahedra ? hexLattice(spec) : tetLattice(spec);
    std::vector<float> cells(mesh.numCells());
    for (uint32_t c = 0; c < mesh.numCells(); ++c)
      cells[c] = static_cast<float>(f(cellCentroid(mesh, c)));
    const std::vector<float> nodes = nodeValues(mesh, cells);
    const auto value = [&](uint32_t i, uint32_t j, uint32_t k) {
      return nodes[latticeNode(spec, i, j, k)];
    };
    const auto exact = [&](uint32_t i, uint32_t j, uint32_t k) {
      return f(h * Eigen::Vector3d(i, j, k));
    };
    for (uint32_t i = 1; i < 4; ++i)
      for (uint32_t j = 1; j < 4; ++j)
        for (uint32_t k = 1; k < 4; ++k)
          EXPECT_NEAR(value(i, j, k), exact(i, j, k), 1e-5) << i << " " << j << " " << k;
    // The corner's cube is all its own (in the tet lattice all 6 tetrahedra of the cube share
    // the corner on their diagonal, their mean centroid the cube's centre).
    EXPECT_NEAR(value(0, 0, 0), exact(0, 0, 0) + (3.0 - 1.0 + 0.5) * h / 2, 1e-5);
    if (!hexahedra) continue;  // the half star of a tet lattice's face node is not symmetric
    for (uint32_t j = 1; j < 4; ++j)
      for (uint32_t k = 1; k < 4; ++k)
        EXPECT_NEAR(value(0, j, k), exact(0, j, k) + 3.0 * h / 2, 1e-5) << j << " " << k;
  }
}

TEST(NodeField, TooFewCellValuesAreRefused) {
  VolumeMesh mesh;
  addBox(mesh, 0, 1, 0, 1, 0, 1);
  addBox(mesh, 1, 2, 0, 1, 0, 1);
  std::vector<float> nodes;
  EXPECT_THROW(nodeFieldFromCells(nodeFieldWeights(mesh), std::vector<float>{1.0f}, nodes),
               std::invalid_argument);
}

}  // namespace
}  // namespace sculpt
