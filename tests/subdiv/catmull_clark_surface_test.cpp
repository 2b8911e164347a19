// Catmull–Clark refinement of surfaces through OpenSubdiv: counts per level, the limit position
// of a cube corner against the Catmull–Clark limit mask written out here, planar grids staying
// planar with interpolated corners, and sharp tags keeping a cube a cube.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <algorithm>
#include <map>
#include <set>
#include <utility>
#include <vector>

#include "mesh/surface_triangles.h"
#include "subdiv/catmull_clark_surface.h"

namespace sculpt {
namespace {

/// The cube [-1, 1]^3 as 6 outward quads.
SurfaceMesh cube() {
  SurfaceMesh mesh;
  mesh.positions.resize(8, 3);
  for (int v = 0; v < 8; ++v)
    mesh.positions.row(v) = Eigen::RowVector3d(v & 1 ? 1 : -1, v & 2 ? 1 : -1, v & 4 ? 1 : -1);
  const int faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& face : faces) {
    for (int c : face) mesh.faces.values.push_back({static_cast<uint32_t>(c)});
    mesh.faces.closeRow();
  }
  return mesh;
}

/// An n x n grid of unit quads in the plane z = 0.
SurfaceMesh grid(int n) {
  SurfaceMesh mesh;
  mesh.positions.resize((n + 1) * (n + 1), 3);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) mesh.positions.row(j * (n + 1) + i) = Eigen::RowVector3d(i, j, 0);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const uint32_t a = static_cast<uint32_t>(j * (n + 1) + i);
      for (uint32_t c :
           {a, a + 1, a + 1 + static_cast<uint32_t>(n + 1), a + static_cast<uint32_t>(n + 1)})
        mesh.faces.values.push_back({c});
      mesh.faces.closeRow();
    }
  return mesh;
}

std::set<std::pair<uint32_t, uint32_t>> edges(const SurfaceMesh& mesh) {
  std::set<std::pair<uint32_t, uint32_t>> out;
  for (uint32_t f = 0; f < mesh.numFaces(); ++f) {
    const auto row = mesh.faces.row(f);
    for (size_t i = 0; i < row.size(); ++i) {
      const uint32_t a = row[i].position, b = row[(i + 1) % row.size()].position;
      out.insert({std::min(a, b), std::max(a, b)});
    }
  }
  return out;
}

TEST(CatmullClarkSurface, CountsPerLevelOnAClosedQuadMesh) {
  SurfaceMesh previous = cube();
  for (int level = 1; level <= 4; ++level) {
    const SurfaceMesh refined = catmullClarkRefine(cube(), level, false);
    const size_t V = previous.numVertices(), E = edges(previous).size(), F = previous.numFaces();
    EXPECT_EQ(refined.numVertices(), V + E + F) << "level " << level;
    EXPECT_EQ(refined.numFaces(), 4 * F) << "level " << level;
    for (uint32_t f = 0; f < refined.numFaces(); ++f) ASSERT_EQ(refined.faces.row(f).size(), 4u);
    // Closed genus 0: V - E + F = 2.
    const long euler =
        long(refined.numVertices()) - long(edges(refined).size()) + long(refined.numFaces());
    EXPECT_EQ(euler, 2);
    EXPECT_EQ(triangulate(refined).size(), 6 * size_t(refined.numFaces()));
    previous = refined;
  }
  EXPECT_EQ(previous.numVertices(), 1538u);  // closed genus-0 quads: V = F + 2, F = 6 * 4^4
}

