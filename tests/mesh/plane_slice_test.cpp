// Plane slices of cell meshes against analytic cross-sections: areas of box sections, exact
// reproduction of linear fields, per-cell values, empty slices and bad input. Positions and
// values are single precision (they go to the GPU), so tolerances are a few float ulps.

#include "mesh/plane_slice.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include <Eigen/Geometry>

#include "mesh/lattice_mesh.h"

namespace sculpt {
namespace {

constexpr double kFloatTolerance = 2e-6;

Eigen::Vector3d vertex(const PlaneSlice& s, uint32_t v) {
  return {s.positions[3 * v], s.positions[3 * v + 1], s.positions[3 * v + 2]};
}

/// (b - a) x (c - a) of triangle t: twice its area times its unit normal.
Eigen::Vector3d triangleCross(const PlaneSlice& s, uint32_t t) {
  const Eigen::Vector3d a = vertex(s, s.triangles[3 * t]);
  return (vertex(s, s.triangles[3 * t + 1]) - a).cross(vertex(s, s.triangles[3 * t + 2]) - a);
}

double totalArea(const PlaneSlice& s) {
  double area = 0.0;
  for (uint32_t t = 0; t < s.numTriangles(); ++t) area += 0.5 * triangleCross(s, t).norm();
  return area;
}

/// Every triangle faces the way the plane normal points.
void expectWoundAlong(const PlaneSlice& s, const Eigen::Vector3d& normal) {
  for (uint32_t t = 0; t < s.numTriangles(); ++t)
    EXPECT_GT(triangleCross(s, t).dot(normal), 0.0) << "triangle " << t;
}

LatticeSpec unitCubeLattice(uint32_t n) {
  LatticeSpec spec;
  spec.cubes = {n, n, n};
  spec.spacing = 1.0 / n;
  return spec;
}

const double kHexagonArea = 3.0 * std::sqrt(3.0) / 4.0;  // x+y+z = 3/2 in [0,1]^3: side sqrt(2)/2

TEST(PlaneSlice, HorizontalCutOfUnitCubeLatticeHasUnitArea) {
  const VolumeMesh mesh = hexLattice(unitCubeLattice(3));
  const Eigen::Vector3d up(0, 0, 1);
  const PlaneSlice slice = slicePlane(mesh, mesh.positions, up, 0.37, {}, {});
  ASSERT_GT(slice.numTriangles(), 0u);
  EXPECT_NEAR(totalArea(slice), 1.0, kFloatTolerance);
  for (uint32_t v = 0; v < slice.numVertices(); ++v) {
    EXPECT_NEAR(slice.positions[3 * v + 2], 0.37, 1e-7) << "vertex " << v;
    EXPECT_EQ(slice.values[v], 0.0f);
  }
  expectWoundAlong(slice, up);
  // The same plane written with a longer normal.
  const PlaneSlice scaled = slicePlane(mesh, mesh.positions, 2.5 * up, 2.5 * 0.37, {}, {});
  EXPECT_EQ(scaled.numTriangles(), slice.numTriangles());
  EXPECT_NEAR(totalArea(scaled), 1.0, kFloatTolerance);
}

TEST(PlaneSlice, FaceLyingInThePlaneIsCutOnce) {
  // z = 1/3 runs through a layer of lattice nodes: the faces there must appear once, not twice.
  const LatticeSpec spec = unitCubeLattice(3);
  for (const VolumeMesh& mesh : {hexLattice(spec), tetLattice(spec)}) {
    const PlaneSlice slice = slicePlane(mesh, mesh.positions, {0, 0, 1}, spec.spacing, {}, {});
    EXPECT_NEAR(totalArea(slice), 1.0, kFloatTolerance);
    expectWoundAlong(slice, {0, 0, 1});
  }
}

TEST(PlaneSlice, ObliqueCutOfUnitCubeIsTheRegularHexagon) {
  const Eigen::Vector3d normal(1, 1, 1);
  for (uint32_t n : {1u, 3u}) {
    const VolumeMesh mesh = hexLattice(unitCubeLattice(n));
    const PlaneSlice slice = slicePlane(mesh, mesh.positions, normal, 1.5, {}, {});
    EXPECT_NEAR(totalArea(slice), kHexagonArea, kFloatTolerance) << n << " cubes a side";
    expectWoundAlong(slice, normal);
  }
}

TEST(PlaneSlice, JitteredLatticeStillFillsTheBoxWithoutCracks) {
  // Interior nodes move, boundary nodes stay on the box: the cells still tile [0,1]^3, so any
  // section of the box keeps its area only if neighbouring cells are cut without gaps or overlaps.
  const LatticeSpec spec = unitCubeLattice(4);
  VolumeMesh mesh = hexLattice(spec);
  jitterLattice(mesh, spec, 0.15, 11);
  EXPECT_NEAR(totalArea(slicePlane(mesh, mesh.positions, {0, 0, 1}, 0.37, {}, {})), 1.0,
              kFloatTolerance);
  EXPECT_NEAR(totalArea(slicePlane(mesh, mesh.positions, {1, 1, 1}, 1.5, {}, {})), kHexagonArea,
              kFloatTolerance);
}

TEST(PlaneSlice, FollowsTheGivenNodePositions) {
  // Stretching the solid by 2 in x and 3 in y makes the horizontal section 6 m^2, at z scaled too.
  const VolumeMesh mesh = hexLattice(unitCubeLattice(3));
  const Points stretched = mesh.positions * Eigen::Vector3d(2, 3, 0.5).asDiagonal();
  const PlaneSlice slice = slicePlane(mesh, stretched, {0, 0, 1}, 0.2, {}, {});
  EXPECT_NEAR(totalArea(slice), 6.0, 6 * kFloatTolerance);
  for (uint32_t v = 0; v < slice.numVertices(); ++v)
    EXPECT_NEAR(slice.positions[3 * v + 2], 0.2, 1e-7);
}

TEST(PlaneSlice, LinearNodeFieldIsReproducedAtEveryVertex) {
  const LatticeSpec spec = unitCubeLattice(4);
  for (bool hexahedra : {true, false}) {
    VolumeMesh mesh = hexahedra ? hexLattice(spec) : tetLattice(spec);
    jitterLattice(mesh, spec, 0.15, 5);
    const auto field = [](const Eigen::Vector3d& x) { return 2 * x.x() - x.y() + 3 * x.z() + 1; };
    std::vector<double> values(mesh.numNodes());
    for (uint32_t n = 0; n < mesh.numNodes(); ++n)
      values[n] = field(mesh.positions.row(n).transpose());
    const Eigen::Vector3d normal(0.3, -0.5, 1.0);
    const PlaneSlice slice = slicePlane(mesh, mesh.positions, normal, 0.2, values, {});
    ASSERT_GT(slice.numTriangles(), 10u);
    for (uint32_t v = 0; v < slice.numVertices(); ++v) {
      const Eigen::Vector3d p = vertex(slice, v);
      EXPECT_NEAR(slice.values[v], field(p), 1e-5) << "vertex " << v;
      EXPECT_NEAR(normal.dot(p), 0.2, 1e-6) << "vertex " << v;
    }
  }
}

TEST(PlaneSlice, CellValuesAreConstantOnEachCellsPolygons) {
  const int n = 3;
  const VolumeMesh mesh = hexLattice(unitCubeLattice(n));
  std::vector<double> values(mesh.numCells());
  for (uint32_t c = 0; c < mesh.numCells(); ++c) values[c] = 100.0 + c;
  const PlaneSlice slice = slicePlane(mesh, mesh.positions, {0.2, 0.7, 1.0}, 0.8, {}, values);
  ASSERT_GT(slice.numTriangles(), 10u);
  for (uint32_t t = 0; t < slice.numTriangles(); ++t) {
    // The cell holding the triangle's centroid, found from the lattice directly.
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    for (int k = 0; k < 3; ++k) centroid += vertex(slice, slice.triangles[3 * t + k]) / 3.0;
    const Eigen::Array3i ijk = (centroid.array() * double(n)).floor().cast<int>();
    const double expected = 100.0 + ijk.x() + n * (ijk.y() + n * ijk.z());
    for (int k = 0; k < 3; ++k)
      EXPECT_EQ(slice.values[slice.triangles[3 * t + k]], static_cast<float>(expected))
          << "triangle " << t;
  }
}

TEST(PlaneSlice, PlaneMissingTheSolidGivesAnEmptySlice) {
  const VolumeMesh mesh = hexLattice(unitCubeLattice(2));
  for (double offset : {-0.5, 1.5}) {
    const PlaneSlice slice = slicePlane(mesh, mesh.positions, {0, 0, 1}, offset, {}, {});
    EXPECT_TRUE(slice.triangles.empty());
    EXPECT_TRUE(slice.positions.empty());
    EXPECT_TRUE(slice.values.empty());
  }
}

TEST(PlaneSlice, SingleTetrahedronGivesTheAnalyticSections) {
  VolumeMesh tet;
  tet.positions.resize(4, 3);
  tet.positions << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1;
  tet.addTetrahedron({0, 1, 2, 3});
  // z = 1/4: one node above, a right triangle with legs 3/4.
  PlaneSlice slice = slicePlane(tet, tet.positions, {0, 0, 1}, 0.25, {}, {});
  EXPECT_EQ(slice.numTriangles(), 1u);
  EXPECT_NEAR(totalArea(slice), 0.5 * 0.75 * 0.75, 1e-7);
  // The same plane seen from the other side: three nodes above, wound the other way.
  slice = slicePlane(tet, tet.positions, {0, 0, -1}, -0.25, {}, {});
  EXPECT_EQ(slice.numTriangles(), 1u);
  EXPECT_NEAR(totalArea(slice), 0.5 * 0.75 * 0.75, 1e-7);
  expectWoundAlong(slice, {0, 0, -1});
  // x + y = 1/2: two nodes on each side, a 1/2 by sqrt(1/2) rectangle.
  slice = slicePlane(tet, tet.positions, {1, 1, 0}, 0.5, {}, {});
  EXPECT_EQ(slice.numTriangles(), 2u);
  EXPECT_NEAR(totalArea(slice), 0.5 * std::sqrt(0.5), 1e-7);
  expectWoundAlong(slice, {1, 1, 0});
}

TEST(PlaneSlice, BadInputThrows) {
  const VolumeMesh mesh = hexLattice(unitCubeLattice(2));
  const Points& x = mesh.positions;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<double> nodeValues(mesh.numNodes(), 1.0), cellValues(mesh.numCells(), 1.0);
  const std::vector<double> tooFew(3, 1.0);
  EXPECT_THROW(slicePlane(mesh, x, {0, 0, 0}, 0.5, {}, {}), std::invalid_argument);
  EXPECT_THROW(slicePlane(mesh, x, {0, nan, 1}, 0.5, {}, {}), std::invalid_argument);
  EXPECT_THROW(slicePlane(mesh, x, {0, 0, 1}, nan, {}, {}), std::invalid_argument);
  EXPECT_THROW(slicePlane(mesh, x.topRows(5), {0, 0, 1}, 0.5, {}, {}), std::invalid_argument);
  EXPECT_THROW(slicePlane(mesh, x, {0, 0, 1}, 0.5, tooFew, {}), std::invalid_argument);
  EXPECT_THROW(slicePlane(mesh, x, {0, 0, 1}, 0.5, {}, tooFew), std::invalid_argument);
  EXPECT_THROW(slicePlane(mesh, x, {0, 0, 1}, 0.5, nodeValues, cellValues), std::invalid_argument);
  VolumeMesh pyramid = mesh;
  pyramid.cells.values.insert(pyramid.cells.values.end(), {0, 1, 2, 3, 4});
  pyramid.cells.closeRow();
  EXPECT_THROW(slicePlane(pyramid, x, {0, 0, 1}, 0.5, {}, {}), std::invalid_argument);
  VolumeMesh outOfRange = mesh;
  outOfRange.addTetrahedron({0, 1, 2, 999});
  EXPECT_THROW(slicePlane(outOfRange, x, {0, 0, 1}, 0.5, {}, {}), std::invalid_argument);
  // A message that says what is wrong.
  try {
    slicePlane(mesh, x, {0, 0, 1}, 0.5, tooFew, {});
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("3 node values for 27 nodes"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace sculpt
