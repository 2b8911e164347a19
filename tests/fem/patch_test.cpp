// Patch tests (docs/design/local-frame-fem.md, "Proof"): an affine deformation x = F X + t of a
// distorted trilinear mesh gives the same strain at every Gauss point, so
//   - the energy is V (mu eps:eps + lambda/2 tr(eps)^2) with V the exact volume,
//   - nodes off the boundary get no force (constant stress is in equilibrium),
//   - the boundary forces are the tractions of that stress: sum_a g_a X_a^T = V R sigma.
// Linear form (rotations reset): eps = sym(F) - I. Co-rotated form with F = R S: eps = S - I.
// Plus exact energies of non-affine (bilinear, trilinear) displacement fields on a cube.

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <Eigen/LU>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "fem/elastic_kernel.h"
#include "fem/fem_mesh.h"
#include "fem/fem_model.h"
#include "fem/material.h"
#include "support/mesh_builders.h"

namespace sculpt {
namespace {

using namespace sculpt::test;

struct Lame {
  double lambda, mu;
};
/// Lame parameters from the textbook formulas (not lameParameters()).
Lame lame(const Material& m) {
  const double E = m.youngs, nu = m.poisson;
  return {E * nu / ((1 + nu) * (1 - 2 * nu)), E / (2 * (1 + nu))};
}

double energyDensity(const Eigen::Matrix3d& eps, const Lame& l) {
  return l.mu * (eps.array() * eps.array()).sum() + 0.5 * l.lambda * eps.trace() * eps.trace();
}

Eigen::Matrix3d stress(const Eigen::Matrix3d& eps, const Lame& l) {
  return 2 * l.mu * eps + l.lambda * eps.trace() * Eigen::Matrix3d::Identity();
}

Points affine(const Points& X, const Eigen::Matrix3d& F, const Eigen::Vector3d& t) {
  Points x(X.rows(), 3);
  for (Eigen::Index i = 0; i < X.rows(); ++i) x.row(i) = (F * X.row(i).transpose() + t).transpose();
  return x;
}

struct PatchResult {
  double energyError = 0;    ///< relative
  double interiorForce = 0;  ///< max |g| at interior nodes / (E L^2 |eps|)
  double virialError = 0;    ///< relative
  double netForce = 0;       ///< |sum g| / (E L^2 |eps|)
  double rotationError = 0;
  int interiorNodes = 0;
};

/// Deforms the model's control points by x = F X + t (nodes follow through A) and compares
/// with the constant-strain prediction. `corotated`: rotations from updateRotations, whose
/// expected value is `R`; otherwise rotations reset (R = I).
PatchResult patch(FemModel& model, double exactVolume, const Eigen::Matrix3d& F,
                  const Eigen::Vector3d& t, bool corotated) {
  PatchResult r;
  const Material material;
  const Lame l = lame(material);
  ElasticKernel& kernel = model.elastic();
  Points nodes;
  model.nodesFromControl(affine(model.restControl(), F, t), nodes);
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity(), eps;
  if (corotated) {
    // Independent polar decomposition: R = F (F^T F)^(-1/2).
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(F.transpose() * F);
    const Eigen::Matrix3d S = es.eigenvectors() * es.eigenvalues().cwiseSqrt().asDiagonal() *
                              es.eigenvectors().transpose();
    R = F * S.inverse();
    eps = S - Eigen::Matrix3d::Identity();
    kernel.updateRotations(nodes);
    for (const Eigen::Matrix3d& Re : kernel.rotations())
      r.rotationError = std::max(r.rotationError, (Re - R).cwiseAbs().maxCoeff());
  } else {
    kernel.resetRotations();
    eps = 0.5 * (F + F.transpose()) - Eigen::Matrix3d::Identity();
  }
  const double expected = exactVolume * energyDensity(eps, l);
  r.energyError = std::abs(kernel.energy(nodes) - expected) / expected;

  Points g = Points::Zero(nodes.rows(), 3);
  kernel.addGradient(nodes, g);
  const FemMesh& mesh = model.mesh();
  const double L = std::cbrt(exactVolume / mesh.numElements());
  const double scale = material.youngs * L * L * eps.norm();
  const Topology& topology = model.subdivision().finestTopology();
  for (uint32_t n = 0; n < mesh.numNodes(); ++n) {
    const bool interior = n >= mesh.numLatticeNodes || !topology.vertexIsBoundary[n];
    if (!interior) continue;
    ++r.interiorNodes;
    r.interiorForce = std::max(r.interiorForce, g.row(n).norm() / scale);
  }
  r.netForce = g.colwise().sum().norm() / scale;
  // sum_a g_a X_a^T = sum_q V_q R sigma (sum_a grad N_a X_a^T) = V R sigma.
  const Eigen::Matrix3d virial = g.transpose() * mesh.restNodes;
  const Eigen::Matrix3d predicted = exactVolume * R * stress(eps, l);
  r.virialError = (virial - predicted).norm() / predicted.norm();
  return r;
}

struct Deformation {
  std::string name;
  Eigen::Matrix3d F;
};

std::vector<Deformation> deformations(bool corotated) {
  std::mt19937_64 rng(1234);
  std::uniform_real_distribution<double> uni(-1, 1);
  auto randomMatrix = [&] {
    Eigen::Matrix3d M;
    for (int i = 0; i < 9; ++i) M(i / 3, i % 3) = uni(rng);
    return M;
  };
  std::vector<Deformation> out;
  if (!corotated) {
    out.push_back({"small", Eigen::Matrix3d::Identity() + 1e-3 * randomMatrix()});
    out.push_back({"large", Eigen::Matrix3d::Identity() + 0.4 * randomMatrix()});
    out.push_back({"uniaxial", Eigen::Vector3d(1.5, 1, 1).asDiagonal().toDenseMatrix()});
  } else {
    for (double size : {1e-3, 0.3}) {
      const Eigen::Matrix3d M = randomMatrix();
      const Eigen::Matrix3d S = Eigen::Matrix3d::Identity() + size * 0.5 * (M + M.transpose());
      out.push_back(
          {size < 0.01 ? "R * small stretch" : "R * large stretch", randomRotation(rng) * S});
    }
    out.push_back({"180 deg * stretch",
                   Eigen::AngleAxisd(std::numbers::pi, Eigen::Vector3d(1, 2, 3).normalized())
                           .toRotationMatrix() *
                       Eigen::Vector3d(0.7, 1.2, 1.05).asDiagonal().toDenseMatrix()});
  }
  for (const auto& d : out) EXPECT_GT(d.F.determinant(), 0.1) << d.name;
  return out;
}

struct PatchMesh {
  std::string name;
  CellComplex control;
};

std::vector<PatchMesh> patchMeshes() {
  return {{"jittered 3x3x3 hexes", jittered(hexGrid(3, 3, 3), 0.2, 5)},
          {"jittered 2x2x2 hexes (h = 0.5)", jittered(hexGrid(2, 2, 2, 0.5), 0.1, 6)},
          {"jittered mixed mesh (hexes + pyramids)", jittered(mixedMesh(), 0.05, 7)}};
}

void runPatchTests(bool corotated) {
  for (const PatchMesh& pm : patchMeshes()) {
    std::string error;
    auto model = FemModel::create(pm.control, FemSetup{0, true, Material{}}, &error);
    ASSERT_TRUE(model) << error;
    double exactVolume = 0;  // divergence theorem over the bilinear faces
    for (uint32_t c = 0; c < pm.control.numCells(); ++c) exactVolume += signedVolume(pm.control, c);
    for (const Deformation& d : deformations(corotated)) {
      const PatchResult r = patch(*model, exactVolume, d.F, {0.1, -0.2, 0.3}, corotated);
      const std::string what = pm.name + ", " + d.name;
      EXPECT_LT(r.energyError, 1e-10) << what;
      EXPECT_LT(r.interiorForce, 1e-9) << what;
      EXPECT_LT(r.virialError, 1e-10) << what;
      EXPECT_LT(r.netForce, 1e-9) << what;
      EXPECT_LT(r.rotationError, 1e-12) << what;
      EXPECT_GT(r.interiorNodes, 0) << what;
      std::printf(
          "%s patch, %-40s %-18s energy rel.err %.2g, %d interior nodes max "
          "|g|/(E L^2 |eps|) %.2g, virial rel.err %.2g, net force %.2g, |R_e - R| %.2g\n",
          corotated ? "co-rotated" : "linear", pm.name.c_str(), d.name.c_str(), r.energyError,
          r.interiorNodes, r.interiorForce, r.virialError, r.netForce, r.rotationError);
    }
  }
}

TEST(PatchTest, LinearAffineDeformationOfDistortedMesh) { runPatchTests(false); }

TEST(PatchTest, CorotatedAffineDeformationOfDistortedMesh) { runPatchTests(true); }

TEST(PatchTest, TricubicModelEnergyAndVirialAreExactForAffineFields) {
  // Level 2 of a jittered grid: tricubic, trilinear elements on distorted lattices (A
  // reproduces affine maps, B-splines and trilinear shapes reproduce affine fields).
  std::string error;
  auto model = FemModel::create(jittered(hexGrid(2, 2, 2, 0.5), 0.05, 3),
                                FemSetup{2, false, Material{}}, &error);
  ASSERT_TRUE(model) << error;
  ASSERT_GT(model->mesh().counts().tricubic, 0u);
  const Lame l = lame(Material{});
  const double V = model->mesh().restVolume();  // the elements' own volume (they overlap)
  for (bool corotated : {false, true}) {
    for (const Deformation& d : deformations(corotated)) {
      ElasticKernel& kernel = model->elastic();
      Points nodes;
      model->nodesFromControl(affine(model->restControl(), d.F, {1, 2, 3}), nodes);
      Eigen::Matrix3d R = Eigen::Matrix3d::Identity(), eps;
      if (corotated) {
        kernel.updateRotations(nodes);
        R = kernel.rotations()[0];
        eps = R.transpose() * d.F - Eigen::Matrix3d::Identity();
        EXPECT_LT((0.5 * (eps - eps.transpose())).norm(), 1e-12);
      } else {
        kernel.resetRotations();
        eps = 0.5 * (d.F + d.F.transpose()) - Eigen::Matrix3d::Identity();
      }
      const double expected = V * energyDensity(eps, l);
      const double energyError = std::abs(kernel.energy(nodes) - expected) / expected;
      Points g = Points::Zero(nodes.rows(), 3);
      kernel.addGradient(nodes, g);
      const Eigen::Matrix3d virial = g.transpose() * model->mesh().restNodes;
      const Eigen::Matrix3d predicted = V * R * stress(eps, l);
      const double virialError = (virial - predicted).norm() / predicted.norm();
      EXPECT_LT(energyError, 1e-10) << d.name;
      EXPECT_LT(virialError, 1e-10) << d.name;
      std::printf("level-2 model (%u tricubic), %s: energy rel.err %.2g, virial rel.err %.2g\n",
                  model->mesh().counts().tricubic, d.name.c_str(), energyError, virialError);
    }
  }
}

TEST(PatchTest, ExactEnergyOfBilinearAndTrilinearDisplacements) {
  // Displacements that trilinear hexahedra represent exactly on the unit cube, with energies
  // integrated by hand (2x2x2 Gauss is exact for these degree-2 integrands):
  //   u = (c x y, 0, 0):    eps:eps = c^2 (y^2 + x^2 / 2),            tr = c y
  //                         E = c^2 (mu / 2 + lambda / 6)
  //   u = (c x y z, 0, 0):  eps:eps = c^2 (y^2 z^2 + (x^2 z^2 + x^2 y^2) / 2), tr = c y z
  //                         E = c^2 (2 mu / 9 + lambda / 18)
  const Lame l = lame(Material{});
  const double c = 1e-3;
  const double exactBilinear = c * c * (l.mu / 2 + l.lambda / 6);
  const double exactTrilinear = c * c * (2 * l.mu / 9 + l.lambda / 18);
  for (int n : {1, 2, 3}) {
    std::string error;
    auto model = FemModel::create(hexGrid(n, n, n, 1.0 / n), FemSetup{0, true, Material{}}, &error);
    ASSERT_TRUE(model) << error;
    model->elastic().resetRotations();
    const Points& X = model->restControl();
    Points bilinear = X, trilinear = X;
    for (Eigen::Index i = 0; i < X.rows(); ++i) {
      bilinear(i, 0) += c * X(i, 0) * X(i, 1);
      trilinear(i, 0) += c * X(i, 0) * X(i, 1) * X(i, 2);
    }
    const double eb = model->elastic().energy(bilinear);
    const double et = model->elastic().energy(trilinear);
    EXPECT_NEAR(eb, exactBilinear, 1e-12 * exactBilinear) << n;
    EXPECT_NEAR(et, exactTrilinear, 1e-12 * exactTrilinear) << n;
    std::printf(
        "%d^3 cube: u = c x y energy %.15g (exact %.15g); u = c x y z energy %.15g "
        "(exact %.15g)\n",
        n, eb, exactBilinear, et, exactTrilinear);
  }
}

}  // namespace
}  // namespace sculpt