TEST(CatmullClarkSurface, CubeCornerLimitMatchesTheLimitMask) {
  // Catmull–Clark's limit mask at a vertex p of valence n of an all-quad mesh, with its edge
  // neighbours e_i and the vertices f_i opposite to it in its quads:
  //   p_limit = (n^2 p + 4 sum e_i + sum f_i) / (n (n + 5)).
  for (int level : {1, 2}) {
    const SurfaceMesh mesh = catmullClarkRefine(cube(), level, false);
    const SurfaceMesh limit = catmullClarkRefine(cube(), level, true);
    ASSERT_EQ(mesh.numVertices(), limit.numVertices());
    std::map<uint32_t, std::set<uint32_t>> edgeNeighbours, opposite;
    for (uint32_t f = 0; f < mesh.numFaces(); ++f) {
      const auto q = mesh.faces.row(f);
      for (size_t i = 0; i < 4; ++i) {
        edgeNeighbours[q[i].position].insert(q[(i + 1) % 4].position);
        edgeNeighbours[q[i].position].insert(q[(i + 3) % 4].position);
        opposite[q[i].position].insert(q[(i + 2) % 4].position);
      }
    }
    int corners = 0;
    for (const auto& [v, ring] : edgeNeighbours) {
      if (ring.size() != 3) continue;
      ++corners;
      const double n = 3.0;
      Eigen::RowVector3d sum = n * n * mesh.positions.row(v);
      for (uint32_t e : ring) sum += 4.0 * mesh.positions.row(e);
      ASSERT_EQ(opposite[v].size(), 3u);
      for (uint32_t f : opposite[v]) sum += mesh.positions.row(f);
      const Eigen::RowVector3d expected = sum / (n * (n + 5.0));
      EXPECT_LT((limit.positions.row(v) - expected).norm(), 1e-14) << "level " << level;
      // The same mask on the cube itself (n = 3, edge neighbours summing to (1, 1, 1) for the
      // corner (1, 1, 1), opposite vertices to (-1, -1, -1)) gives (9 + 4 - 1) / 24 = 1/2.
      EXPECT_NEAR(expected.cwiseAbs().minCoeff(), 0.5, 1e-15);
      EXPECT_NEAR(expected.cwiseAbs().maxCoeff(), 0.5, 1e-15);
      if (corners == 1)
        std::printf("[ measured ] level %d corner limit (%.15f, %.15f, %.15f)\n", level,
                    expected.x(), expected.y(), expected.z());
    }
    EXPECT_EQ(corners, 8) << "level " << level;
  }
}

TEST(CatmullClarkSurface, CornerLimitIsTheSameFromEveryLevel) {
  // A vertex's limit point does not depend on the level it is evaluated from: the valence-3
  // vertices (the 8 corners) of levels 1 and 3 have the same set of limit points.
  auto cornerLimits = [](int level) {
    const SurfaceMesh mesh = catmullClarkRefine(cube(), level, false);
    const SurfaceMesh limit = catmullClarkRefine(cube(), level, true);
    std::map<uint32_t, std::set<uint32_t>> ring;
    for (uint32_t f = 0; f < mesh.numFaces(); ++f) {
      const auto q = mesh.faces.row(f);
      for (size_t i = 0; i < 4; ++i) ring[q[i].position].insert(q[(i + 1) % 4].position);
    }
    std::vector<Eigen::Vector3d> out;
    for (const auto& [v, r] : ring)
      if (r.size() == 3) out.push_back(limit.positions.row(v).transpose());
    std::sort(out.begin(), out.end(), [](const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
      return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
    });
    return out;
  };
  const auto a = cornerLimits(1), b = cornerLimits(3);
  ASSERT_EQ(a.size(), 8u);
  ASSERT_EQ(b.size(), 8u);
  for (size_t i = 0; i < 8; ++i) EXPECT_LT((a[i] - b[i]).norm(), 1e-13);
}

TEST(CatmullClarkSurface, PlanarGridStaysPlanarWithFixedCorners) {
  const SurfaceMesh base = grid(4);
  for (bool toLimit : {false, true}) {
    const SurfaceMesh refined = catmullClarkRefine(base, 3, toLimit);
    EXPECT_EQ(refined.numFaces(), 16u * 64u);
    EXPECT_EQ(refined.positions.col(2).cwiseAbs().maxCoeff(), 0.0);
    // Edge-and-corner boundary rule: the grid's four corners stay put, and the boundary stays on
    // the square [0, 4]^2.
    for (const Eigen::RowVector3d& corner :
         {Eigen::RowVector3d(0, 0, 0), Eigen::RowVector3d(4, 0, 0), Eigen::RowVector3d(0, 4, 0),
          Eigen::RowVector3d(4, 4, 0)}) {
      double nearest = 1e9;
      for (Eigen::Index v = 0; v < refined.positions.rows(); ++v)
        nearest = std::min(nearest, (refined.positions.row(v) - corner).norm());
      EXPECT_LT(nearest, 1e-14);
    }
    EXPECT_GE(refined.positions.minCoeff(), -1e-14);
    EXPECT_LE(refined.positions.maxCoeff(), 4.0 + 1e-14);
  }
}

