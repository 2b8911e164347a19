// The preconditioner's stiffness brought to new materials by assembling only the elements whose
// materials changed (sim/assembled_stiffness.h), against the same stiffness assembled whole:
// both kinds (the stand-in and the elements' own rest stiffness), every element kind, materials
// that vary inside an element, and a dab undone.

#include "sim/assembled_stiffness.h"

#include <gtest/gtest.h>

#include <Eigen/SparseCore>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <limits>
#include <filesystem>
#include <memory>

#include "support/fem_builders.h"
#include "support/painted_mixed_model.h"

namespace sculpt {
namespace {

// max |a - b| / max |b| over the entries; infinity when the patterns differ.
double relativeDifference(const SparseMatrix& a, const SparseMatrix& b) {
  if (a.rows() != b.rows() || a.cols() != b.cols() || a.nonZeros() != b.nonZeros())
    return std::numeric_limits<double>::infinity();
  double largest = 0, difference = 0;
  for (Eigen::Index column = 0; column < b.outerSize(); ++column) {
    SparseMatrix::InnerIterator ia(a, column), ib(b, column);
    for (; ib; ++ia, ++ib) {
      if (!ia || ia.row() != ib.row()) return std::numeric_limits<double>::infinity();
      largest = std::max(largest, std::abs(ib.value()));
      difference = std::max(difference, std::abs(ia.value() - ib.value()));
    }
  }
  return difference / largest;
}

class AssembledStiffnessTest : public ::testing::TestWithParam<bool> {
 protected:
  bool rest() const { return GetParam(); }
  AssembledStiffness assembled(const FemModel& model) const {
    const FemMesh& mesh = model.mesh();
    return {assembleStiffness(mesh, mesh.gaussLame, model.stencilMatrix(), rest()),
            mesh.gaussLame, rest()};
  }
};

TEST_P(AssembledStiffnessTest, ADabAssembledAloneIsTheWholeAssembly) {
  auto model = test::paintedMixedModel(Material{.youngs = 7e5, .poisson = 0.45});
  ASSERT_TRUE(model);
  const AssembledStiffness before = assembled(*model);
  // A second dab off the centre, across elements of every kind (part of each element only).
  const Material second{.youngs = 3e4, .poisson = 0.2};
  const Eigen::Vector3d corner = model->restControl().colwise().minCoeff().transpose();
  const Eigen::Vector3d centre = model->restControl().colwise().mean().transpose();
  ASSERT_GT(model->paintMaterial(0.5 * (corner + centre), 0.7, second), 0);
  const FemMesh& mesh = model->mesh();
  const SparseMatrix updated = stiffnessAt(mesh, before, mesh.gaussLame, model->stencilMatrix());
  const SparseMatrix whole = assembleStiffness(mesh, mesh.gaussLame, model->stencilMatrix(), rest());
  const double difference = relativeDifference(updated, whole);
  std::printf("[ %s ] the dab's elements alone against the whole: %.2e\n",
              rest() ? "rest stiffness" : "stand-in", difference);
  EXPECT_LT(difference, 1e-13);
  // It did change: the first matrix is not the answer.
  EXPECT_GT(relativeDifference(before.matrix, whole), 1e-3);
}

TEST_P(AssembledStiffnessTest, UnchangedMaterialsGiveTheSameMatrixAndAnUndoneDabTheFirst) {
  // block4 at level 1: affine tricubic elements whose parts are shared, and trilinear ones.
  auto model = test::buildModel(
      loadControlMeshJson(std::filesystem::path(SCULPT_SOURCE_DIR) / "assets/table1/block4.json"),
      1, false);
  ASSERT_TRUE(model);
  const FemMesh& mesh = model->mesh();
  const SparseMatrix& A = model->stencilMatrix();
  const AssembledStiffness first = assembled(*model);
  const SparseMatrix same = stiffnessAt(mesh, first, mesh.gaussLame, A);
  EXPECT_EQ(relativeDifference(same, first.matrix), 0.0);

  const std::vector<LameParameters> original = mesh.gaussLame;
  const Material stiffer{.youngs = 1e6};
  ASSERT_GT(model->paintMaterial(model->restControl().row(5).transpose(), 1.0, stiffer), 0);
  const AssembledStiffness painted{stiffnessAt(mesh, first, mesh.gaussLame, A), mesh.gaussLame,
                                   rest()};
  EXPECT_LT(relativeDifference(painted.matrix,
                               assembleStiffness(mesh, mesh.gaussLame, A, rest())),
            1e-13);
  // Undone (the materials as they were): the first matrix again, to rounding.
  const SparseMatrix undone = stiffnessAt(mesh, painted, original, A);
  EXPECT_LT(relativeDifference(undone, first.matrix), 1e-13);
}

TEST_P(AssembledStiffnessTest, MostElementsChangedIsAssembledWhole) {
  auto model = test::buildModel(test::block3(), 1, false);
  ASSERT_TRUE(model);
  const FemMesh& mesh = model->mesh();
  const AssembledStiffness first = assembled(*model);
  std::vector<LameParameters> doubled = mesh.gaussLame;
  for (LameParameters& p : doubled) p = {2 * p.lambda, 2 * p.mu};
  const SparseMatrix updated = stiffnessAt(mesh, first, doubled, model->stencilMatrix());
  // Bit for bit what a whole assembly gives: no difference added to the old matrix.
  EXPECT_EQ(relativeDifference(updated,
                               assembleStiffness(mesh, doubled, model->stencilMatrix(), rest())),
            0.0);
  const std::atomic<bool> stop{true};
  std::vector<LameParameters> one = mesh.gaussLame;
  one[0].mu *= 2;
  EXPECT_EQ(stiffnessAt(mesh, first, one, model->stencilMatrix(), &stop).size(), 0);
}

INSTANTIATE_TEST_SUITE_P(Kinds, AssembledStiffnessTest, ::testing::Values(false, true),
                         [](const ::testing::TestParamInfo<bool>& kind) {
                           return kind.param ? "RestStiffness" : "StandIn";
                         });

}  // namespace
}  // namespace sculpt
