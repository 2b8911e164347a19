// Picking on the CPU (scene/material_picker.h): a point of the deformed cells maps back to the rest
// point with the same local coordinates. Under an affine deformation x = F X + t, which both cell
// kinds reproduce exactly, the rest point of x is F^-1 (x - t); points outside the solid by more
// than the tolerance have no material.

#include "scene/material_picker.h"

#include <gtest/gtest.h>

#include <random>

#include "mesh/lattice_mesh.h"

namespace sculpt {
namespace {

void expectAffineInverse(const VolumeMesh& rest) {
  Eigen::Matrix3d F;
  F << 1.2, 0.3, 0.0, -0.2, 0.9, 0.1, 0.05, 0.0, 1.1;
  const Eigen::Vector3d t(0.5, -1.0, 2.0);
  const Points nodes = ((rest.positions * F.transpose()).rowwise() + t.transpose()).eval();
  const MaterialPicker picker(rest, nodes);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> inside(0.05, 2.95);
  double worst = 0.0;
  for (int i = 0; i < 200; ++i) {
    const Eigen::Vector3d X(inside(random), inside(random), inside(random));
    const std::optional<Eigen::Vector3d> found = picker.restPoint(F * X + t, 0.1);
    ASSERT_TRUE(found.has_value());
    worst = std::max(worst, (*found - X).norm());
  }
  EXPECT_LT(worst, 1e-9);
  EXPECT_FALSE(picker.restPoint(F * Eigen::Vector3d(10, 1, 1) + t, 0.1).has_value());
  EXPECT_FALSE(picker.restPoint(Eigen::Vector3d::Constant(std::nan("")), 0.1).has_value());
}

TEST(MaterialPicker, HexahedraMapDeformedPointsBackToTheirRestPoints) {
  LatticeSpec spec;
  spec.cubes = {3, 3, 3};
  expectAffineInverse(hexLattice(spec));
}

TEST(MaterialPicker, TetrahedraMapDeformedPointsBackToTheirRestPoints) {
  LatticeSpec spec;
  spec.cubes = {3, 3, 3};
  expectAffineInverse(tetLattice(spec));
}

}  // namespace
}  // namespace sculpt