TEST(CatmullClarkSurface, SharpEdgesAndCornersKeepACube) {
  // Every edge of the cube a crease and every vertex a corner: the limit surface is the cube
  // itself, so every limit point lies on a face of [-1, 1]^3.
  SurfaceTags tags;
  for (const auto& [a, b] : edges(cube())) tags.creases.push_back({a, b});
  for (uint32_t v = 0; v < 8; ++v) tags.corners.push_back(v);
  const SurfaceMesh limit = catmullClarkRefine(cube(), 3, true, tags);
  for (Eigen::Index v = 0; v < limit.positions.rows(); ++v)
    EXPECT_NEAR(limit.positions.row(v).cwiseAbs().maxCoeff(), 1.0, 1e-14) << "vertex " << v;
  // Without tags the cube rounds off: every limit point lies strictly inside.
  const SurfaceMesh smooth = catmullClarkRefine(cube(), 3, true);
  EXPECT_LT(smooth.positions.cwiseAbs().maxCoeff(), 0.99);
}

TEST(CatmullClarkSurface, PolygonsAndTrianglesBecomeQuads) {
  // A square pyramid: one quad and four triangles. One level: every face a quad; each n-gon
  // gives n quads.
  SurfaceMesh pyramid;
  pyramid.positions.resize(5, 3);
  pyramid.positions << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0.5, 0.5, 1;
  const std::vector<std::vector<uint32_t>> faces = {
      {0, 3, 2, 1}, {0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}};
  for (const auto& face : faces) {
    for (uint32_t c : face) pyramid.faces.values.push_back({c});
    pyramid.faces.closeRow();
  }
  const SurfaceMesh refined = catmullClarkRefine(pyramid, 1, true);
  EXPECT_EQ(refined.numFaces(), 4u + 4u * 3u);
  EXPECT_EQ(refined.numVertices(), 5u + 8u + 5u);
  for (uint32_t f = 0; f < refined.numFaces(); ++f) EXPECT_EQ(refined.faces.row(f).size(), 4u);
  EXPECT_TRUE(refined.positions.allFinite());
  // Level 0 keeps the input; triangulate fans the quad into two triangles.
  const SurfaceMesh same = catmullClarkRefine(pyramid, 0, true);
  EXPECT_EQ(same.positions, pyramid.positions);
  const std::vector<uint32_t> triangles = triangulate(same);
  EXPECT_EQ(triangles,
            (std::vector<uint32_t>{0, 3, 2, 0, 2, 1, 0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4}));
}

TEST(CatmullClarkSurface, RejectsBadInput) {
  EXPECT_THROW(catmullClarkRefine(cube(), 9, false), std::invalid_argument);
  EXPECT_THROW(catmullClarkRefine(cube(), -1, false), std::invalid_argument);
  SurfaceMesh bad = cube();
  bad.faces.values[5].position = 99;
  EXPECT_THROW(catmullClarkRefine(bad, 1, false), std::invalid_argument);
  SurfaceMesh degenerate;
  degenerate.positions.setZero(2, 3);
  degenerate.faces.values = {{0}, {1}};
  degenerate.faces.closeRow();
  EXPECT_THROW(catmullClarkRefine(degenerate, 1, false), std::invalid_argument);
  SurfaceTags tags;
  tags.corners.push_back(8);
  EXPECT_THROW(catmullClarkRefine(cube(), 1, false, tags), std::invalid_argument);
}

}  // namespace
}  // namespace sculpt
