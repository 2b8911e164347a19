// docs/design/mj-subdivision.md §7.2 (hand-checkable point values), §7.1.3 (displaced centre) and
// §7.1.4 (linear precision). Points are located through the child numbering of mj_refiner.h.

#include <gtest/gtest.h>

#include <optional>
#include <string>

#include "mesh/topology.h"
#include "subdiv/mj_refiner.h"
#include "support/mesh_builders.h"

namespace sculpt {
namespace {

using test::cellPointId;
using test::edgePointId;
using test::facePointId;
using test::gridVertex;

constexpr double kTol = 1e-13;

void expectPoint(const Points& p, uint32_t id, const Eigen::Vector3d& expected,
                 const std::string& what) {
  ASSERT_LT(id, static_cast<uint32_t>(p.rows())) << what;
  const Eigen::Vector3d got = test::pos(p, id);
  EXPECT_NEAR(got.x(), expected.x(), kTol) << what;
  EXPECT_NEAR(got.y(), expected.y(), kTol) << what;
  EXPECT_NEAR(got.z(), expected.z(), kTol) << what;
}

Subdivision refined(const CellComplex& m, int levels) {
  auto s = subdivide(m, levels);
  EXPECT_TRUE(s.has_value());
  if (!s) return {};
  EXPECT_EQ(s->numLevels(), levels);
  return std::move(*s);
}

Eigen::Vector3d v3(double x, double y, double z) { return {x, y, z}; }
Eigen::Vector3d all(double a) { return {a, a, a}; }

TEST(HandValues, UnitCubeStepOne) {
  const Subdivision s = refined(test::unitCube(), 1);
  ASSERT_EQ(s.numLevels(), 1);
  ASSERT_EQ(s.levels.size(), 2u);
  const Topology& t = s.topologies[0];
  const Points& p = s.levels[1].positions;
  // Corner ids x + 2y + 4z.
  expectPoint(p, 0, all(2.0 / 9.0), "vertex point of (0,0,0)");
  expectPoint(p, edgePointId(t, 0, 1), v3(0.5, 1.0 / 8.0, 1.0 / 8.0), "edge point (0,0,0)-(1,0,0)");
  expectPoint(p, facePointId(t, {0, 1, 2, 3}), v3(0.5, 0.5, 0.0), "face point of z=0");
  expectPoint(p, cellPointId(t, 0), all(0.5), "cell point");
}

TEST(HandValues, UnitCubeStepTwo) {
  const Subdivision s = refined(test::unitCube(), 2);
  ASSERT_EQ(s.numLevels(), 2);
  ASSERT_EQ(s.levels.size(), 3u);
  const Topology& t0 = s.topologies[0];
  const Topology& t1 = s.topologies[1];
  const Points& p2 = s.levels[2].positions;
  const uint32_t centre = cellPointId(t0, 0);             // level-1 id of the cube centre
  const uint32_t bottom = facePointId(t0, {0, 1, 2, 3});  // level-1 id of the z=0 face point
  // The level-1 centre is a regular interior vertex.
  ASSERT_FALSE(t1.vertexIsBoundary[centre]);
  EXPECT_EQ(t1.vertexEdges.rowSize(centre), 6u);
  EXPECT_EQ(t1.vertexFaces.rowSize(centre), 12u);
  EXPECT_EQ(t1.vertexCells.rowSize(centre), 8u);
  expectPoint(p2, centre, all(0.5), "level-1 cell point stays");
  const int64_t e = t1.findEdge(centre, bottom);
  ASSERT_GE(e, 0);
  EXPECT_FALSE(t1.edgeIsBoundary[static_cast<size_t>(e)]);
  EXPECT_EQ(t1.edgeFaces.rowSize(static_cast<uint32_t>(e)), 4u);
  expectPoint(p2, edgePointId(t1, centre, bottom), v3(0.5, 0.5, 323.0 / 1152.0),
              "edge point centre - bottom face point");
  expectPoint(p2, 0, all(53.0 / 216.0), "corner after two steps");
}

TEST(HandValues, TwoByTwoByTwoBlock) {
  const Subdivision s = refined(test::hexGrid(2, 2, 2), 1);
  ASSERT_EQ(s.numLevels(), 1);
  const Topology& t = s.topologies[0];
  const Points& p = s.levels[1].positions;
  auto g = [](int i, int j, int k) { return gridVertex(2, 2, i, j, k); };
  expectPoint(p, g(1, 1, 1), all(1.0), "centre vertex");
  expectPoint(p, edgePointId(t, g(1, 1, 1), g(1, 1, 2)), v3(1, 1, 1.5), "interior edge up");
  expectPoint(p, facePointId(t, {g(1, 1, 1), g(2, 1, 1), g(2, 2, 1), g(1, 2, 1)}), v3(1.5, 1.5, 1),
              "interior face");
  expectPoint(p, edgePointId(t, g(1, 1, 0), g(1, 1, 1)), v3(1, 1, 0.5),
              "interior edge ending on the boundary");
  expectPoint(p, g(1, 1, 0), v3(1, 1, 0), "boundary face-centre vertex");
  expectPoint(p, g(0, 0, 0), all(2.0 / 9.0), "corner");
  expectPoint(p, g(1, 0, 0), v3(1, 1.0 / 8.0, 1.0 / 8.0), "box-edge vertex");
}

TEST(HandValues, Tetrahedron) {
  const Subdivision s = refined(test::regularTet(), 1);
  ASSERT_EQ(s.numLevels(), 1);
  const Topology& t = s.topologies[0];
  const Points& p = s.levels[1].positions;
  expectPoint(p, 0, all(7.0 / 27.0), "vertex (1,1,1)");
  expectPoint(p, edgePointId(t, 0, 1), v3(2.0 / 3.0, 0, 0), "edge (1,1,1)-(1,-1,-1)");
  expectPoint(p, facePointId(t, {0, 1, 2}), v3(1.0 / 3.0, 1.0 / 3.0, -1.0 / 3.0), "face");
  expectPoint(p, cellPointId(t, 0), all(0.0), "cell");
}

TEST(HandValues, KuhnCube) {
  const Subdivision s = refined(test::kuhnCube(), 1);
  ASSERT_EQ(s.numLevels(), 1);
  const Topology& t = s.topologies[0];
  const Points& p = s.levels[1].positions;
  // Corner ids x + 2y + 4z: (0,0,0) = 0, (1,0,0) = 1, (1,1,1) = 7.
  const int64_t diag = t.findEdge(0, 7);
  ASSERT_GE(diag, 0);
  EXPECT_EQ(t.edgeFaces.rowSize(static_cast<uint32_t>(diag)), 6u);
  EXPECT_EQ(t.edgeCells.rowSize(static_cast<uint32_t>(diag)), 6u);
  expectPoint(p, edgePointId(t, 0, 7), all(0.5), "diagonal edge point (n = 6)");
  expectPoint(p, facePointId(t, {0, 1, 7}), v3(17.0 / 24.0, 17.0 / 48.0, 17.0 / 48.0),
              "interior face {(0,0,0),(1,0,0),(1,1,1)}");
  expectPoint(p, 0, all(5.0 / 36.0), "boundary corner (0,0,0), CC valence 6");
  expectPoint(p, 1, v3(43.0 / 48.0, 5.0 / 24.0, 5.0 / 24.0), "boundary vertex (1,0,0), valence 4");
}

TEST(HandValues, SixPyramidCube) {
  const Subdivision s = refined(test::pyramidCube(v3(0.5, 0.5, 0.75)), 1);
  ASSERT_EQ(s.numLevels(), 1);
  const Topology& t = s.topologies[0];
  const Points& p = s.levels[1].positions;
  const uint32_t apex = 8;
  expectPoint(p, apex, v3(0.5, 0.5, 197.0 / 320.0), "apex vertex point");
  const int64_t e = t.findEdge(0, apex);
  ASSERT_GE(e, 0);
  EXPECT_EQ(t.edgeFaces.rowSize(static_cast<uint32_t>(e)), 3u);
  expectPoint(p, edgePointId(t, 0, apex), v3(83.0 / 270.0, 83.0 / 270.0, 41.0 / 108.0),
              "interior edge (0,0,0)-apex (n = 3)");
  expectPoint(p, facePointId(t, {0, 1, apex}), v3(0.5, 7.0 / 30.0, 0.3),
              "interior triangle {(0,0,0),(1,0,0),apex}");
}

// §7.1.3: moving the centre of a 2x2x2 block by d moves its vertex point by 27/64 d.
TEST(HandValues, DisplacedCentre) {
  CellComplex m = test::hexGrid(2, 2, 2);
  const uint32_t centre = gridVertex(2, 2, 1, 1, 1);
  const Eigen::Vector3d d(0.1, -0.2, 0.3);
  m.positions.row(centre) += d.transpose();
  const Subdivision s = refined(m, 1);
  ASSERT_EQ(s.numLevels(), 1);
  expectPoint(s.levels[1].positions, centre, v3(667.0 / 640.0, 293.0 / 320.0, 721.0 / 640.0),
              "displaced centre");
  expectPoint(s.levels[1].positions, centre, all(1.0) + 27.0 / 64.0 * d, "1 + 27/64 d");
}

// §7.1.4: on an undistorted 3x3x3 grid every point of an interior element is the centroid of
// its element and interior vertices stay put.
TEST(HandValues, LinearPrecisionOnUnitGrid) {
  const CellComplex m = test::hexGrid(3, 3, 3);
  const Subdivision s = refined(m, 1);
  ASSERT_EQ(s.numLevels(), 1);
  const Topology& t = s.topologies[0];
  const Points& p = s.levels[1].positions;
  auto centroid = [&](auto vertices) {
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    double n = 0;
    for (uint32_t v : vertices) {
      c += test::pos(m, v);
      n += 1;
    }
    return Eigen::Vector3d(c / n);
  };
  int vertices = 0, edges = 0, faces = 0;
  for (uint32_t v = 0; v < t.numVertices; ++v) {
    if (t.vertexIsBoundary[v]) continue;
    ++vertices;
    expectPoint(p, v, test::pos(m, v), "interior vertex " + std::to_string(v));
  }
  for (uint32_t e = 0; e < t.numEdges(); ++e) {
    if (t.edgeIsBoundary[e]) continue;
    ++edges;
    expectPoint(p, t.numVertices + e, centroid(t.edgeVertices[e]),
                "interior edge " + std::to_string(e));
  }
  for (uint32_t f = 0; f < t.numFaces(); ++f) {
    if (t.faceIsBoundary[f]) continue;
    ++faces;
    expectPoint(p, t.numVertices + t.numEdges() + f, centroid(t.faceVertices.row(f)),
                "interior face " + std::to_string(f));
  }
  for (uint32_t c = 0; c < t.numCells(); ++c)
    expectPoint(p, cellPointId(t, c), centroid(test::cellVertexSet(m, c)),
                "cell " + std::to_string(c));
  // 2^3 interior vertices, 3 * 2 * 2 * 3 interior edges, 3 * 2 * 9 interior faces.
  EXPECT_EQ(vertices, 8);
  EXPECT_EQ(edges, 36);
  EXPECT_EQ(faces, 54);
  EXPECT_EQ(t.numCells(), 27u);
}

}  // namespace
}  // namespace sculpt
