// Rigid motion of the rest shape gives zero internal force and zero energy once the element
// rotations are updated (docs/design/local-frame-fem.md, "Proof"), for each element type on its
// own: the mesh is filtered to one type so no other element can hide or cancel a residual.

#include <gtest/gtest.h>

#include <Eigen/Geometry>
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
#include "support/mesh_builders.h"

namespace sculpt {
namespace {

using namespace sculpt::test;

/// The elements of `mesh` of one type, with their rest data (same nodes).
FemMesh onlyType(const FemMesh& m, ElementType type) {
  FemMesh out;
  out.nodeStencils = m.nodeStencils;
  out.numLatticeNodes = m.numLatticeNodes;
  out.restNodes = m.restNodes;
  for (uint32_t e = 0; e < m.numElements(); ++e) {
    if (m.elementType[e] != type) continue;
    out.elementType.push_back(type);
    out.elementCell.push_back(m.elementCell[e]);
    if (e < m.numTricubic()) {
      out.tricubicNodes.push_back(m.tricubicNodes[e]);
      out.tricubicCentreInverseJacobian.push_back(m.tricubicCentreInverseJacobian[e]);
      for (uint32_t q = 0; q < 64; ++q)
        out.tricubicInverseJacobian.push_back(m.tricubicInverseJacobian[size_t(e) * 64 + q]);
    } else {
      const uint32_t l = e - m.numTricubic();
      out.linearNodes.push_back(m.linearNodes[l]);
      out.linearCentreShapeGradient.push_back(m.linearCentreShapeGradient[l]);
      for (uint32_t q = 0; q < 8; ++q)
        out.linearShapeGradient.push_back(m.linearShapeGradient[size_t(l) * 8 + q]);
    }
    for (uint32_t q = m.gaussBegin(e); q < m.gaussBegin(e) + m.gaussCount(e); ++q) {
      out.gaussVolume.push_back(m.gaussVolume[q]);
      out.gaussRestPosition.push_back(m.gaussRestPosition[q]);
      out.gaussMaterial.push_back(m.gaussMaterial[q]);
      out.gaussLame.push_back(m.gaussLame[q]);
    }
  }
  return out;
}

struct RigidMotion {
  std::string name;
  Eigen::Matrix3d Q;
  Eigen::Vector3d t;
};

std::vector<RigidMotion> rigidMotions() {
  using std::numbers::pi;
  std::vector<RigidMotion> motions;
  auto aa = [](double angle, Eigen::Vector3d axis) {
    return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
  };
  const Eigen::Vector3d t(3.0, -2.0, 5.0);
  for (int axis = 0; axis < 3; ++axis) {
    motions.push_back(
        {"90 deg about axis " + std::to_string(axis), aa(pi / 2, Eigen::Vector3d::Unit(axis)), t});
    motions.push_back(
        {"180 deg about axis " + std::to_string(axis), aa(pi, Eigen::Vector3d::Unit(axis)), -t});
  }
  motions.push_back({"180 deg about (1,1,1)", aa(pi, {1, 1, 1}), t});
  motions.push_back({"120 deg about (1,-2,0.5)", aa(2 * pi / 3, {1, -2, 0.5}), t});
  motions.push_back({"179.9 deg about (0.3,1,-1)", aa(pi - 1e-3, {0.3, 1, -1}), {0, 0, 0}});
  std::mt19937_64 rng(99);
  for (int k = 0; k < 3; ++k)
    motions.push_back({"random rotation " + std::to_string(k), randomRotation(rng),
                       Eigen::Vector3d(10, 20, -30)});
  motions.push_back({"translation only", Eigen::Matrix3d::Identity(), t});
  return motions;
}

/// The level-K nodes of `model` after moving its control points rigidly by `m`.
Points movedNodes(const FemModel& model, const RigidMotion& m) {
  Points control = model.restControl();
  for (Eigen::Index i = 0; i < control.rows(); ++i)
    control.row(i) = (m.Q * control.row(i).transpose() + m.t).transpose();
  Points nodes;
  model.nodesFromControl(control, nodes);
  return nodes;
}

struct Case {
  std::string name;
  CellComplex control;
  int level;
  bool trilinear;
};

std::vector<Case> cases() {
  return {
      {"jittered 2x2x2 hex grid, level 2", jittered(hexGrid(2, 2, 2, 0.5), 0.05, 3), 2, false},
      {"jittered 3x3x3 hex grid, trilinear mode", jittered(hexGrid(3, 3, 3), 0.2, 4), 0, true},
      {"pyramid cube, trilinear mode", pyramidCube({0.3, 0.6, 0.45}), 0, true},
      {"octahedron, trilinear mode", octahedron(), 0, true},
      {"jittered mixed mesh, trilinear mode", jittered(mixedMesh(), 0.05, 8), 0, true},
      {"octahedron, level 1", octahedron(), 1, false},
      {"jittered mixed mesh, level 2", jittered(mixedMesh(), 0.05, 8), 2, false},
  };
}

TEST(RigidMotion, ZeroForceAndEnergyForEveryElementType) {
  const Material material;  // E = 1e5 Pa
  bool seen[3] = {false, false, false};
  double worstForce[3] = {0, 0, 0}, worstEnergy[3] = {0, 0, 0}, worstRotation[3] = {0, 0, 0};
  for (const Case& c : cases()) {
    std::string error;
    auto model = FemModel::create(c.control, FemSetup{c.level, c.trilinear, material}, &error);
    ASSERT_TRUE(model) << c.name << ": " << error;
    // The nodes of the rest control points are the rest nodes (A reproduces them).
    Points restNodes;
    model->nodesFromControl(model->restControl(), restNodes);
    ASSERT_LT((restNodes - model->mesh().restNodes).cwiseAbs().maxCoeff(), 1e-13) << c.name;
    for (ElementType type : {ElementType::Tricubic, ElementType::Trilinear, ElementType::Pyramid}) {
      const FemMesh sub = onlyType(model->mesh(), type);
      if (sub.numElements() == 0) continue;
      const int ti = int(type);
      seen[ti] = true;
      ElasticKernel kernel(sub);
      const double volume = sub.restVolume();
      const double L = std::cbrt(volume / sub.numElements());  // characteristic element size
      const double forceScale = material.youngs * L * L;       // force of a unit strain
      const double energyScale = material.youngs * volume;     // energy of a unit strain
      for (const RigidMotion& m : rigidMotions()) {
        const Points nodes = movedNodes(*model, m);
        kernel.updateRotations(nodes);
        double rotationError = 0;
        for (const Eigen::Matrix3d& R : kernel.rotations())
          rotationError = std::max(rotationError, (R - m.Q).cwiseAbs().maxCoeff());
        Points gradient = Points::Zero(nodes.rows(), 3);
        kernel.addGradient(nodes, gradient);
        const double force = gradient.cwiseAbs().maxCoeff() / forceScale;
        const double energy = kernel.energy(nodes) / energyScale;
        EXPECT_LT(force, 1e-9) << c.name << ", " << elementTypeName(type) << ", " << m.name;
        EXPECT_LT(std::abs(energy), 1e-20)
            << c.name << ", " << elementTypeName(type) << ", " << m.name;
        EXPECT_LT(rotationError, 1e-12)
            << c.name << ", " << elementTypeName(type) << ", " << m.name;
        worstForce[ti] = std::max(worstForce[ti], force);
        worstEnergy[ti] = std::max(worstEnergy[ti], std::abs(energy));
        worstRotation[ti] = std::max(worstRotation[ti], rotationError);
      }
      // Sensitivity: without the local frames a 90-degree turn is a huge strain.
      kernel.resetRotations();
      Points control = model->restControl();
      const Eigen::Matrix3d Q = rigidMotions()[0].Q;
      for (Eigen::Index i = 0; i < control.rows(); ++i)
        control.row(i) = (Q * control.row(i).transpose()).transpose();
      Points nodes;
      model->nodesFromControl(control, nodes);
      Points gradient = Points::Zero(nodes.rows(), 3);
      kernel.addGradient(nodes, gradient);
      EXPECT_GT(gradient.cwiseAbs().maxCoeff() / forceScale, 1e-3) << c.name;
      std::printf("%-42s %-9s %4u elements: unrotated 90 deg force/(E L^2) = %.3g\n",
                  c.name.c_str(), elementTypeName(type), sub.numElements(),
                  gradient.cwiseAbs().maxCoeff() / forceScale);
    }
  }
  for (int ti = 0; ti < 3; ++ti) {
    EXPECT_TRUE(seen[ti]) << elementTypeName(ElementType(ti)) << " never tested";
    std::printf(
        "%-9s: worst max|gradient|/(E L^2) = %.3g, worst energy/(E V) = %.3g, worst "
        "|R_e - Q| = %.3g over %zu motions\n",
        elementTypeName(ElementType(ti)), worstForce[ti], worstEnergy[ti], worstRotation[ti],
        rigidMotions().size());
  }
}

TEST(RigidMotion, WholeModelThroughControlPoints) {
  // The full model (all types together) with the gradient projected to control points by A^T.
  std::string error;
  auto model = FemModel::create(jittered(mixedMesh(), 0.05, 8), FemSetup{}, &error);
  ASSERT_TRUE(model) << error;
  ElasticKernel& kernel = model->elastic();
  const double L = std::cbrt(model->mesh().restVolume() / model->mesh().numElements());
  double worst = 0;
  for (const RigidMotion& m : rigidMotions()) {
    const Points nodes = movedNodes(*model, m);
    kernel.updateRotations(nodes);
    Points gradient = Points::Zero(nodes.rows(), 3);
    kernel.addGradient(nodes, gradient);
    Points reduced = Points::Zero(model->restControl().rows(), 3);
    model->addToControl(gradient, reduced);
    worst = std::max(worst, reduced.cwiseAbs().maxCoeff() / (Material{}.youngs * L * L));
  }
  EXPECT_LT(worst, 1e-9);
  std::printf("mixed mesh level 2, reduced to control points: worst max|A^T g|/(E L^2) = %.3g\n",
              worst);
}

}  // namespace
}  // namespace sculpt
