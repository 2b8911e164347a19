// Convergence of the subdivision-solid FEM (level K = 2, tricubic elements inside, trilinear
// ones at the boundary) on a cantilever, against a fine CalculiX C3D20R reference of the same
// box (docs/fem-validation.md has the table and the discussion).
//
// The solid is the 10 x 1 x 1 box: creased control meshes of 10x1x1, 20x2x2 and 40x4x4 cells
// with every control edge on a box edge creased and the 8 box corners tagged, so that every
// level (and the limit) is exactly the box. Clamped: every control point with x = 0 fixed.
// Load: a total P along -y spread equally over the control points with x = 10. Measured: the
// y displacement of the level-2 node at the tip-face centre (10, 0.5, 0.5), and the mean over
// the level-2 nodes of the tip face. Reference: ccx C3D20R on the box (every node of x = 0
// fixed, the same resultant as a uniform traction on x = 10) at 40x4x4 and 80x8x8 elements,
// read at its tip-centre node. E = 1e6, nu = 0.3, P = 0.25: the Euler-Bernoulli deflection is
// 1e-3, 1e-4 of the length (small displacements).
//
// Asserted: the error falls with each control refinement and is below 5% at 40x4x4.
// Skips without ccx.

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <iterator>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "fem/fem_model.h"
#include "mesh/cell_complex.h"
#include "mesh/validation.h"
#include "sim/simulator.h"
#include "sim/standard_forms.h"
#include "support/calculix.h"
#include "support/mesh_builders.h"

