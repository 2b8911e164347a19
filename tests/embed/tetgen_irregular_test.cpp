// Phong Deformation on an irregular tetrahedral mesh made by TetGen (the paper's setting):
// finite results for every point, inside or outside the mesh, lower error than linear
// interpolation against analytic Kelvinlets and the bend-and-twist map, and on a ball (mostly
// boundary nodes) lower error with the quadratic-fit node gradients than with the average.

#include <gtest/gtest.h>

#include <cstdio>
#include <random>

#include "embed/embedded_deformer.h"
#include "embed/interpolation_study.h"
#include "embed/kelvinlet.h"
#include "support/tetgen.h"

namespace sculpt {
namespace {

VolumeMesh tetgenBox(const char* name) {
  // tetgen is installed by scripts/install-deps.sh: a missing tetgen is a failure, not a skip.
  EXPECT_TRUE(test::tetgenAvailable())
      << "tetgen not on PATH (scripts/install-deps.sh installs it)";
  test::ScopedTempDir dir(name);
  std::string error;
  // Max volume 0.002: mean edge about 0.25 in a box of edge 4 (h / eps about 0.25 below).
  const auto mesh = test::tetgenMesh(test::boxSurface(Eigen::Vector3d::Constant(-2.0),
                                                      Eigen::Vector3d::Constant(2.0)),
                                     0.002, dir.path(), &error);
  if (!mesh) ADD_FAILURE() << error;
  return mesh ? *mesh : VolumeMesh{};
}

Points ballPoints(uint32_t count, double radius, uint32_t seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Points points(count, 3);
  for (Eigen::Index p = 0; p < points.rows();) {
    const Eigen::Vector3d X(uniform(random), uniform(random), uniform(random));
    if (X.norm() <= 1.0) points.row(p++) = radius * X.transpose();
  }
  return points;
}

TEST(TetGenIrregular, PhongBeatsLinearOnKelvinletsAndBendTwist) {
  const VolumeMesh mesh = tetgenBox("phong_tetgen");
  ASSERT_GT(mesh.numCells(), 1000u);
  std::printf("tetgen mesh: %u nodes, %u tets, mean edge %.4f\n", mesh.numNodes(), mesh.numCells(),
              meanEdgeLength(mesh));
  const Points points = ballPoints(3000, 1.5, 5);
  Eigen::Matrix3d pinch;
  pinch << 1.0, 0.3, 0.0, 0.3, -0.5, 0.2, 0.0, 0.2, -0.5;
  const RegularizedKelvinlet kelvinlets[] = {
      RegularizedKelvinlet::grab(Eigen::Vector3d(0.01, 0.02, -0.01), Eigen::Vector3d(1, 0.5, -0.3),
                                 1.0),
      RegularizedKelvinlet::twist(Eigen::Vector3d(0.01, 0.02, -0.01), Eigen::Vector3d(0.2, 0.3, 1),
                                  1.0),
      RegularizedKelvinlet::pinch(Eigen::Vector3d(0.01, 0.02, -0.01), 0.5 * pinch, 1.0)};
  for (const RegularizedKelvinlet& kelvinlet : kelvinlets) {
    const MethodErrors errors = measureInterpolationErrors(
        mesh, points, [&](const Eigen::Vector3d& X) { return kelvinlet.map(X); });
    std::printf("kelvinlet: rms linear %.3e phong %.3e (ratio %.2f), max linear %.3e phong %.3e\n",
                errors.rms[0], errors.rms[2], errors.rms[0] / errors.rms[2], errors.max[0],
                errors.max[2]);
    for (double e : errors.rms) EXPECT_TRUE(std::isfinite(e));
    EXPECT_LT(errors.rms[2], errors.rms[0]);
    EXPECT_LT(errors.max[2], errors.max[0]);
  }
  const MethodErrors bend = measureInterpolationErrors(mesh, 0.5 * points, bendAndTwist);
  std::printf("bend+twist: rms linear %.3e phong %.3e attribute %.3e\n", bend.rms[0], bend.rms[2],
              bend.rms[3]);
  EXPECT_LT(bend.rms[2], bend.rms[0]);
}

TEST(TetGenIrregular, QuadraticFitGradientsBeatTheAverageOnASphere) {
  // An irregular mesh with a curved boundary: most of a ball's volume is near its surface.
  EXPECT_TRUE(test::tetgenAvailable())
      << "tetgen not on PATH (scripts/install-deps.sh installs it)";
  test::ScopedTempDir dir("phong_tetgen_sphere");
  std::string error;
  const auto mesh = test::tetgenMesh(test::icosphereSurface(Eigen::Vector3d::Zero(), 1.0, 3),
                                     0.001, dir.path(), &error);
  ASSERT_TRUE(mesh) << error;
  ASSERT_GT(mesh->numCells(), 1000u);
  // Points inside the ball, where the mesh is: a ball of radius 0.98.
  const Points points = ballPoints(3000, 0.98, 11);
  const AnalyticDeformation maps[] = {
      bendAndTwist,
      [](const Eigen::Vector3d& X) {
        return RegularizedKelvinlet::twist(Eigen::Vector3d(0.6, 0.1, -0.2),
                                           Eigen::Vector3d(0.1, 0.2, 0.5), 1.0)
            .map(X);
      }};
  const char* names[] = {"bend+twist", "kelvinlet twist at the surface"};
  for (size_t k = 0; k < std::size(maps); ++k) {
    const MethodErrors fit =
        measureInterpolationErrors(*mesh, points, maps[k], GradientScheme::Fit);
    const MethodErrors average =
        measureInterpolationErrors(*mesh, points, maps[k], GradientScheme::Average);
    std::printf("[ measured ] sphere, %u tets, mean edge %.4f, %s: phong rms fit %.3e average %.3e "
                "(%.2fx), max fit %.3e average %.3e; linear rms %.3e\n",
                mesh->numCells(), meanEdgeLength(*mesh), names[k], fit.rms[2], average.rms[2],
                average.rms[2] / fit.rms[2], fit.max[2], average.max[2], fit.rms[0]);
    EXPECT_LT(fit.rms[2], average.rms[2]) << names[k];
    EXPECT_LT(fit.max[2], average.max[2]) << names[k];
  }
}

TEST(TetGenIrregular, EveryPointFiniteInsideAndOutside) {
  const VolumeMesh mesh = tetgenBox("phong_tetgen_outside");
  ASSERT_GT(mesh.numCells(), 1000u);
  // Points up to twice the box size: a quarter of them outside the mesh.
  const Points points = ballPoints(4000, 3.5, 8);
  EmbeddedDeformer deformer(mesh, points);
  EXPECT_GT(deformer.embedding().outsideCount, 500u);
  Points nodes(mesh.positions.rows(), 3);
  for (Eigen::Index i = 0; i < nodes.rows(); ++i)
    nodes.row(i) = bendAndTwist(0.25 * mesh.positions.row(i).transpose()).transpose();
  for (InterpolationMethod method : kAllMethods) {
    deformer.setFrame(nodes, method);
    EXPECT_TRUE(deformer.positions().allFinite()) << methodName(method);
    EXPECT_TRUE(deformer.positionsSinglePrecision().allFinite()) << methodName(method);
  }
  for (const Eigen::Matrix3d& F : deformer.nodeGradients()) EXPECT_TRUE(F.allFinite());
}

}  // namespace
}  // namespace sculpt
