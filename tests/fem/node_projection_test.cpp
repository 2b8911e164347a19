// FemModel::nodesFromControl and addToControl go level by level (the stencil chain, then the
// virtual centre nodes) instead of through the composed A: they must equal A p and A^T f with
// the composed matrix, on meshes with and without virtual centre nodes and in trilinear mode.
#include <gtest/gtest.h>

#include <random>
#include <string>

#include "fem/fem_model.h"
#include "sim/linear_stiffness.h"
#include "support/fem_builders.h"
#include "support/mesh_builders.h"

namespace sculpt {
namespace {

using namespace sculpt::test;

void expectProjectionsEqualTheComposedMatrix(const CellComplex& control, int level,
                                             bool trilinear, const std::string& name) {
  auto model = buildModel(control, level, trilinear);
  ASSERT_TRUE(model) << name;
  const SparseMatrix& A = model->stencilMatrix();
  ASSERT_EQ(A.rows(), model->numNodes()) << name;
  std::mt19937_64 rng(5);
  const Points p = randomPoints(model->numControlPoints(), 1.0, rng);
  const Points f = randomPoints(model->numNodes(), 1.0, rng);

  Points nodes;
  model->nodesFromControl(p, nodes);
  const Points expectedNodes = A * p;
  const double nodeError = (nodes - expectedNodes).cwiseAbs().maxCoeff();
  EXPECT_LT(nodeError, 1e-13) << name;

  const Points start = randomPoints(model->numControlPoints(), 1.0, rng);
  Points projected = start;
  model->addToControl(f, projected);
  const Points expectedControl = start + Points(A.transpose() * f);
  const double controlError = (projected - expectedControl).cwiseAbs().maxCoeff();
  EXPECT_LT(controlError, 1e-12 * double(f.rows())) << name;
  std::printf("%s: %u nodes from %u control points, |A p - chain| %.2g, |A^T f - chain| %.2g\n",
              name.c_str(), model->numNodes(), model->numControlPoints(), nodeError, controlError);
}

TEST(NodeProjection, BlockAtLevelsOneToThree) {
  for (int level = 1; level <= 3; ++level)
    expectProjectionsEqualTheComposedMatrix(block3(), level, false,
                                            "block3 K=" + std::to_string(level));
}

TEST(NodeProjection, MeshWithVirtualCentreNodes) {
  for (int level = 1; level <= 2; ++level)
    expectProjectionsEqualTheComposedMatrix(mixedMesh(), level, false,
                                            "mixed mesh K=" + std::to_string(level));
  expectProjectionsEqualTheComposedMatrix(octahedron(), 1, false, "octahedron K=1");
}

TEST(NodeProjection, TrilinearModeIsTheIdentityWithCentres) {
  expectProjectionsEqualTheComposedMatrix(block3(), 0, true, "block3 trilinear");
  expectProjectionsEqualTheComposedMatrix(mixedMesh(), 0, true, "mixed mesh trilinear");
}

}  // namespace
}  // namespace sculpt
