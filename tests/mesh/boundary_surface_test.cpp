// The boundary surface of a cell complex: counts, closedness, Euler characteristic and outward
// orientation (its enclosed volume by the divergence theorem equals the solid's volume), the
// vertex map back to the complex, and the sharp tags carried over.

#include "mesh/boundary_surface.h"

#include <gtest/gtest.h>

#include <map>
#include <set>
#include <utility>

#include "support/mesh_builders.h"

namespace sculpt {
namespace {

/// Volume enclosed by the surface: 1/3 of the flux of x through it, each polygon fanned.
double enclosedVolume(const SurfaceMesh& s) {
  double volume = 0;
  for (uint32_t f = 0; f < s.numFaces(); ++f) {
    const auto row = s.faces.row(f);
    const Eigen::Vector3d a = s.positions.row(row[0].position).transpose();
    for (size_t i = 2; i < row.size(); ++i) {
      const Eigen::Vector3d b = s.positions.row(row[i - 1].position).transpose();
      const Eigen::Vector3d c = s.positions.row(row[i].position).transpose();
      volume += a.dot(b.cross(c)) / 6.0;
    }
  }
  return volume;
}

TEST(BoundarySurface, LatticeTwoByTwoByTwo) {
  const CellComplex lattice = test::hexGrid(2, 2, 2, 0.5);
  const Topology topology = buildTopology(lattice);
  const BoundarySurface boundary = boundarySurface(lattice, topology);
  const SurfaceMesh& s = boundary.surface;
  EXPECT_EQ(s.numFaces(), 24u);
  EXPECT_EQ(s.numVertices(), 26u);  // all 27 lattice points but the centre
  for (uint32_t f = 0; f < s.numFaces(); ++f) EXPECT_EQ(s.faces.row(f).size(), 4u);

  // Closed and consistently oriented: every directed edge appears once, its reverse once.
  std::map<std::pair<uint32_t, uint32_t>, int> directed;
  for (uint32_t f = 0; f < s.numFaces(); ++f) {
    const auto row = s.faces.row(f);
    for (size_t i = 0; i < row.size(); ++i)
      ++directed[{row[i].position, row[(i + 1) % row.size()].position}];
  }
  std::set<std::pair<uint32_t, uint32_t>> undirected;
  for (const auto& [edge, count] : directed) {
    EXPECT_EQ(count, 1);
    EXPECT_EQ(directed.count({edge.second, edge.first}), 1u);
    undirected.insert({std::min(edge.first, edge.second), std::max(edge.first, edge.second)});
  }
  const long euler = long(s.numVertices()) - long(undirected.size()) + long(s.numFaces());
  EXPECT_EQ(euler, 2);
  // Outward: the enclosed volume is +1 (the cube of side 1), not -1.
  EXPECT_NEAR(enclosedVolume(s), 1.0, 1e-14);

  // The vertex map: increasing complex indices, same positions, and the centre left out.
  ASSERT_EQ(boundary.complexVertex.size(), 26u);
  for (uint32_t v = 0; v < 26; ++v) {
    if (v > 0) {
      EXPECT_LT(boundary.complexVertex[v - 1], boundary.complexVertex[v]);
    }
    EXPECT_EQ(s.positions.row(v), lattice.positions.row(boundary.complexVertex[v]));
  }
  const uint32_t centre = test::gridVertex(2, 2, 1, 1, 1);
  for (uint32_t v : boundary.complexVertex) EXPECT_NE(v, centre);
}

TEST(BoundarySurface, TagsOnTheBoundaryAreCarriedOver) {
  CellComplex lattice = test::hexGrid(2, 1, 1);
  const uint32_t a = test::gridVertex(2, 1, 0, 0, 0), b = test::gridVertex(2, 1, 1, 0, 0);
  lattice.creases.push_back({a, b});
  lattice.corners.push_back(a);
  const Topology topology = buildTopology(lattice);
  const BoundarySurface boundary = boundarySurface(lattice, topology);
  ASSERT_EQ(boundary.creases.size(), 1u);
  ASSERT_EQ(boundary.corners.size(), 1u);
  EXPECT_EQ(boundary.complexVertex[boundary.creases[0][0]], a);
  EXPECT_EQ(boundary.complexVertex[boundary.creases[0][1]], b);
  EXPECT_EQ(boundary.complexVertex[boundary.corners[0]], a);
  EXPECT_NEAR(enclosedVolume(boundary.surface), 2.0, 1e-14);
}

TEST(BoundarySurface, EmptyComplexGivesEmptySurface) {
  const CellComplex empty;
  const BoundarySurface boundary = boundarySurface(empty, buildTopology(empty));
  EXPECT_EQ(boundary.surface.numVertices(), 0u);
  EXPECT_EQ(boundary.surface.numFaces(), 0u);
}

}  // namespace
}  // namespace sculpt
