// docs/design/mj-subdivision.md §4 and §7.1.6: topology of MJ refinement. Single-cell table, the
// count formulas of §4.2, the valences of §4.3, trapezohedra at pyramid apices, and closed,
// consistently oriented, positive-volume cells at every level.

#include "mesh/topology.h"

#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "mesh/validation.h"
#include "subdiv/mj_refiner.h"
#include "support/mesh_builders.h"

namespace sculpt {
namespace {

using test::jittered;
using test::NamedMesh;

const NamedMesh kMeshes[] = {
    {"UnitCube", test::unitCube},
    {"Block2x2x2", [] { return test::hexGrid(2, 2, 2); }},
    {"Block3x2x1Jittered", [] { return jittered(test::hexGrid(3, 2, 1), 0.08, 5); }},
    {"Tetrahedron", test::regularTet},
    {"Prism", test::singlePrism},
    {"Pyramid", test::singlePyramid},
    {"Octahedron", test::octahedron},
    {"KuhnCube", test::kuhnCube},
    {"PyramidCube",
     [] {
       return test::pyramidCube({0.5, 0.5, 0.75});
     }},
    {"PrismCube", test::prismCube},
    {"MixedJittered", [] { return jittered(test::mixedMesh(), 0.05, 11); }},
};

// ---------------------------------------------------------------------------------------------
// §7.1.6 single cells.

struct SingleCellRow {
  std::string name;
  std::function<CellComplex()> build;
  uint32_t vertices;
  uint32_t cells;
  uint32_t hexes;
  uint32_t trapezohedra;  ///< 10-vertex, 8-quad cells
};
void PrintTo(const SingleCellRow& r, std::ostream* os) { *os << r.name; }

class SingleCell : public ::testing::TestWithParam<SingleCellRow> {};

TEST_P(SingleCell, Section716Table) {
  const auto& row = GetParam();
  const auto s = subdivide(row.build(), 1);
  ASSERT_TRUE(s.has_value());
  const CellComplex& m = s->finest();
  EXPECT_EQ(m.numVertices(), row.vertices);
  EXPECT_EQ(m.numCells(), row.cells);
  uint32_t hexes = 0, traps = 0;
  for (uint32_t c = 0; c < m.numCells(); ++c) {
    hexes += test::rawIsHex(m, c) ? 1u : 0u;
    traps += test::rawIsTrapezohedron4(m, c) ? 1u : 0u;
    EXPECT_EQ(s->finestTopology().isHexahedron(c), test::rawIsHex(m, c)) << "cell " << c;
  }
  EXPECT_EQ(hexes, row.hexes);
  EXPECT_EQ(traps, row.trapezohedra);
}

const SingleCellRow kSingleCells[] = {
    {"Tet", test::regularTet, 15, 4, 4, 0},        {"Prism", test::singlePrism, 21, 6, 6, 0},
    {"Pyramid", test::singlePyramid, 19, 5, 4, 1}, {"Octahedron", test::octahedron, 27, 6, 0, 6},
    {"Hex", test::unitCube, 27, 8, 8, 0},
};
INSTANTIATE_TEST_SUITE_P(Section716, SingleCell, ::testing::ValuesIn(kSingleCells),
                         [](const auto& p) { return p.param.name; });

TEST(MjTopology, OneHexCounts) {
  const auto s = subdivide(test::unitCube(), 1);
  ASSERT_TRUE(s.has_value());
  const Topology& t = s->finestTopology();
  EXPECT_EQ(t.numVertices, 27u);
  EXPECT_EQ(t.numEdges(), 54u);
  EXPECT_EQ(t.numFaces(), 36u);
  EXPECT_EQ(t.numCells(), 8u);
  const auto raw = test::rawCounts(s->finest());
  EXPECT_EQ(raw.edges, 54u);
  EXPECT_EQ(raw.faces, 36u);
}

TEST(MjTopology, PyramidCubeKeepsTrapezohedra) {
  const auto s = subdivide(test::pyramidCube({0.5, 0.5, 0.75}), 2);
  ASSERT_TRUE(s.has_value());
  const uint32_t expectedHex[] = {0, 24, 240};
  const uint32_t expectedTrap[] = {0, 6, 12};
  for (int level = 1; level <= 2; ++level) {
    const CellComplex& m = s->levels[static_cast<size_t>(level)];
    uint32_t hexes = 0, traps = 0;
    for (uint32_t c = 0; c < m.numCells(); ++c) {
      hexes += test::rawIsHex(m, c) ? 1u : 0u;
      traps += test::rawIsTrapezohedron4(m, c) ? 1u : 0u;
    }
    EXPECT_EQ(hexes, expectedHex[level]) << "level " << level;
    EXPECT_EQ(traps, expectedTrap[level]) << "level " << level;
    EXPECT_EQ(m.numCells(), hexes + traps) << "level " << level;
  }
}

// ---------------------------------------------------------------------------------------------
// Per-mesh properties.

class MeshLevels : public ::testing::TestWithParam<NamedMesh> {};

// §4.2: V' = V+E+F+C, E' = 2E + sum|f| + sum F(c), F' = sum|f| + sum E(c), C' = sum V(c).
// Counts are taken straight from the face loops (independent of buildTopology) and compared with
// the topology as well.
TEST_P(MeshLevels, CountFormulas) {
  const auto s = subdivide(GetParam().build(), 2);
  ASSERT_TRUE(s.has_value());
  for (int level = 0; level < 2; ++level) {
    const auto parent = test::rawCounts(s->levels[static_cast<size_t>(level)]);
    const auto child = test::rawCounts(s->levels[static_cast<size_t>(level + 1)]);
    SCOPED_TRACE("level " + std::to_string(level) + " -> " + std::to_string(level + 1));
    EXPECT_EQ(child.vertices, parent.vertices + parent.edges + parent.faces + parent.cells);
    EXPECT_EQ(child.edges, 2 * parent.edges + parent.sumFaceSizes + parent.sumCellFaces);
    EXPECT_EQ(child.faces, parent.sumFaceSizes + parent.sumCellEdges);
    EXPECT_EQ(child.cells, parent.sumCellVerts);
    // Every child face is a quad.
    EXPECT_EQ(child.sumFaceSizes, 4ull * child.faces);
  }
  for (int level = 0; level <= 2; ++level) {
    const Topology& t = s->topologies[static_cast<size_t>(level)];
    const auto raw = test::rawCounts(s->levels[static_cast<size_t>(level)]);
    EXPECT_EQ(t.numVertices, raw.vertices);
    EXPECT_EQ(t.numEdges(), raw.edges);
    EXPECT_EQ(t.numFaces(), raw.faces);
    EXPECT_EQ(t.numCells(), raw.cells);
  }
}

// §4.3: valences of new vertices and edges after one step.
TEST_P(MeshLevels, NewValences) {
  const auto s = subdivide(GetParam().build(), 1);
  ASSERT_TRUE(s.has_value());
  const Topology& t = s->topologies[0];
  const Topology& u = s->topologies[1];
  const CellComplex& m = s->levels[0];
  const uint32_t V = t.numVertices, E = t.numEdges(), F = t.numFaces();
  for (uint32_t v = 0; v < V; ++v) {
    EXPECT_EQ(u.vertexEdges.rowSize(v), t.vertexEdges.rowSize(v)) << "vertex point " << v;
    EXPECT_EQ(u.vertexCells.rowSize(v), t.vertexCells.rowSize(v)) << "vertex point " << v;
  }
  for (uint32_t e = 0; e < E; ++e) {
    const auto [a, b] = t.edgeVertices[e];
    const uint32_t n = t.edgeFaces.rowSize(e);
    const uint32_t cells = t.edgeCells.rowSize(e);
    // Both halves inherit the number of cells around e.
    for (uint32_t end : {a, b}) {
      const int64_t half = u.findEdge(end, V + e);
      ASSERT_GE(half, 0) << "half of edge " << e;
      EXPECT_EQ(u.edgeCells.rowSize(static_cast<uint32_t>(half)), cells) << "half of edge " << e;
    }
    if (t.edgeIsBoundary[e]) continue;
    EXPECT_EQ(n, cells);
    EXPECT_EQ(u.vertexEdges.rowSize(V + e), n + 2) << "edge point " << e;
    EXPECT_EQ(u.vertexCells.rowSize(V + e), 2 * n) << "edge point " << e;
  }
  for (uint32_t f = 0; f < F; ++f) {
    const uint32_t mSize = t.faceVertices.rowSize(f);
    const uint32_t fp = V + E + f;
    // Edges from the face point to the cell points of its cells have m cells around them.
    for (int32_t c : t.faceCells[f]) {
      if (c == kNoCell) continue;
      const int64_t e = u.findEdge(fp, test::cellPointId(t, static_cast<uint32_t>(c)));
      ASSERT_GE(e, 0);
      EXPECT_EQ(u.edgeCells.rowSize(static_cast<uint32_t>(e)), mSize) << "face " << f;
    }
    if (t.faceIsBoundary[f]) continue;
    EXPECT_EQ(u.vertexEdges.rowSize(fp), mSize + 2) << "face point " << f;
    EXPECT_EQ(u.vertexCells.rowSize(fp), 2 * mSize) << "face point " << f;
    // Edges from an interior face point to the edge points of its edges have 4 cells.
    for (uint32_t e : t.faceEdges.row(f)) {
      const int64_t fe = u.findEdge(fp, V + e);
      ASSERT_GE(fe, 0);
      EXPECT_EQ(u.edgeCells.rowSize(static_cast<uint32_t>(fe)), 4u) << "face " << f;
    }
  }
  for (uint32_t c = 0; c < t.numCells(); ++c) {
    const uint32_t cp = test::cellPointId(t, c);
    EXPECT_EQ(u.vertexEdges.rowSize(cp), m.numFacesOfCell(c)) << "cell point " << c;
    EXPECT_EQ(u.vertexCells.rowSize(cp), test::cellVertexSet(m, c).size()) << "cell point " << c;
  }
}

// Every cell at levels 0..3 is closed, consistently oriented and of positive volume.
TEST_P(MeshLevels, CellsClosedOrientedPositive) {
  const auto s = subdivide(GetParam().build(), 3);
  ASSERT_TRUE(s.has_value());
  for (int level = 0; level <= 3; ++level) {
    SCOPED_TRACE("level " + std::to_string(level));
    const CellComplex& m = s->levels[static_cast<size_t>(level)];
    EXPECT_EQ(test::closedOrientedCheck(m), "");
    const auto issues = validate(m);
    EXPECT_TRUE(isValid(issues));
    for (const auto& issue : issues)
      ADD_FAILURE() << "validation: " << static_cast<int>(issue.kind) << " " << issue.message;
    EXPECT_TRUE(s->topologies[static_cast<size_t>(level)].problems.empty());
    int nonPositive = 0;
    for (uint32_t c = 0; c < m.numCells(); ++c) {
      const double v = cellVolume(m, c);
      const double own = test::signedVolume(m, c);
      if (!(v > 0.0) || !(own > 0.0)) ++nonPositive;
      EXPECT_NEAR(v, own, 1e-12 * (1.0 + std::abs(own))) << "cell " << c;
    }
    EXPECT_EQ(nonPositive, 0);
  }
}

// Total volume of the control mesh equals the sum of cellVolume (a sanity check of cellVolume on
// shapes with known volume).
TEST(MjTopology, CellVolumesOfKnownShapes) {
  const CellComplex block = test::hexGrid(2, 2, 2);
  for (uint32_t c = 0; c < block.numCells(); ++c) EXPECT_NEAR(cellVolume(block, c), 1.0, 1e-14);
  const CellComplex kuhn = test::kuhnCube();
  for (uint32_t c = 0; c < kuhn.numCells(); ++c) EXPECT_NEAR(cellVolume(kuhn, c), 1.0 / 6.0, 1e-14);
  const CellComplex pyr = test::pyramidCube({0.5, 0.5, 0.5});
  for (uint32_t c = 0; c < pyr.numCells(); ++c) EXPECT_NEAR(cellVolume(pyr, c), 1.0 / 6.0, 1e-14);
  const CellComplex tet = test::regularTet();
  EXPECT_NEAR(cellVolume(tet, 0), 8.0 / 3.0, 1e-14);
}

// §4.3 / §7.1.6 example: Kuhn cube after one step.
TEST(MjTopology, KuhnCubeValences) {
  const auto s = subdivide(test::kuhnCube(), 1);
  ASSERT_TRUE(s.has_value());
  const Topology& t = s->topologies[0];
  const Topology& u = s->topologies[1];
  ASSERT_EQ(t.numCells(), 6u);
  for (uint32_t c = 0; c < 6; ++c) {
    const uint32_t cp = test::cellPointId(t, c);
    EXPECT_EQ(u.vertexEdges.rowSize(cp), 4u);
    EXPECT_EQ(u.vertexCells.rowSize(cp), 4u);
  }
  int interiorFaces = 0;
  for (uint32_t f = 0; f < t.numFaces(); ++f) {
    if (t.faceIsBoundary[f]) continue;
    ++interiorFaces;
    const uint32_t fp = t.numVertices + t.numEdges() + f;
    EXPECT_EQ(u.vertexEdges.rowSize(fp), 5u);
    EXPECT_EQ(u.vertexCells.rowSize(fp), 6u);
  }
  EXPECT_EQ(interiorFaces, 6);
  const uint32_t diag = test::edgePointId(t, 0, 7);
  EXPECT_EQ(u.vertexEdges.rowSize(diag), 8u);
  EXPECT_EQ(u.vertexCells.rowSize(diag), 12u);
}

INSTANTIATE_TEST_SUITE_P(Meshes, MeshLevels, ::testing::ValuesIn(kMeshes),
                         [](const auto& p) { return p.param.name; });

}  // namespace
}  // namespace sculpt
