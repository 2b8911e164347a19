// The hexahedral control cage around an imported surface: a valid complex whose level-2
// MacCracken–Joy solid contains every surface vertex, with a cell count that follows the cell
// size, and clear refusals.

#include "embed/surface_cage.h"

#include <gtest/gtest.h>

#include <chrono>
#include <iostream>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>

#include "embed/embedding.h"
#include "embed/solid_cell_mesh.h"
#include "io/obj_surface.h"
#include "mesh/validation.h"
#include "subdiv/mj_refiner.h"
#include "support/tetgen.h"

namespace sculpt {
namespace {

SurfaceMesh triangleSurface(const std::vector<Eigen::Vector3d>& points,
                            const std::vector<std::array<uint32_t, 3>>& triangles) {
  SurfaceMesh surface;
  surface.positions.resize(Eigen::Index(points.size()), 3);
  for (size_t v = 0; v < points.size(); ++v)
    surface.positions.row(Eigen::Index(v)) = points[v].transpose();
  for (const auto& t : triangles) {
    for (uint32_t v : t) surface.faces.values.push_back({v});
    surface.faces.closeRow();
  }
  return surface;
}

// An icosahedron subdivided `levels` times and pushed onto the sphere (outward triangles).
SurfaceMesh icosphere(int levels, double radius, const Eigen::Vector3d& centre,
                      size_t dropFaces = 0) {
  // The icosphere of the TetGen test support, as a SurfaceMesh (optionally with holes).
  test::TriangleSurface sphere = test::icosphereSurface(centre, radius, levels);
  sphere.triangles.resize(sphere.triangles.size() - dropFaces);
  return triangleSurface(sphere.vertices, sphere.triangles);
}

SurfaceMesh bunny() { return readObjSurface(SCULPT_SOURCE_DIR "/assets/bunny.obj"); }

std::string errors(const CellComplex& complex) {
  std::string text;
  for (const auto& issue : validate(complex))
    if (issue.severity == ValidationIssue::Severity::Error) text += issue.message + "\n";
  return text;
}

// Surface vertices outside the level-2 MacCracken–Joy solid of the cage.
uint32_t outsideLevel2(const Cage& cage, const SurfaceMesh& surface) {
  const auto subdivision = subdivide(cage.control, 2);
  if (!subdivision) return std::numeric_limits<uint32_t>::max();
  const SolidCellMesh solid = solidCellMesh(subdivision->finest(), subdivision->finestTopology());
  return embedPoints(solid.mesh, surface.positions).outsideCount;
}

TEST(SurfaceCage, IcosphereCageIsValidAndItsLevel2SolidContainsTheSurface) {
  const SurfaceMesh sphere = icosphere(3, 1.0, {0.3, -0.2, 0.1});
  const Cage cage = buildSurfaceCage(sphere);
  EXPECT_EQ(errors(cage.control), "");
  EXPECT_NEAR(cage.cellSize, 2.0 / 12.0, 0.01);
  // Every cell is an axis-aligned cube of the cell size with positive volume
  for (uint32_t c = 0; c < cage.control.numCells(); ++c)
    ASSERT_NEAR(cellVolume(cage.control, c), std::pow(cage.cellSize, 3), 1e-9);
  // The interior is filled: the cage holds about the volume of the sphere grown by the margin
  const double volume = cage.control.numCells() * std::pow(cage.cellSize, 3);
  EXPECT_GT(volume, 4.0 / 3.0 * std::numbers::pi);
  EXPECT_LT(volume, 4.0 / 3.0 * std::numbers::pi * std::pow(1.0 + 3.0 * cage.cellSize, 3));
  EXPECT_EQ(outsideLevel2(cage, sphere), 0u);
}

TEST(SurfaceCage, BunnyCageIsValidAndItsLevel2SolidContainsTheSurface) {
  const SurfaceMesh surface = bunny();
  const auto start = std::chrono::steady_clock::now();
  const Cage cage = buildSurfaceCage(surface);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << "[ bunny    ] default cage: cell size " << cage.cellSize << ", grid "
            << cage.gridSize[0] << " x " << cage.gridSize[1] << " x " << cage.gridSize[2] << ", "
            << cage.control.numCells() << " cells, " << cage.control.numVertices()
            << " vertices, built in " << seconds * 1e3 << " ms\n";
  EXPECT_EQ(errors(cage.control), "");
  EXPECT_GT(cage.control.numCells(), 200u);
  EXPECT_EQ(outsideLevel2(cage, surface), 0u);
}

TEST(SurfaceCage, ContainmentByMargin) {
  // Reports what each margin achieves; the default (1) must contain every vertex.
  const SurfaceMesh surfaces[2] = {icosphere(3, 1.0, {0.3, -0.2, 0.1}), bunny()};
  const char* names[2] = {"icosphere", "bunny"};
  for (int s = 0; s < 2; ++s)
    for (int margin : {0, 1}) {
      CageSettings settings;
      settings.marginCells = margin;
      const Cage cage = buildSurfaceCage(surfaces[s], settings);
      ASSERT_EQ(errors(cage.control), "") << names[s] << " margin " << margin;
      const uint32_t outside = outsideLevel2(cage, surfaces[s]);
      std::cout << "[ margin   ] " << names[s] << " margin " << margin << ": "
                << cage.control.numCells() << " cells, " << outside << " of "
                << surfaces[s].numVertices() << " vertices outside the level-2 solid\n";
      if (margin == CageSettings{}.marginCells) {
        EXPECT_EQ(outside, 0u) << names[s];
      }
    }
}

TEST(SurfaceCage, OpenSurfaceStillGetsAFilledCage) {
  // Two triangles missing: the winding number still calls the interior inside.
  const SurfaceMesh closed = icosphere(3, 1.0, {0, 0, 0});
  const SurfaceMesh open = icosphere(3, 1.0, {0, 0, 0}, 2);
  const Cage a = buildSurfaceCage(closed), b = buildSurfaceCage(open);
  EXPECT_EQ(errors(b.control), "");
  EXPECT_EQ(a.control.numCells(), b.control.numCells());
  EXPECT_EQ(outsideLevel2(b, open), 0u);
}

TEST(SurfaceCage, VoxelsTouchingAlongAnEdgeAreMadeManifold) {
  // Two tiny tetrahedra in diagonal voxels that share one edge: margin 0 would give two cubes
  // sharing only an edge, which validate() rejects; the builder fills around it.
  std::vector<Eigen::Vector3d> points;
  std::vector<std::array<uint32_t, 3>> faces;
  for (const Eigen::Vector3d& centre :
       {Eigen::Vector3d(0.5, 0.5, 0.5), Eigen::Vector3d(1.5, 1.5, 0.5)}) {
    const uint32_t base = uint32_t(points.size());
    points.push_back(centre + Eigen::Vector3d(0.1, 0.1, 0.1));
    points.push_back(centre + Eigen::Vector3d(0.1, -0.1, -0.1));
    points.push_back(centre + Eigen::Vector3d(-0.1, 0.1, -0.1));
    points.push_back(centre + Eigen::Vector3d(-0.1, -0.1, 0.1));
    for (const auto& f :
         std::vector<std::array<uint32_t, 3>>{{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}})
      faces.push_back({base + f[0], base + f[1], base + f[2]});
  }
  CageSettings settings;
  settings.cellSize = 1.0;
  settings.marginCells = 0;
  const Cage cage = buildSurfaceCage(triangleSurface(points, faces), settings);
  EXPECT_GT(cage.control.numCells(), 2u);
  EXPECT_EQ(errors(cage.control), "");
}

TEST(SurfaceCage, HalvingTheCellSizeMultipliesCellsByAboutEight) {
  const SurfaceMesh surfaces[2] = {icosphere(3, 1.0, {0, 0, 0}), bunny()};
  const double sizes[2] = {0.1, 0.5};
  for (int s = 0; s < 2; ++s) {
    CageSettings coarse, fine;
    coarse.cellSize = sizes[s];
    fine.cellSize = sizes[s] / 2;
    fine.marginCells = 2 * coarse.marginCells;  // the same margin in surface units
    const auto start = std::chrono::steady_clock::now();
    const Cage a = buildSurfaceCage(surfaces[s], coarse);
    const Cage b = buildSurfaceCage(surfaces[s], fine);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double ratio = double(b.control.numCells()) / double(a.control.numCells());
    std::cout << "[ scaling  ] cell size " << sizes[s] << ": " << a.control.numCells() << " cells, "
              << sizes[s] / 2 << ": " << b.control.numCells() << " cells (ratio " << ratio
              << ", both in " << seconds * 1e3 << " ms)\n";
    // The voxels that hold the surface stick out about half a cell, less on the finer grid: the
    // ratio is a little under 8
    EXPECT_GT(ratio, 6.0);
    EXPECT_LT(ratio, 8.5);
    EXPECT_EQ(errors(b.control), "");
  }
}

template <typename F>
std::string refusal(F&& build) {
  try {
    build();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(no exception)";
}

TEST(SurfaceCage, RefusesBadInputWithClearMessages) {
  const SurfaceMesh sphere = icosphere(1, 1.0, {0, 0, 0});
  CageSettings settings;
  settings.cellSize = 1e-4;
  EXPECT_NE(refusal([&] { buildSurfaceCage(sphere, settings); }).find("too many cells"),
            std::string::npos);
  settings.cellSize = 0.2;
  settings.maxCells = 100;
  EXPECT_NE(refusal([&] { buildSurfaceCage(sphere, settings); }).find("limit of 100"),
            std::string::npos);
  settings = {};
  settings.cellSize = -1.0;
  EXPECT_NE(refusal([&] { buildSurfaceCage(sphere, settings); }).find("cell size must be positive"),
            std::string::npos);
  settings.cellSize = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(refusal([&] { buildSurfaceCage(sphere, settings); }).find("cell size must be positive"),
            std::string::npos);
  settings = {};
  settings.marginCells = -1;
  EXPECT_NE(refusal([&] { buildSurfaceCage(sphere, settings); }).find("marginCells"),
            std::string::npos);
  EXPECT_NE(refusal([] { buildSurfaceCage(SurfaceMesh{}); }).find("surface is empty"),
            std::string::npos);
  SurfaceMesh broken = sphere;
  broken.positions(3, 1) = std::numeric_limits<double>::infinity();
  EXPECT_NE(refusal([&] { buildSurfaceCage(broken); }).find("non-finite"), std::string::npos);
  SurfaceMesh point = triangleSurface({{1, 1, 1}, {1, 1, 1}, {1, 1, 1}}, {{0, 1, 2}});
  EXPECT_NE(refusal([&] { buildSurfaceCage(point); }).find("zero extent"), std::string::npos);
}

}  // namespace
}  // namespace sculpt
