// The nearest point on the deformed boundary, against brute force and closed forms.

#include <gtest/gtest.h>

#include <random>

#include "fem/fem_model.h"
#include "io/control_mesh_json.h"
#include "tools/deformed_boundary.h"

namespace sculpt {
namespace {

TEST(ClosestPointOnTriangle, MatchesADenseSearchOfTheTriangle) {
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> u(-2, 2);
  for (int trial = 0; trial < 200; ++trial) {
    const Eigen::Vector3d a(u(random), u(random), u(random)), b(u(random), u(random), u(random)),
        c(u(random), u(random), u(random)), p(u(random), u(random), u(random));
    const Eigen::Vector3d bary = closestPointOnTriangle(p, a, b, c);
    EXPECT_NEAR(bary.sum(), 1.0, 1e-12);
    EXPECT_GE(bary.minCoeff(), -1e-12);
    const double found = (p - (bary[0] * a + bary[1] * b + bary[2] * c)).norm();
    double best = 1e300;
    const int n = 200;
    for (int i = 0; i <= n; ++i)
      for (int j = 0; i + j <= n; ++j) {
        const double s = double(i) / n, t = double(j) / n;
        best = std::min(best, (p - ((1 - s - t) * a + s * b + t * c)).norm());
      }
    EXPECT_LE(found, best + 1e-12) << "trial " << trial;
    EXPECT_GE(found, best - 0.02 * (b - a).norm() - 0.02 * (c - a).norm());
  }
}

TEST(DeformedBoundary, FindsTheFaceOfAUnitCubeAndItsDepth) {
  const std::string cube = std::string(SCULPT_SOURCE_DIR) + "/assets/block3.json";
  const CellComplex control = loadControlMeshJson(cube);
  FemSetup setup;
  setup.level = 1;
  std::string error;
  std::optional<FemModel> model = FemModel::create(control, setup, &error);
  ASSERT_TRUE(model) << error;
  const DeformedBoundary boundary(*model);
  EXPECT_GT(boundary.numTriangles(), 0u);
  Points nodes;
  model->nodesFromControl(model->restControl(), nodes);
  const Eigen::Vector3d lo = nodes.colwise().minCoeff().transpose(),
                        hi = nodes.colwise().maxCoeff().transpose();
  const Eigen::Vector3d centre = 0.5 * (lo + hi);
  // Just inside the top face, near its middle: the hit is on that face, facing +y.
  const Eigen::Vector3d inside(centre.x(), hi.y() - 0.01, centre.z());
  const std::optional<BoundaryHit> hit = boundary.nearest(nodes, inside);
  ASSERT_TRUE(hit);
  EXPECT_LT(hit->signedDistance, 0);
  EXPECT_GT(hit->normal.y(), 0.9);
  // Outside above it: positive distance.
  const std::optional<BoundaryHit> above =
      boundary.nearest(nodes, Eigen::Vector3d(centre.x(), hi.y() + 0.3, centre.z()));
  ASSERT_TRUE(above);
  EXPECT_GT(above->signedDistance, 0.25);
  // Translating the solid translates the hit.
  Points moved = nodes;
  moved.col(1).array() += 0.5;
  const std::optional<BoundaryHit> shifted =
      boundary.nearest(moved, inside + Eigen::Vector3d(0, 0.5, 0));
  ASSERT_TRUE(shifted);
  EXPECT_NEAR((shifted->point - hit->point - Eigen::Vector3d(0, 0.5, 0)).norm(), 0.0, 1e-12);
  // The rest point of the hit lies on the rest boundary.
  EXPECT_NEAR((boundary.restPoint(*shifted) - hit->point).norm(), 0.0, 1e-9);
}

}  // namespace
}  // namespace sculpt