namespace sculpt::test {
namespace {

constexpr double kLength = 10.0, kWidth = 1.0, kHeight = 1.0;
constexpr double kYoungs = 1e6, kPoisson = 0.3, kLoad = 0.25;

using Clock = std::chrono::steady_clock;
double secondsSince(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

/// The 10 x 1 x 1 box as 10n x n x n unit-h hexahedra (h = 1/n), every grid edge lying on one
/// of the 12 box edges creased and the 8 box corners tagged (the construction of
/// assets/beam.json, scripts/make_assets.py make_beam, for n = 1).
CellComplex creasedBeam(int n) {
  const int nx = 10 * n, ny = n, nz = n;
  CellComplex m = hexGrid(nx, ny, nz, 1.0 / n);
  const std::array<int, 3> last = {nx, ny, nz};
  const auto vertex = [&](const std::array<int, 3>& g) {
    return gridVertex(nx, ny, g[0], g[1], g[2]);
  };
  // Edges along axis a with the other two grid coordinates at an end.
  for (int a = 0; a < 3; ++a) {
    const int b = (a + 1) % 3, c = (a + 2) % 3;
    for (int eb : {0, last[size_t(b)]})
      for (int ec : {0, last[size_t(c)]})
        for (int t = 0; t < last[size_t(a)]; ++t) {
          std::array<int, 3> g0{}, g1{};
          g0[size_t(a)] = t;
          g1[size_t(a)] = t + 1;
          g0[size_t(b)] = g1[size_t(b)] = eb;
          g0[size_t(c)] = g1[size_t(c)] = ec;
          m.creases.push_back({vertex(g0), vertex(g1)});
        }
  }
  for (int i : {0, nx})
    for (int j : {0, ny})
      for (int k : {0, nz}) m.corners.push_back(gridVertex(nx, ny, i, j, k));
  return m;
}

struct OursResult {
  int n = 0, level = 2;
  uint32_t controlPoints = 0, nodes = 0;
  ElementCounts elements;
  double tipCentre = 0;  ///< y displacement of the tip-centre node
  double tipMean = 0;    ///< mean y displacement of the tip-face nodes
  double createSeconds = 0, solveSeconds = 0;
  StaticReport report;
  std::map<double, double> axis;  ///< x -> y displacement of the level-K nodes at (x, 0.5, 0.5)
};

/// Our solve of the creased 10n x n x n beam at simulation level `level`.
OursResult solveOurs(int n, int level = 2, double poisson = kPoisson) {
  OursResult out;
  out.n = n;
  out.level = level;
  const CellComplex control = creasedBeam(n);
  const auto issues = validate(control);
  EXPECT_TRUE(isValid(issues)) << (issues.empty() ? std::string() : issues.front().message);

  const auto t0 = Clock::now();
  std::string error;
  FemSetup setup;
  setup.level = level;
  setup.material = Material{1000.0, 0.0, kYoungs, poisson};
  auto model = FemModel::create(control, setup, &error);
  out.createSeconds = secondsSince(t0);
  EXPECT_TRUE(model.has_value()) << error;
  if (!model) return out;
  out.controlPoints = model->numControlPoints();
  out.nodes = model->numNodes();
  out.elements = model->mesh().counts();

  // Every level is the box itself (creases and corners): the level-2 nodes span it exactly.
  const Points& rest = model->mesh().restNodes;
  const Eigen::Vector3d lo = rest.colwise().minCoeff().transpose();
  const Eigen::Vector3d hi = rest.colwise().maxCoeff().transpose();
  EXPECT_LE((lo - Eigen::Vector3d::Zero()).norm(), 1e-12);
  EXPECT_LE((hi - Eigen::Vector3d(kLength, kWidth, kHeight)).norm(), 1e-12);

  const auto t1 = Clock::now();
  Simulator sim(*model);
  const Points& restControl = model->restControl();
  std::vector<uint32_t> tipControl;
  for (Eigen::Index i = 0; i < restControl.rows(); ++i) {
    if (restControl(i, 0) == 0.0) sim.setFixed(uint32_t(i), true);
    if (restControl(i, 0) == kLength) tipControl.push_back(uint32_t(i));
  }
  EXPECT_EQ(tipControl.size(), size_t((n + 1) * (n + 1)));
  Points forces = Points::Zero(restControl.rows(), 3);
  for (uint32_t i : tipControl) forces(i, 1) = -kLoad / double(tipControl.size());
  sim.addLoad(std::make_unique<ControlForceForm>(forces));
  out.report = sim.solveStatic();
  EXPECT_TRUE(out.report.converged) << out.report.message;

  Points nodes;
  model->nodesFromControl(sim.positions(), nodes);
  // Fixing the control points of x = 0 clamps the whole face at level K: with the box edges
  // creased, the boundary rules of that face use only its own points.
  double clampMotion = 0;
  for (Eigen::Index i = 0; i < rest.rows(); ++i)
    if (rest(i, 0) == 0.0) clampMotion = std::max(clampMotion, (nodes.row(i) - rest.row(i)).norm());
  EXPECT_EQ(clampMotion, 0.0);
  const Eigen::Vector3d centre(kLength, kWidth / 2, kHeight / 2);
  std::optional<Eigen::Index> centreNode;
  double sum = 0;
  int count = 0;
  for (Eigen::Index i = 0; i < static_cast<Eigen::Index>(model->mesh().numLatticeNodes); ++i) {
    if (std::abs(rest(i, 1) - kWidth / 2) <= 1e-12 && std::abs(rest(i, 2) - kHeight / 2) <= 1e-12)
      out.axis[rest(i, 0)] = nodes(i, 1) - rest(i, 1);
    if (std::abs(rest(i, 0) - kLength) > 1e-12) continue;
    sum += nodes(i, 1) - rest(i, 1);
    ++count;
    if ((rest.row(i).transpose() - centre).norm() <= 1e-12) centreNode = i;
  }
  out.solveSeconds = secondsSince(t1);
  EXPECT_TRUE(centreNode.has_value()) << "no level-K node at the tip-face centre";
  EXPECT_EQ(count, ((n << level) + 1) * ((n << level) + 1));
  if (centreNode) out.tipCentre = nodes(*centreNode, 1) - rest(*centreNode, 1);
  out.tipMean = sum / count;
  return out;
}

struct CcxTip {
  int n = 0;
  size_t nodes = 0;
  double tipCentre = 0, seconds = 0;
  bool ok = false;
  std::map<double, double> axis;  ///< x -> y displacement of the nodes at (x, 0.5, 0.5)
};

/// ccx C3D20R on n*10 x n x n elements.
CcxTip solveCcx(int n, double poisson = kPoisson) {
  CcxTip out;
  out.n = n;
  CcxModel m = boxC3D20(10 * n, n, n, Eigen::Vector3d(kLength, kWidth, kHeight), true);
  m.youngs = kYoungs;
  m.poisson = poisson;
  m.fixedNodes = nodesOnPlane(m, 0, 0.0);
  addUniformTraction(m, 0, kLength, Eigen::Vector3d(0.0, -kLoad, 0.0));
  const auto tip = findNode(m, Eigen::Vector3d(kLength, kWidth / 2, kHeight / 2));
  EXPECT_TRUE(tip.has_value());
  if (!tip) return out;
  const auto t0 = Clock::now();
  std::string error;
  const auto r = runCalculix(m, &error);
  out.seconds = secondsSince(t0);
  EXPECT_TRUE(r.has_value()) << error;
  if (!r) return out;
  out.nodes = m.nodes.size();
  out.tipCentre = r->displacement[*tip].y();
  for (size_t i = 0; i < m.nodes.size(); ++i)
    if (std::abs(m.nodes[i].y() - kWidth / 2) <= 1e-12 &&
        std::abs(m.nodes[i].z() - kHeight / 2) <= 1e-12)
      out.axis[m.nodes[i].x()] = r->displacement[i].y();
  out.ok = true;
  return out;
}

/// The axis error u_ours(x) - u_ref(x), fitted on 2 <= x <= L by least squares as
/// a x + b u_ref(x): a rigid rotation a gained or lost in the root region (a x, which is what
/// an error confined near the clamp leaves downstream) plus a uniformly wrong bending
/// compliance (b u_ref). Both as fractions of the reference tip deflection: a L / u_ref(L)
/// and b. `fitResidual` is the relative misfit (about 0 when this model describes the error).
struct ErrorSplit {
  double root = 0, distributed = 0, fitResidual = 0;
};

ErrorSplit splitError(const std::map<double, double>& ours, const std::map<double, double>& ref) {
  double s11 = 0, s12 = 0, s22 = 0, t1 = 0, t2 = 0, norm = 0;
  std::vector<std::array<double, 3>> rows;  // x, u_ref, difference
  for (const auto& [x, u] : ours) {
    if (x < 2.0) continue;
    const auto it = ref.find(x);
    if (it == ref.end()) {
      ADD_FAILURE() << "no reference node at x = " << x;
      return {};
    }
    const double r = it->second, d = u - r;
    s11 += x * x, s12 += x * r, s22 += r * r, t1 += x * d, t2 += r * d, norm += d * d;
    rows.push_back({x, r, d});
  }
  const double det = s11 * s22 - s12 * s12;
  const double a = (s22 * t1 - s12 * t2) / det, b = (s11 * t2 - s12 * t1) / det;
  double misfit = 0;
  for (const auto& [x, r, d] : rows) misfit += (a * x + b * r - d) * (a * x + b * r - d);
  ErrorSplit out;
  out.root = a * kLength / ref.at(kLength);
  out.distributed = b;
  out.fitResidual = norm > 0 ? std::sqrt(misfit / norm) : 0.0;
  return out;
}

TEST(BeamConvergence, CreasedBoxBeamConvergesToCalculix) {
  SCULPT_REQUIRE_CCX();
  const auto tAll = Clock::now();

  // Reference.
  const CcxTip coarse = solveCcx(4), fine = solveCcx(8);
  ASSERT_TRUE(coarse.ok && fine.ok);
  const double reference = fine.tipCentre;
  const double I = kWidth * kHeight * kHeight * kHeight / 12.0, A = kWidth * kHeight;
  const double G = kYoungs / (2.0 * (1.0 + kPoisson));
  const double eulerBernoulli = -kLoad * std::pow(kLength, 3) / (3.0 * kYoungs * I);
  const double timoshenko = eulerBernoulli - kLoad * kLength / (5.0 / 6.0 * G * A);
  std::printf("  reference tip-centre deflection u_y (10, 0.5, 0.5):\n");
  std::printf("    ccx C3D20R %3dx%dx%d (%6zu nodes, %5.1f s): %.6e  (%+.3f%% of 80x8x8)\n",
              10 * coarse.n, coarse.n, coarse.n, coarse.nodes, coarse.seconds, coarse.tipCentre,
              100.0 * (coarse.tipCentre / reference - 1.0));
  std::printf("    ccx C3D20R %3dx%dx%d (%6zu nodes, %5.1f s): %.6e\n", 10 * fine.n, fine.n, fine.n,
              fine.nodes, fine.seconds, fine.tipCentre);
  std::printf("    Euler-Bernoulli P L^3 / (3 E I):          %.6e  (%+.3f%%)\n", eulerBernoulli,
              100.0 * (eulerBernoulli / reference - 1.0));
  std::printf("    Timoshenko (+ P L / (5/6 G A)):           %.6e  (%+.3f%%)\n", timoshenko,
              100.0 * (timoshenko / reference - 1.0));
  // The two ccx meshes agree closely: the reference is converged far beyond what we test.
  EXPECT_NEAR(coarse.tipCentre / reference, 1.0, 2e-3);

  std::printf(
      "  ours (level 2)  control pts   nodes  tricubic/trilinear  tip centre u_y   error   "
      "tip mean u_y    error   (root  distributed)  create  solve  Newton/CG\n");
  std::vector<OursResult> ours;
  for (int n : {1, 2, 4}) {
    ours.push_back(solveOurs(n));
    const OursResult& o = ours.back();
    const ErrorSplit split = splitError(o.axis, fine.axis);
    std::printf(
        "  %2dx%dx%d        %11u %7u  %8u/%-9u  %.6e  %+7.3f%%  %.6e  %+7.3f%%  (%+.3f%% %+.3f%%)  "
        "%5.2fs %5.2fs  %d/%d\n",
        10 * n, n, n, o.controlPoints, o.nodes, o.elements.tricubic, o.elements.trilinear,
        o.tipCentre, 100.0 * (o.tipCentre / reference - 1.0), o.tipMean,
        100.0 * (o.tipMean / reference - 1.0), 100.0 * split.root, 100.0 * split.distributed,
        o.createSeconds, o.solveSeconds, o.report.newtonIterations, o.report.cgIterations);
  }
  for (size_t k = 0; k < ours.size(); ++k) {
    const double error = std::abs(ours[k].tipCentre / reference - 1.0);
    if (k > 0) {
      EXPECT_LT(error, std::abs(ours[k - 1].tipCentre / reference - 1.0))
          << "no improvement from " << ours[k - 1].n << " to " << ours[k].n;
    }
  }
  EXPECT_LT(std::abs(ours.back().tipCentre / reference - 1.0), 0.05);
  std::printf("  whole test %.1f s\n", secondsSince(tAll));
}

// Where the remaining error lives (docs/fem-validation.md, "What remains"); slow (about two
// minutes), so disabled: run with --gtest_also_run_disabled_tests. For nu = 0.3 and nu = 0
// (no Poisson contraction for the clamp to suppress, no thickness locking), every control mesh
// at levels 1..3 (40x4x4 at 1..2), split as in splitError against ccx C3D20R 80x8x8:
//  * the part that depends on the level K (at a fixed control mesh) is the element error of the
//    level-K lattice (trilinear boundary band, level-K nodes instead of the limit);
//  * the part that stays as K grows is the control (subdivision) space itself.
TEST(BeamConvergence, DISABLED_ErrorStudy) {
  SCULPT_REQUIRE_CCX();
  for (double nu : {kPoisson, 0.0}) {
    const CcxTip ref = solveCcx(8, nu);
    ASSERT_TRUE(ref.ok);
    std::printf("  nu = %.1f, reference ccx 80x8x8 tip %.6e\n", nu, ref.tipCentre);
    std::printf(
        "    control  K  elements   tip error   at x=1    at x=5    root  distributed  fit\n");
    std::map<double, double> finest;  // 40x4x4 at level 2
    for (const auto& [n, level] : std::vector<std::pair<int, int>>{
             {1, 1}, {1, 2}, {1, 3}, {2, 1}, {2, 2}, {2, 3}, {4, 1}, {4, 2}}) {
      const OursResult o = solveOurs(n, level, nu);
      if (n == 4 && level == 2) finest = o.axis;
      const ErrorSplit split = splitError(o.axis, ref.axis);
      const auto at = [&](double x) { return o.axis.at(x) / ref.axis.at(x) - 1.0; };
      std::printf(
          "    %2dx%dx%d  %d  %8u  %+8.3f%%  %+7.3f%%  %+7.3f%%  %+7.3f%%  %+7.3f%%  %.3f\n",
          10 * n, n, n, level, o.elements.total(), 100.0 * (o.tipCentre / ref.tipCentre - 1),
          100.0 * at(1.0), 100.0 * at(5.0), 100.0 * split.root, 100.0 * split.distributed,
          split.fitResidual);
    }
    // The bending curvature u_y'' along the axis near the clamp (second differences on the
    // 0.0625 lattice of both): the natural end condition of the subdivision space shows as a
    // curvature that starts from zero at the clamped face and peaks one control cell (0.25) in.
    std::printf("    u_y'' near the clamp (Euler-Bernoulli P L / E I = %.3e):\n      x      ",
                kLoad * kLength * 12.0 / kYoungs);
    const std::vector<double> xs = {0.0625, 0.125, 0.1875, 0.25, 0.3125, 0.375, 0.5, 1.0};
    for (double x : xs) std::printf("  %9.4f", x);
    for (const std::map<double, double>* curve :
         std::array<const std::map<double, double>*, 2>{&ref.axis, &finest}) {
      std::printf("\n      %s", curve == &ref.axis ? "ccx    " : "40x4x4 ");
      for (double x : xs) {
        const auto it = curve->find(x);
        if (it == curve->end() || it == curve->begin() || std::next(it) == curve->end()) {
          std::printf("  %9s", "-");
          continue;
        }
        const auto before = std::prev(it), after = std::next(it);
        const double h = after->first - it->first;
        std::printf("  %9.2e", (after->second - 2.0 * it->second + before->second) / (h * h));
      }
    }
    std::printf("\n");
  }
}

}  // namespace
}  // namespace sculpt::test
