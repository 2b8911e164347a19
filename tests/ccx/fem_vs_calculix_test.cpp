// Small-displacement statics of our --trilinear mode against CalculiX (C3D8, full 2x2x2 Gauss
// integration) on the same hexahedral mesh, built and compared inside the test: every nodal
// displacement must agree to 1e-6 of the largest one (docs/design/local-frame-fem.md, "Proof").
//
// Both sides discretise the same problem with the same element: trilinear 8-node hexahedra,
// K_e = sum over 2x2x2 Gauss points of B^T C B det J on the true isoparametric map, the same
// fixed nodes and the same nodal forces. ccx's linear *STATIC is a direct solve, ours is
// Newton with Cholesky-preconditioned CG driven to a force residual of 1e-12, so the only
// intrinsic difference is ccx's printout: 7 significant digits (E13.6), a relative rounding
// of at most 5e-7 of each component. The cases:
//   * a clamped 8 x 2 x 2 cantilever (4 x 1 x 1) under a tip shear load;
//   * a 4 x 4 x 4 unit block clamped at z = 0, twisted by tangential forces on z = 1 that
//     form a pure torque (zero net force);
//   * both with every node jittered by up to 10% of the spacing (non-affine hexahedra with
//     warped faces, the same coordinates written to ccx), so nothing rests on box symmetry;
//   * nu = 0.45 (near-incompressible: locking is the same in both, since the element is);
//   * our co-rotated elasticity under a tiny load (displacements ~1e-8 of the size), whose
//     linearisation at rest is the same small-strain problem.
// Tests that run ccx fail without it.

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <random>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "fem/fem_model.h"
#include "mesh/cell_complex.h"
#include "mesh/standard_cell.h"
#include "mesh/validation.h"
#include "sim/simulator.h"
#include "sim/standard_forms.h"
#include "support/calculix.h"
#include "support/mesh_builders.h"

namespace sculpt::test {
namespace {


/// The sculpt cell complex of a C3D8 model: vertex i = node i, each element's 8 VTK-ordered
/// nodes a hexahedral cell.
CellComplex complexFromCcx(const CcxModel& m) {
  CellComplex c;
  c.positions.resize(static_cast<Eigen::Index>(m.nodes.size()), 3);
  for (size_t i = 0; i < m.nodes.size(); ++i)
    c.positions.row(static_cast<Eigen::Index>(i)) = m.nodes[i].transpose();
  for (const auto& e : m.elements)
    c.addCell(standardCellFaces(StandardCell::Hexahedron, std::span<const uint32_t>(e)));
  return c;
}

/// Moves every node by a uniform random amount in [-amplitude, amplitude] per coordinate.
void jitterNodes(CcxModel& m, double amplitude, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> uni(-amplitude, amplitude);
  for (auto& p : m.nodes)
    for (int d = 0; d < 3; ++d) p[d] += uni(rng);
}

struct Comparison {
  double maxCcx = 0;   ///< largest |u| of ccx
  double maxDiff = 0;  ///< largest |u_ours - u_ccx| over nodes
  size_t worstNode = 0;
  double residual = 0;     ///< our static solve's relative force residual
  int newton = 0, cg = 0;  ///< our iterations
  double relative() const { return maxDiff / maxCcx; }
};

/// Solves the model with ccx and with our trilinear FEM (fixed nodes and nodal forces as in the
/// CcxModel) and compares every node. `forceScale` multiplies the loads on our side only (the
/// problem is linear on ccx's side, so ours are scaled back). `requireConverged`: expect our
/// static solve to report convergence.
Comparison compareWithCcx(const char* name, const CcxModel& m, bool corotated,
                          double forceScale = 1.0, bool requireConverged = true) {
  Comparison out;
  // Ours.
  const CellComplex control = complexFromCcx(m);
  const auto issues = validate(control);
  EXPECT_TRUE(isValid(issues)) << name << ": control mesh invalid: "
                               << (issues.empty() ? std::string() : issues.front().message);
  for (uint32_t c = 0; c < control.numCells(); ++c)
    EXPECT_GT(signedVolume(control, c), 0.0) << name << ": cell " << c << " is inverted";
  std::string error;
  FemSetup setup;
  setup.trilinear = true;
  setup.material = Material{1000.0, 0.0, m.youngs, m.poisson};
  auto model = FemModel::create(control, setup, &error);
  EXPECT_TRUE(model.has_value()) << name << ": " << error;
  if (!model) return out;
  EXPECT_EQ(model->numNodes(), m.nodes.size());
  EXPECT_EQ(model->numControlPoints(), m.nodes.size());
  EXPECT_EQ(model->mesh().numLinear(), m.elements.size());

  SimulationSettings settings;
  settings.corotated = corotated;
  Simulator sim(*model, settings);
  for (uint32_t n : m.fixedNodes) sim.setFixed(n, true);
  Points forces = Points::Zero(static_cast<Eigen::Index>(m.nodes.size()), 3);
  for (const auto& [n, f] : m.loads) forces.row(n) += forceScale * f.transpose();
  sim.addLoad(std::make_unique<ControlForceForm>(forces));
  const auto t0 = std::chrono::steady_clock::now();
  const StaticReport report = sim.solveStatic(1e-12, 40);
  const double oursMs =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  if (requireConverged) {
    EXPECT_TRUE(report.converged) << name << ": " << report.message;
  }
  out.residual = report.residual;
  out.newton = report.newtonIterations;
  out.cg = report.cgIterations;

  // CalculiX.
  const auto t1 = std::chrono::steady_clock::now();
  auto r = runCalculix(m, &error);
  const double ccxMs =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t1).count();
  EXPECT_TRUE(r.has_value()) << name << ": " << error;
  if (!r) return out;

