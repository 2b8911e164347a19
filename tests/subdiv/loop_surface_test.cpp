// Loop refinement of surfaces through OpenSubdiv: counts on the bunny, affine invariance, and the
// limit position of an icosahedron vertex against Loop's closed-form limit mask.

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "io/obj_surface.h"
#include "subdiv/loop_surface.h"

namespace sculpt {
namespace {

SurfaceMesh icosahedron() {
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  const double v[12][3] = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                           {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  const int f[20][3] = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                        {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                        {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                        {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  SurfaceMesh mesh;
  mesh.positions.resize(12, 3);
  for (int i = 0; i < 12; ++i)
    mesh.positions.row(i) = Eigen::RowVector3d(v[i][0], v[i][1], v[i][2]).normalized();
  for (const auto& face : f) {
    for (int c : face) mesh.faces.values.push_back({static_cast<uint32_t>(c)});
    mesh.faces.closeRow();
  }
  return mesh;
}

TEST(LoopSurface, BunnyLevel3CountsAndClosedTopology) {
  const SurfaceMesh bunny = readObjSurface(SCULPT_SOURCE_DIR "/assets/bunny.obj");
  ASSERT_EQ(bunny.numFaces(), 3674u);
  const auto start = std::chrono::steady_clock::now();
  const SurfaceMesh refined = loopRefine(bunny, 3, true);
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  std::printf("[ measured ] bunny level 3: %u vertices, %u triangles in %.1f ms\n",
              refined.numVertices(), refined.numFaces(), ms);
  EXPECT_EQ(refined.numFaces(), 3674u * 64u);
  // A closed genus-0 triangle mesh has V = F / 2 + 2.
  EXPECT_EQ(refined.numVertices(), refined.numFaces() / 2 + 2);
  EXPECT_TRUE(refined.positions.allFinite());
}

TEST(LoopSurface, AffineInvariance) {
  const SurfaceMesh base = icosahedron();
  Eigen::Matrix3d A;
  A << 1.3, 0.2, -0.1, 0.0, 0.9, 0.4, 0.3, -0.2, 1.1;
  const Eigen::RowVector3d t(0.5, -2.0, 1.0);
  SurfaceMesh moved = base;
  moved.positions = (base.positions * A.transpose()).rowwise() + t;
  for (bool limit : {false, true}) {
    const SurfaceMesh a = loopRefine(base, 3, limit);
    const SurfaceMesh b = loopRefine(moved, 3, limit);
    const Points expected = (a.positions * A.transpose()).rowwise() + t;
    EXPECT_LT((expected - b.positions).cwiseAbs().maxCoeff(), 1e-12);
  }
}

TEST(LoopSurface, IcosahedronVertexLimitMatchesLoopsLimitMask) {
  // Loop's limit mask at valence n: (w v + sum of neighbours) / (w + n), w = 3 / (8 beta),
  // beta = (5/8 - (3/8 + cos(2 pi / n) / 4)^2) / n. An icosahedron vertex on the unit sphere has
  // five neighbours at cos(angle) = 1/sqrt(5), so its limit point lies at this radius:
  const double n = 5.0;
  const double c = 3.0 / 8.0 + std::cos(2.0 * std::numbers::pi / n) / 4.0;
  const double beta = (5.0 / 8.0 - c * c) / n;
  const double w = 3.0 / (8.0 * beta);
  const double radius = (w + n / std::sqrt(5.0)) / (w + n);
  for (int levels : {1, 3}) {
    const SurfaceMesh limit = loopRefine(icosahedron(), levels, true);
    int onRadius = 0;
    double largest = 0.0;
    for (Eigen::Index v = 0; v < limit.positions.rows(); ++v) {
      const double r = limit.positions.row(v).norm();
      largest = std::max(largest, r);
      if (std::abs(r - radius) < 1e-12) ++onRadius;
    }
    std::printf("[ measured ] level %d: %d limit points at the mask radius %.12f\n", levels,
                onRadius, radius);
    EXPECT_EQ(onRadius, 12);  // exactly the children of the 12 original vertices
  }
}

TEST(LoopSurface, RejectsNonTrianglesAndBadLevels) {
  SurfaceMesh quad;
  quad.positions.setZero(4, 3);
  for (uint32_t v = 0; v < 4; ++v) quad.faces.values.push_back({v});
  quad.faces.closeRow();
  EXPECT_THROW(loopRefine(quad, 1), std::invalid_argument);
  EXPECT_THROW(loopRefine(icosahedron(), 9), std::invalid_argument);
  EXPECT_THROW(loopRefine(icosahedron(), -1), std::invalid_argument);
}

}  // namespace
}  // namespace sculpt
