// The integrators on small-amplitude free vibration: energy behaviour (bounded for the paper's
// central differences, monotone decay for backward Euler) and the largest stable step of each.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>

#include "sim/simulator.h"
#include "sim/standard_forms.h"
#include "support/mesh_builders.h"

namespace sculpt {
namespace {

int testLevel() {
  // SCULPT_VIBRATION_LEVEL=2 reproduces the figures of docs/fem-validation.md.
  if (const char* text = std::getenv("SCULPT_VIBRATION_LEVEL")) return std::atoi(text);
  return 1;
}

// A 1 m cube of 3x3x3 control cells, bottom face (z = 0) fixed.
struct Block {
  FemModel model;
  static Block make(double youngs) {
    std::string error;
    auto model = FemModel::create(test::hexGrid(3, 3, 3, 1.0 / 3.0),
                                  FemSetup{testLevel(), false, Material{1000, 0, youngs, 0.3}},
                                  &error);
    EXPECT_TRUE(model) << error;
    return Block{std::move(*model)};
  }
};

void fixBottom(Simulator& sim) {
  ASSERT_GT(sim.fixInBox(Eigen::AlignedBox3d(Eigen::Vector3d(-1, -1, -1e-9),
                                             Eigen::Vector3d(2, 2, 1e-9))),
            0u);
}

// Mechanical energy of the state: kinetic plus elastic.
double mechanicalEnergy(Simulator& sim) { return sim.kineticEnergy() + sim.elasticEnergy(); }

// Deflects the block statically under a lateral force at the top, then removes the force.
// Returns the Rayleigh-quotient estimate of the fundamental period, 2 pi / sqrt(f.u / u^T M u).
double prepareDeflectedState(Simulator& sim, double force) {
  const Points& rest = sim.model().restControl();
  Points forces = Points::Zero(rest.rows(), 3);
  int top = 0;
  for (Eigen::Index i = 0; i < rest.rows(); ++i)
    if (rest(i, 2) > 1 - 1e-9) ++top;
  for (Eigen::Index i = 0; i < rest.rows(); ++i)
    if (rest(i, 2) > 1 - 1e-9) forces(i, 0) = force / top;
  Form* load = sim.addLoad(std::make_unique<ControlForceForm>(forces));
  const StaticReport report = sim.solveStatic();
  EXPECT_TRUE(report.converged) << report.message;
  sim.removeLoad(load);
  const Points u = sim.positions() - rest;
  const Points Mu = applyScalarMatrix(sim.model().reducedMass(), u);
  const double omega2 = forces.cwiseProduct(u).sum() / u.cwiseProduct(Mu).sum();
  sim.setState(sim.positions(), Points::Zero(rest.rows(), 3));
  return 2 * M_PI / std::sqrt(omega2);
}

TEST(Integrators, PaperSchemeEnergyStaysBoundedOverTwentyPeriods) {
  Block block = Block::make(1e5);
  SimulationSettings settings;
  settings.integrator = Integrator::Paper;
  Simulator sim(block.model, settings);
  fixBottom(sim);
  const double period = prepareDeflectedState(sim, 1.0);  // about 1e-4 of the size
  // Central differences are stable only below about 2 / w_max; the highest element mode of this
  // mesh is some 50 times the fundamental, so the step is a 200th of the period.
  const int stepsPerPeriod = 200, periods = 20;
  settings.timeStep = period / stepsPerPeriod;
  settings.paperTolerance = 1e-8;  // measure the scheme, not the CG tolerance
  ASSERT_EQ(sim.setSettings(settings), "");
  // Leapfrog conserves E_{n+1/2} = 1/2 v^T M v + (U_n + U_{n+1}) / 2 up to O((w dt)^2).
  double previousElastic = sim.elasticEnergy();
  const double initial = previousElastic;
  std::vector<double> energy;
  for (int n = 0; n < stepsPerPeriod * periods; ++n) {
    const StepReport report = sim.step();
    ASSERT_TRUE(report.ok) << report.message;
    const double elastic = sim.elasticEnergy();
    energy.push_back(sim.kineticEnergy() + 0.5 * (elastic + previousElastic));
    previousElastic = elastic;
  }
  double worst = 0, firstMean = 0, lastMean = 0;
  for (double e : energy) worst = std::max(worst, std::abs(e - initial) / initial);
  for (int n = 0; n < stepsPerPeriod; ++n) {
    firstMean += energy[size_t(n)] / stepsPerPeriod;
    lastMean += energy[energy.size() - 1 - size_t(n)] / stepsPerPeriod;
  }
  const double drift = (lastMean - firstMean) / initial;
  std::printf("paper scheme, T = %.4g s, dt = T/200: energy within %.3g%% of the initial, drift "
              "over 20 periods %.3g%%\n",
              period, 100 * worst, 100 * drift);
  EXPECT_LT(worst, 0.05);
  EXPECT_LT(std::abs(drift), 0.01);
}

TEST(Integrators, ImplicitSchemeEnergyDecaysMonotonically) {
  Block block = Block::make(1e5);
  Simulator sim(block.model);
  fixBottom(sim);
  const double period = prepareDeflectedState(sim, 1.0);
  SimulationSettings settings;
  settings.timeStep = period / 50;
  settings.implicitTolerance = 1e-10;
  ASSERT_EQ(sim.setSettings(settings), "");
  double previous = mechanicalEnergy(sim);
  const double initial = previous;
  int increases = 0;
  for (int n = 0; n < 50 * 20; ++n) {
    const StepReport report = sim.step();
    ASSERT_TRUE(report.ok) << report.message;
    const double energy = mechanicalEnergy(sim);
    if (energy > previous * (1 + 1e-9)) ++increases;
    previous = energy;
  }
  std::printf("implicit scheme, dt = T/50: energy after 20 periods %.3g%% of the initial, %d "
              "increases\n",
              100 * previous / initial, increases);
  EXPECT_EQ(increases, 0);
  EXPECT_LT(previous, 0.5 * initial);
}

// True when `steps` steps from a small random state never fail and the energy stays bounded.
bool stableAt(FemModel& model, Integrator integrator, double dt, int steps) {
  SimulationSettings settings;
  settings.integrator = integrator;
  settings.timeStep = dt;
  settings.maxHalvings = 0;  // a failure must show, not be repaired
  Simulator sim(model, settings);
  fixBottom(sim);
  std::mt19937_64 rng(7);
  std::normal_distribution<double> noise(0.0, 1e-5);
  Points p = model.restControl();
  for (Eigen::Index i = 0; i < p.rows(); ++i)
    if (!sim.fixedMask()[size_t(i)])
      for (int c = 0; c < 3; ++c) p(i, c) += noise(rng);
  sim.setState(p, Points::Zero(p.rows(), 3));
  const double initial = mechanicalEnergy(sim);
  for (int n = 0; n < steps; ++n)
    if (!sim.step().ok) return false;
  const double final = mechanicalEnergy(sim);
  return std::isfinite(final) && final < 2 * initial;
}

TEST(Integrators, LargestStableStepScalesWithWaveSpeed) {
  const double moduli[] = {1e4, 1e6, 1e8};
  double paperLimit[3];
  for (int m = 0; m < 3; ++m) {
    Block block = Block::make(moduli[m]);
    // Bisection in log space between a stable and an unstable step.
    double lo = 1e-7, hi = 1.0;
    ASSERT_TRUE(stableAt(block.model, Integrator::Paper, lo, 200));
    ASSERT_FALSE(stableAt(block.model, Integrator::Paper, hi, 200));
    for (int it = 0; it < 18; ++it) {
      const double mid = std::sqrt(lo * hi);
      (stableAt(block.model, Integrator::Paper, mid, 200) ? lo : hi) = mid;
    }
    paperLimit[m] = lo;
    // Backward Euler: stable at every step tried, up to 10 s.
    bool implicitStable = true;
    for (double dt : {1e-3, 1e-1, 10.0})
      implicitStable = implicitStable && stableAt(block.model, Integrator::Implicit, dt, 20);
    std::printf("E = %.0e Pa: paper scheme stable up to dt = %.3g s; implicit stable at 1e-3, "
                "0.1 and 10 s: %s\n",
                moduli[m], paperLimit[m], implicitStable ? "yes" : "no");
    EXPECT_TRUE(implicitStable);
  }
  // Central differences are limited by the highest frequency, which grows as sqrt(E).
  EXPECT_NEAR(paperLimit[0] / paperLimit[1], 10.0, 1.5);
  EXPECT_NEAR(paperLimit[1] / paperLimit[2], 10.0, 1.5);
}

}  // namespace
}  // namespace sculpt
