// isClosedOutwardSurface on cubes whose triangles are oriented by geometry (each triangle's
// normal pointing away from its cube's centre), then opened, flipped, split along seams, joined
// at an edge, nested and moved far from the origin.

#include "mesh/closed_surface.h"

#include <gtest/gtest.h>

#include <array>
#include <utility>
#include <vector>

#include <Eigen/Geometry>

namespace sculpt {
namespace {

struct Surface {
  Points positions;
  std::vector<uint32_t> triangles;
};

// Appends the 12 triangles of the cube [low, low + size]^3 (8 new vertices), each facing away
// from the centre when `outward`, towards it otherwise.
void addCube(Surface& s, const Eigen::Vector3d& low, double size, bool outward) {
  const auto first = static_cast<uint32_t>(s.positions.rows());
  s.positions.conservativeResize(first + 8, 3);
  for (uint32_t corner = 0; corner < 8; ++corner)
    s.positions.row(first + corner) =
        (low + size * Eigen::Vector3d(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1))
            .transpose();
  const Eigen::Vector3d centre = low + Eigen::Vector3d::Constant(0.5 * size);
  // Each face as a loop of corners (bit d of a corner is its coordinate along axis d).
  const int faces[6][4] = {{0, 1, 3, 2}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 3, 7, 5}};
  for (const auto& face : faces)
    for (const auto& tri : {std::array<int, 3>{face[0], face[1], face[2]},
                            std::array<int, 3>{face[0], face[2], face[3]}}) {
      uint32_t a = first + tri[0], b = first + tri[1], c = first + tri[2];
      const Eigen::Vector3d pa = s.positions.row(a), pb = s.positions.row(b),
                            pc = s.positions.row(c);
      const bool facesOut = (pb - pa).cross(pc - pa).dot(pa - centre) > 0.0;
      if (facesOut != outward) std::swap(b, c);
      s.triangles.insert(s.triangles.end(), {a, b, c});
    }
}

Surface cube(bool outward = true) {
  Surface s;
  addCube(s, Eigen::Vector3d::Zero(), 1.0, outward);
  return s;
}

TEST(ClosedOutwardSurface, ACubeFacingOutIsAndFacingInIsNot) {
  const Surface out = cube(true), in = cube(false);
  EXPECT_TRUE(isClosedOutwardSurface(out.positions, out.triangles));
  EXPECT_FALSE(isClosedOutwardSurface(in.positions, in.triangles));
}

TEST(ClosedOutwardSurface, AMissingOrFlippedTriangleOpensIt) {
  for (size_t t = 0; t < 12; ++t) {
    Surface open = cube();
    open.triangles.erase(open.triangles.begin() + 3 * t, open.triangles.begin() + 3 * t + 3);
    EXPECT_FALSE(isClosedOutwardSurface(open.positions, open.triangles)) << "without " << t;
    Surface flipped = cube();
    std::swap(flipped.triangles[3 * t + 1], flipped.triangles[3 * t + 2]);
    EXPECT_FALSE(isClosedOutwardSurface(flipped.positions, flipped.triangles)) << "flip " << t;
  }
}

TEST(ClosedOutwardSurface, VerticesSplitAlongASeamStillClose) {
  Surface split = cube();
  // The first face's two triangles get vertices of their own at the same positions, as a
  // texture seam around that face would give them.
  for (size_t i = 0; i < 6; ++i) {
    const auto copy = static_cast<uint32_t>(split.positions.rows());
    split.positions.conservativeResize(copy + 1, 3);
    split.positions.row(copy) = split.positions.row(split.triangles[i]);
    split.triangles[i] = copy;
  }
  EXPECT_TRUE(isClosedOutwardSurface(split.positions, split.triangles));
  // Moved by a rounding error, the copies no longer meet: open.
  split.positions(split.positions.rows() - 1, 0) += 1e-12;
  EXPECT_FALSE(isClosedOutwardSurface(split.positions, split.triangles));
}

TEST(ClosedOutwardSurface, EveryShellMustFaceOut) {
  Surface two = cube();
  addCube(two, Eigen::Vector3d(3.0, 0.0, 0.0), 1.0, true);
  EXPECT_TRUE(isClosedOutwardSurface(two.positions, two.triangles));
  // A small cube facing in beside a large one facing out: the total volume is positive, yet the
  // small one would be drawn inside out.
  Surface mixed;
  addCube(mixed, Eigen::Vector3d::Zero(), 3.0, true);
  addCube(mixed, Eigen::Vector3d(5.0, 0.0, 0.0), 1.0, false);
  EXPECT_FALSE(isClosedOutwardSurface(mixed.positions, mixed.triangles));
  // A hollow solid: its inner wall faces into the cavity.
  Surface hollow;
  addCube(hollow, Eigen::Vector3d::Zero(), 3.0, true);
  addCube(hollow, Eigen::Vector3d::Constant(1.0), 1.0, false);
  EXPECT_FALSE(isClosedOutwardSurface(hollow.positions, hollow.triangles));
}

TEST(ClosedOutwardSurface, CubesJoinedAtAnEdgeAreNotAManifold) {
  Surface joined = cube();
  addCube(joined, Eigen::Vector3d(1.0, 1.0, 0.0), 1.0, true);  // shares the edge x = y = 1
  EXPECT_FALSE(isClosedOutwardSurface(joined.positions, joined.triangles));
}

TEST(ClosedOutwardSurface, FarFromTheOriginAndDegenerateOrBadInput) {
  Surface far;
  addCube(far, Eigen::Vector3d(1e7, -2e7, 3e7), 0.01, true);
  EXPECT_TRUE(isClosedOutwardSurface(far.positions, far.triangles));

  Surface degenerate = cube();
  degenerate.triangles[2] = degenerate.triangles[1];
  EXPECT_FALSE(isClosedOutwardSurface(degenerate.positions, degenerate.triangles));
  Surface outOfRange = cube();
  outOfRange.triangles[5] = 8;
  EXPECT_FALSE(isClosedOutwardSurface(outOfRange.positions, outOfRange.triangles));
  const Surface whole = cube();
  EXPECT_FALSE(isClosedOutwardSurface(whole.positions, {}));
  EXPECT_FALSE(isClosedOutwardSurface(
      whole.positions, std::span<const uint32_t>(whole.triangles.data(), 35)));
}

}  // namespace
}  // namespace sculpt
