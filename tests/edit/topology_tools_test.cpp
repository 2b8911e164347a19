// Every topology tool (core/edit/topology_edit.h) on the bundled 3x3x3 block and on the small
// house (a hexahedron with a pyramid roof and tagged sharp features): the result validates, its
// MacCracken–Joy boundary equals OpenSubdiv's Catmull–Clark refinement of its boundary, and the
// counts and volumes are the ones the operation must give (volumes from cellVolume, exact for
// planar faces).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>

#include "edit/topology_edit.h"
#include "support/edit_fixtures.h"
#include "support/opensubdiv_oracle.h"

namespace sculpt {
namespace {

using test::block3;
using test::houseSmall;
using test::twoParts;
using test::unitCube;

constexpr double kNoCheck = NAN;

struct ToolCase {
  std::string name;
  std::function<CellComplex()> mesh;
  std::function<TopologyEdit(const CellComplex&)> edit;
  int cellDelta = 0;
  int vertexDelta = 0;
  double volumeDelta = kNoCheck;    ///< m^3
  size_t creases = 0, corners = 0;  ///< tag counts after the edit
  bool movesVertices = false;       ///< weld: surviving vertices may move (by half the tolerance)
};

void PrintTo(const ToolCase& c, std::ostream* os) { *os << c.name; }

// The roof triangle (4, 5, 8) of the house: area |(1,0,0) x (.5,.5,.5)| / 2 = sqrt(2)/4.
const double kRoofTriangleArea = std::sqrt(2.0) / 4.0;

std::vector<FaceRef> block3TopFaces() {
  std::vector<FaceRef> faces;
  for (uint32_t c = 18; c < 27; ++c) faces.push_back({c, 1});
  return faces;
}

const ToolCase kCases[] = {
    {"Block3DeleteCorner", block3,
     [](const CellComplex& m) { return deleteCells(m, std::vector<uint32_t>{26}); }, -1, -1, -1.0},
    {"Block3DeleteCentre", block3,
     [](const CellComplex& m) { return deleteCells(m, std::vector<uint32_t>{13}); }, -1, 0, -1.0},
    {"HouseDeleteRoof", houseSmall,
     [](const CellComplex& m) { return deleteCells(m, std::vector<uint32_t>{1}); }, -1, -1,
     -1.0 / 6.0, 4, 4},
    {"Block3ExtrudeTopQuad", block3,
     [](const CellComplex& m) {
       return extrudeFaces(m, std::vector<FaceRef>{{22, 1}}, 0.5);
     },
     1, 4, 0.5},
    {"Block3ExtrudeTopRegion", block3,
     [](const CellComplex& m) { return extrudeFaces(m, block3TopFaces(), 0.25); }, 9, 16, 9 * 0.25},
    {"Block3ExtrudeAroundAnEdge", block3,
     [](const CellComplex& m) {
       return extrudeFaces(m, std::vector<FaceRef>{{26, 1}, {26, 3}}, 0.3);
     },
     2, 6},
    {"HouseExtrudeRoofTriangle", houseSmall,
     [](const CellComplex& m) {
       return extrudeFaces(m, std::vector<FaceRef>{{1, 1}}, 0.3);
     },
     1, 3, 0.3 * kRoofTriangleArea, 4, 4},
    {"HouseExtrudeCreasedSide", houseSmall,
     [](const CellComplex& m) {
       return extrudeFaces(m, std::vector<FaceRef>{{0, 2}}, 0.3);
     },
     1, 4, 0.3, 4, 4},
    {"Block3BridgeToCube",
     [] {
       return twoParts(block3(), unitCube(), {4, 1, 1});
     },
     [](const CellComplex& m) {
       return bridgeFaces(m, {14, 3}, {27, 5});
     },
     1, 0, 1.0},
    {"HouseBridgeToHouse",
     [] {
       return twoParts(houseSmall(), houseSmall(), {2, 0, 0});
     },
     [](const CellComplex& m) {
       return bridgeFaces(m, {0, 3}, {2, 5});
     },
     1, 0, 1.0, 8, 8},
    {"Block3WeldCube",
     [] {
       return twoParts(block3(), unitCube(), {3, 1, 1});
     },
     [](const CellComplex& m) {
       return weldFaces(m, {14, 3}, {27, 5}, 1e-9);
     },
     0, -4, 0.0, 0, 0, true},
    // The bottom creases (1, 3) and (0', 2') become one, as do corners 1, 0' and 3, 2'.
    {"HouseWeldHouse",
     [] {
       return twoParts(houseSmall(), houseSmall(), {1, 0, 0});
     },
     [](const CellComplex& m) {
       return weldFaces(m, {0, 3}, {2, 5}, 1e-9);
     },
     0, -4, 0.0, 7, 6, true},
    {"Block3SubdivideTopMiddle", block3,
     [](const CellComplex& m) { return subdivideCells(m, std::vector<uint32_t>{22}); }, 7,
     12 + 6 + 1, 0.0},
    {"Block3SubdivideTwoNeighbours", block3,
     [](const CellComplex& m) {
       return subdivideCells(m, std::vector<uint32_t>{13, 22});
     },
     14, 2 * 19 - 4 - 1, 0.0},
    // Each creased bottom edge is split in two.
    {"HouseSubdivideHex", houseSmall,
     [](const CellComplex& m) { return subdivideCells(m, std::vector<uint32_t>{0}); }, 7, 19, 0.0,
     8, 4},
    // A pyramid has 5 corners; 8 edges, 5 faces and the centre give 14 new vertices.
    {"HouseSubdivideRoof", houseSmall,
     [](const CellComplex& m) { return subdivideCells(m, std::vector<uint32_t>{1}); }, 4, 14, 0.0,
     4, 4},
    {"Block3CreaseTopEdges", block3,
     [](const CellComplex& m) {
       const std::array<uint32_t, 2> edges[] = {{49, 48}, {49, 50}, {50, 51}, {50, 51}};
       return setCreases(m, edges, true);
     },
     0, 0, 0.0, 3, 0},
    {"Block3TagCorners", block3,
     [](const CellComplex& m) {
       return setCorners(m, std::vector<uint32_t>{48, 51, 5}, true);
     },
     0, 0, 0.0, 0, 3},
    {"HouseClearCreaseAndTagApex", houseSmall,
     [](const CellComplex& m) {
       const std::array<uint32_t, 2> edge[] = {{1, 0}};
       const TopologyEdit cleared = setCreases(m, edge, false);
       return setCorners(cleared.mesh, std::vector<uint32_t>{8}, true);
     },
     0, 0, 0.0, 3, 5},
};

class TopologyTools : public ::testing::TestWithParam<ToolCase> {};

TEST_P(TopologyTools, ResultValidatesMatchesOpenSubdivAndCounts) {
  const ToolCase& c = GetParam();
  const CellComplex before = c.mesh();
  ASSERT_TRUE(test::validMesh(before));
  const TopologyEdit edit = c.edit(before);
  const CellComplex& after = edit.mesh;
  EXPECT_FALSE(edit.label.empty());
  ASSERT_TRUE(test::validMesh(after));

  EXPECT_EQ(int(after.numCells()) - int(before.numCells()), c.cellDelta);
  EXPECT_EQ(int(after.numVertices()) - int(before.numVertices()), c.vertexDelta);
  if (!std::isnan(c.volumeDelta)) {
    EXPECT_NEAR(test::totalVolume(after) - test::totalVolume(before), c.volumeDelta, 1e-12);
  }
  EXPECT_EQ(after.creases.size(), c.creases);
  EXPECT_EQ(after.corners.size(), c.corners);
  // Tags are normalised: (low, high), sorted, no repeats.
  for (const auto& [a, b] : after.creases) EXPECT_LT(a, b);
  EXPECT_TRUE(std::adjacent_find(after.creases.begin(), after.creases.end(),
                                 std::greater_equal<>()) == after.creases.end());
  EXPECT_TRUE(std::adjacent_find(after.corners.begin(), after.corners.end(),
                                 std::greater_equal<>()) == after.corners.end());

  // The vertex map: surviving vertices keep their place.
  ASSERT_EQ(edit.newVertexOfOld.size(), before.numVertices());
  for (uint32_t v = 0; v < before.numVertices(); ++v) {
    const int64_t n = edit.newVertexOfOld[v];
    ASSERT_LT(n, int64_t(after.numVertices()));
    if (n < 0) continue;
    const double moved = (test::pos(after, uint32_t(n)) - test::pos(before, v)).norm();
    EXPECT_LE(moved, c.movesVertices ? 1e-9 : 0.0) << "vertex " << v;
  }

  test::compareWithOpenSubdiv(after, 3);
}

INSTANTIATE_TEST_SUITE_P(Edits, TopologyTools, ::testing::ValuesIn(kCases),
                         [](const auto& p) { return p.param.name; });

// The extruded block of one quad: the old face is now shared, the new vertices lie `distance`
// above the old ones along +z, and the new cell is a hexahedron.
TEST(TopologyTools, ExtrudedQuadIsAHexahedronAboveTheFace) {
  const CellComplex block = block3();
  const TopologyEdit edit = extrudeFaces(block, std::vector<FaceRef>{{22, 1}}, 0.5);
  const Topology t = buildTopology(edit.mesh);
  EXPECT_TRUE(t.isHexahedron(27));
  const auto top = block.cellFace(22, 1);
  for (uint32_t k = 0; k < 4; ++k) {
    const Eigen::Vector3d expected = test::pos(block, top[k]) + Eigen::Vector3d(0, 0, 0.5);
    EXPECT_EQ(test::pos(edit.mesh, 64 + k), expected);
  }
  EXPECT_EQ(boundaryFaces(block).size(), 54u);
  EXPECT_EQ(boundaryFaces(edit.mesh).size(), 54u + 4u);
}

// Local subdivision of the centre cell: 8 hexahedra with the right volumes (1/8 each), the
// neighbour across a face gets 4 quads instead of that face (9 faces), the neighbour across an
// edge gets the midpoint in its two faces at that edge (5-gons).
TEST(TopologyTools, SubdividedCentreCellSplitsItsNeighboursConformingly) {
  const TopologyEdit edit = subdivideCells(block3(), std::vector<uint32_t>{13});
  const CellComplex& m = edit.mesh;
  const Topology t = buildTopology(m);
  std::vector<uint32_t> parts = {13};
  for (uint32_t c = 27; c < 34; ++c) parts.push_back(c);
  for (uint32_t c : parts) {
    EXPECT_TRUE(t.isHexahedron(c)) << c;
    EXPECT_NEAR(cellVolume(m, c), 0.125, 1e-14) << c;
  }
  EXPECT_EQ(m.numFacesOfCell(14), 9u);  // (2,1,1): face neighbour
  EXPECT_EQ(m.numFacesOfCell(5), 6u);   // (2,1,0): edge neighbour, still 6 faces...
  size_t pentagons = 0;
  for (uint32_t j = 0; j < m.numFacesOfCell(5); ++j) pentagons += m.cellFace(5, j).size() == 5;
  EXPECT_EQ(pentagons, 2u);            // ...two of them with the midpoint inserted
  EXPECT_EQ(m.numFacesOfCell(0), 6u);  // (0,0,0) touches the centre cell at a vertex only
  for (uint32_t j = 0; j < 6; ++j) EXPECT_EQ(m.cellFace(0, j).size(), 4u);
}

}  // namespace
}  // namespace sculpt
