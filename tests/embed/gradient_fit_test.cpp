// The quadratic-fit node gradients (embed/gradient_fit.h): exact for quadratic maps at every node
// that the fit reaches, boundary and corner nodes included (where the paper's averaging is not),
// exact for rigid motions, the averaging kept where no ring qualifies, and rings that grow only
// where the first one cannot determine a quadratic.

#include "embed/gradient_fit.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cstdio>

#include "embed/gradient_scheme.h"
#include "embed/solid_cell_mesh.h"
#include "io/control_mesh_json.h"
#include "mesh/lattice_mesh.h"
#include "subdiv/mj_refiner.h"

namespace sculpt {
namespace {

/// A quadratic map and its exact gradient.
Eigen::Vector3d quadraticMap(const Eigen::Vector3d& X) {
  return Eigen::Vector3d(1.1 * X.x() + 0.2 * X.y() + 0.7 * X.x() * X.y() - 0.4 * X.z() * X.z(),
                         0.9 * X.y() - 0.3 * X.z() + 0.5 * X.x() * X.x() + 0.6 * X.y() * X.z(),
                         1.2 * X.z() + 0.1 * X.x() - 0.8 * X.y() * X.y() + 0.3 * X.x() * X.z());
}

Eigen::Matrix3d quadraticGradient(const Eigen::Vector3d& X) {
  Eigen::Matrix3d F;
  F << 1.1 + 0.7 * X.y(), 0.2 + 0.7 * X.x(), -0.8 * X.z(),  //
      X.x(), 0.9 + 0.6 * X.z(), -0.3 + 0.6 * X.y(),         //
      0.1 + 0.3 * X.z(), -1.6 * X.y(), 1.2 + 0.3 * X.x();
  return F;
}

Points mapped(const VolumeMesh& mesh, Eigen::Vector3d (*map)(const Eigen::Vector3d&)) {
  Points out(mesh.positions.rows(), 3);
  for (Eigen::Index i = 0; i < out.rows(); ++i)
    out.row(i) = map(mesh.positions.row(i).transpose()).transpose();
  return out;
}

struct LatticeCase {
  const char* name;
  VolumeMesh mesh;
};

std::vector<LatticeCase> lattices() {
  LatticeSpec spec;
  spec.cubes = {4, 3, 5};
  spec.spacing = 0.2;
  spec.origin = Eigen::Vector3d(-0.3, -0.2, -0.5);
  VolumeMesh jitteredTets = tetLattice(spec);
  jitterLattice(jitteredTets, spec, 0.15, 3);
  VolumeMesh jitteredHexes = hexLattice(spec);
  jitterLattice(jitteredHexes, spec, 0.15, 4);
  return {{"tets", tetLattice(spec)},
          {"hexes", hexLattice(spec)},
          {"jittered tets", std::move(jitteredTets)},
          {"jittered hexes", std::move(jitteredHexes)}};
}

/// Largest |F_i - grad phi(X_i)| over the nodes (Frobenius).
double worstGradientError(const VolumeMesh& mesh, const NodeGradientStencil& stencil) {
  std::vector<Eigen::Matrix3d> gradients;
  applyNodeGradientStencil(stencil, mapped(mesh, quadraticMap), gradients);
  double worst = 0.0;
  for (uint32_t i = 0; i < mesh.numNodes(); ++i)
    worst = std::max(worst,
                     (gradients[i] - quadraticGradient(mesh.positions.row(i).transpose())).norm());
  return worst;
}

TEST(GradientFit, ExactForQuadraticMapsAtEveryNodeBoundaryIncluded) {
  for (const LatticeCase& lattice : lattices()) {
    GradientFitReport report;
    const NodeGradientStencil fit = quadraticFitStencil(
        lattice.mesh, nodeGradientStencil(lattice.mesh, GradientScheme::Average), &report);
    const double fitError = worstGradientError(lattice.mesh, fit);
    const double averageError = worstGradientError(
        lattice.mesh, nodeGradientStencil(lattice.mesh, GradientScheme::Average));
    std::printf(
        "[ measured ] %s: %u nodes, ring 1/2/3 %u/%u/%u, fallbacks %u; worst |F - grad phi| "
        "fit %.2e, average %.2e\n",
        lattice.name, lattice.mesh.numNodes(), report.ringCounts[1], report.ringCounts[2],
        report.ringCounts[3], report.fallbacks, fitError, averageError);
    EXPECT_EQ(report.fallbacks, 0u) << lattice.name;
    EXPECT_LT(fitError, 1e-10) << lattice.name;
    // The averaging is first-order at the boundary: the fit is what makes the difference.
    EXPECT_GT(averageError, 1e-2) << lattice.name;
  }
}

TEST(GradientFit, ExactForQuadraticMapsOnTheSubdividedSolidWithItsCentreNodes) {
  // The window's cell mesh: level-K hexahedra of a refined control mesh with pyramids, whose apex
  // cells are tetrahedra around a centre node.
  const CellComplex control = loadControlMeshJson(SCULPT_SOURCE_DIR "/assets/mixed.json");
  const auto subdivision = subdivide(control, 2);
  ASSERT_TRUE(subdivision);
  const SolidCellMesh solid = solidCellMesh(subdivision->finest(), subdivision->finestTopology());
  ASSERT_GT(solid.mesh.numNodes(), solid.numVertices) << "the mesh has centre nodes";
  GradientFitReport report;
  const NodeGradientStencil fit = quadraticFitStencil(
      solid.mesh, nodeGradientStencil(solid.mesh, GradientScheme::Average), &report);
  std::printf("[ measured ] mixed.json level 2: %u nodes (%u centres), ring 1/2/3 %u/%u/%u, "
              "fallbacks %u\n",
              solid.mesh.numNodes(), solid.mesh.numNodes() - solid.numVertices,
              report.ringCounts[1], report.ringCounts[2], report.ringCounts[3], report.fallbacks);
  EXPECT_EQ(report.fallbacks, 0u);
  EXPECT_LT(worstGradientError(solid.mesh, fit), 1e-9);
}

TEST(GradientFit, RingsGrowOnlyWhereTheFirstCannotDetermineAQuadratic) {
  LatticeSpec spec;
  spec.cubes = {4, 4, 4};
  spec.spacing = 0.25;
  const VolumeMesh hexes = hexLattice(spec);
  GradientFitReport report;
  quadraticFitStencil(hexes, nodeGradientStencil(hexes, GradientScheme::Average), &report);
  // A hex node's first ring is its 3x3x3 block; on a face it has only two layers across the face,
  // too few for the quadratic term across it: the 3^3 interior nodes keep ring 1, the rest grow.
  EXPECT_EQ(report.ringCounts[1], 27u);
  EXPECT_EQ(report.ringCounts[2], 125u - 27u);
  EXPECT_EQ(report.fallbacks, 0u);
}

TEST(GradientFit, RigidMotionsGiveTheirRotationAtEveryNode) {
  const Eigen::Matrix3d R =
      Eigen::AngleAxisd(0.9, Eigen::Vector3d(0.3, -0.5, 0.8).normalized()).toRotationMatrix();
  for (const LatticeCase& lattice : lattices()) {
    Points moved = lattice.mesh.positions * R.transpose();
    moved.rowwise() += Eigen::RowVector3d(3.0, -1.0, 2.0);
    std::vector<Eigen::Matrix3d> gradients;
    applyNodeGradientStencil(nodeGradientStencil(lattice.mesh, GradientScheme::Fit), moved,
                             gradients);
    for (const Eigen::Matrix3d& F : gradients) EXPECT_LT((F - R).norm(), 1e-11) << lattice.name;
  }
}

TEST(GradientFit, ANodeWithoutAQualifyingRingKeepsTheAverage) {
  // One hexahedron: 8 nodes, fewer than a quadratic needs, so every row is the average's.
  LatticeSpec spec;
  const VolumeMesh cube = hexLattice(spec);
  const NodeGradientStencil average = nodeGradientStencil(cube, GradientScheme::Average);
  GradientFitReport report;
  const NodeGradientStencil fit = quadraticFitStencil(cube, average, &report);
  EXPECT_EQ(report.fallbacks, 8u);
  EXPECT_EQ(fit.offsets, average.offsets);
  EXPECT_EQ(fit.nodes, average.nodes);
  EXPECT_EQ(fit.g, average.g);
}

TEST(GradientFit, SchemeNamesRoundTrip) {
  for (GradientScheme scheme : {GradientScheme::Average, GradientScheme::Fit})
    EXPECT_EQ(parseGradientScheme(gradientSchemeName(scheme)), scheme);
  EXPECT_FALSE(parseGradientScheme("quadratic"));
}

}  // namespace
}  // namespace sculpt