  const Points& p = sim.positions();
  const Points& rest = model->restControl();
  for (size_t n = 0; n < m.nodes.size(); ++n)
    out.maxCcx = std::max(out.maxCcx, r->displacement[n].norm());
  for (size_t n = 0; n < m.nodes.size(); ++n) {
    const Eigen::Index i = static_cast<Eigen::Index>(n);
    const Eigen::Vector3d ours = (p.row(i) - rest.row(i)).transpose() / forceScale;
    const double diff = (ours - r->displacement[n]).norm();
    if (diff > out.maxDiff) {
      out.maxDiff = diff;
      out.worstNode = n;
    }
  }
  std::printf(
      "  %-32s %4zu nodes %4zu C3D8 %s: max|u| %.6e, max|du| %.3e = %.2e of max|u| "
      "(node %zu); ours: residual %.1e%s, %d Newton / %d CG, %.0f ms; ccx %.0f ms\n",
      name, m.nodes.size(), m.elements.size(), corotated ? "corotated" : "linear   ", out.maxCcx,
      out.maxDiff, out.relative(), out.worstNode, out.residual,
      report.converged ? "" : " (not converged)", out.newton, out.cg, oursMs, ccxMs);
  return out;
}

constexpr double kTolerance = 1e-6;

/// Clamped cantilever [0,4]x[0,1]x[0,1] of 8x2x2 C3D8, every node of x = 0 fixed, a shear
/// load of resultant P along -y spread equally over the tip-face nodes.
CcxModel cantilever(double E, double nu, double P) {
  CcxModel m = boxC3D8(8, 2, 2, Eigen::Vector3d(4.0, 1.0, 1.0));
  m.youngs = E;
  m.poisson = nu;
  m.fixedNodes = nodesOnPlane(m, 0, 0.0);
  const auto tip = nodesOnPlane(m, 0, 4.0);
  for (uint32_t n : tip)
    m.loads.emplace_back(n, Eigen::Vector3d(0.0, -P / static_cast<double>(tip.size()), 0.0));
  return m;
}

/// Unit block of 4x4x4 C3D8 clamped at z = 0; on z = 1 every node gets T e_z x (x - c) / S
/// with c the mean of those nodes and S = sum |x - c|^2, so the forces sum to zero and their
/// moment about the z axis through c is T. `jitter` moves every node first (fraction of the
/// spacing 0.25).
CcxModel twistedBlock(double E, double nu, double T, double jitter, uint64_t seed) {
  CcxModel m = boxC3D8(4, 4, 4, Eigen::Vector3d::Ones());
  const auto top = nodesOnPlane(m, 2, 1.0);
  m.fixedNodes = nodesOnPlane(m, 2, 0.0);
  if (jitter > 0) jitterNodes(m, jitter * 0.25, seed);
  m.youngs = E;
  m.poisson = nu;
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (uint32_t n : top) c += m.nodes[n];
  c /= static_cast<double>(top.size());
  double S = 0;
  for (uint32_t n : top) S += (m.nodes[n] - c).head<2>().squaredNorm();
  for (uint32_t n : top) {
    const Eigen::Vector3d r = m.nodes[n] - c;
    m.loads.emplace_back(n, T / S * Eigen::Vector3d(-r.y(), r.x(), 0.0));
  }
  return m;
}

TEST(FemVsCalculix, ClampedCantileverLinear) {
  SCULPT_REQUIRE_CCX();
  const Comparison c = compareWithCcx("cantilever 8x2x2", cantilever(1e6, 0.3, 1.0), false);
  EXPECT_GT(c.maxCcx, 0.0);
  EXPECT_LE(c.maxDiff, kTolerance * c.maxCcx);
}

TEST(FemVsCalculix, TwistedBlockLinear) {
  SCULPT_REQUIRE_CCX();
  const Comparison c =
      compareWithCcx("twisted block 4x4x4", twistedBlock(1e6, 0.3, 1.0, 0, 0), false);
  EXPECT_GT(c.maxCcx, 0.0);
  EXPECT_LE(c.maxDiff, kTolerance * c.maxCcx);
}

TEST(FemVsCalculix, JitteredMeshesLinear) {
  SCULPT_REQUIRE_CCX();
  {
    CcxModel m = boxC3D8(8, 2, 2, Eigen::Vector3d(4.0, 1.0, 1.0));
    jitterNodes(m, 0.1 * 0.5, 7);  // spacing 0.5
    m.youngs = 1e6;
    m.poisson = 0.3;
    m.fixedNodes = nodesOnPlane(m, 0, 0.0, 0.06);
    const auto tip = nodesOnPlane(m, 0, 4.0, 0.06);
    ASSERT_EQ(m.fixedNodes.size(), 9u);
    ASSERT_EQ(tip.size(), 9u);
    // Not parallel to an axis: bending about both axes, torsion and tension together.
    for (uint32_t n : tip) m.loads.emplace_back(n, Eigen::Vector3d(0.3, -1.0, 0.4) / 9.0);
    const Comparison c = compareWithCcx("jittered cantilever 8x2x2", m, false);
    EXPECT_LE(c.maxDiff, kTolerance * c.maxCcx);
  }
  {
    const Comparison c =
        compareWithCcx("jittered twisted block 4x4x4", twistedBlock(1e6, 0.3, 1.0, 0.1, 11), false);
    EXPECT_LE(c.maxDiff, kTolerance * c.maxCcx);
  }
}

TEST(FemVsCalculix, NearlyIncompressible) {
  SCULPT_REQUIRE_CCX();
  {
    const Comparison c =
        compareWithCcx("cantilever 8x2x2 nu 0.45", cantilever(1e6, 0.45, 1.0), false);
    EXPECT_LE(c.maxDiff, kTolerance * c.maxCcx);
  }
  {
    const Comparison c = compareWithCcx("jittered twisted block nu 0.45",
                                        twistedBlock(1e6, 0.45, 1.0, 0.1, 13), false);
    EXPECT_LE(c.maxDiff, kTolerance * c.maxCcx);
  }
}

// Co-rotated elasticity linearises to the same small-strain stiffness at rest. Its geometric
// non-linearity changes the displacements by about (displacement / size) relative, so the
// comparison at 1e-6 needs a load that moves the solid by ~1e-8 of its size; the positions
// (~1) still resolve such displacements to ~1e-8 relative.
//
// At that scale the force residual cannot fall below ~1e-5 of the load: the elastic forces
// are computed from positions carrying a rounding of ~1e-16 of the size, i.e. ~1e-8 of the
// displacement, times the conditioning. solveStatic's stall test (an update below 1e-10 of the
// displacement, ~4e-18 here, under what a position of size ~4 can represent) never fires, so
// it runs its 40 Newton iterations and reports no convergence although it sits on that floor.
// Hence the residual is checked against the floor here, not report.converged; the nodal
// comparison with ccx is the real check.
TEST(FemVsCalculix, CorotatedAgreesUnderTinyLoad) {
  SCULPT_REQUIRE_CCX();
  // Cantilever: P = 1 gives a tip deflection of 2.3e-4 on a length of 4; scale to ~3.5e-8.
  {
    const Comparison c = compareWithCcx("cantilever 8x2x2 (tiny load)", cantilever(1e6, 0.3, 1.0),
                                        true, 1.5e-4, /*requireConverged=*/false);
    EXPECT_LE(c.residual, 1e-3);
    EXPECT_LE(c.maxDiff, kTolerance * c.maxCcx);
  }
  {
    const Comparison c =
        compareWithCcx("jittered twisted block (tiny load)", twistedBlock(1e6, 0.3, 1.0, 0.1, 11),
                       true, 1e-2, /*requireConverged=*/false);
    EXPECT_LE(c.residual, 1e-3);
    EXPECT_LE(c.maxDiff, kTolerance * c.maxCcx);
  }
  // For scale: at the full load (tip deflection 6e-5 of the length) the co-rotated answer
  // differs from the linear one by about that fraction, far above 1e-6. Printed, not asserted
  // beyond a sanity bound.
  {
    const Comparison c =
        compareWithCcx("cantilever 8x2x2 (full load)", cantilever(1e6, 0.3, 1.0), true);
    EXPECT_LE(c.maxDiff, 1e-3 * c.maxCcx);
  }
}

}  // namespace
}  // namespace sculpt::test
