// Absurd inputs never leave NaN, infinity or an exploded state, and the step says what it did.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "sim/simulator.h"
#include "sim/standard_forms.h"
#include "support/mesh_builders.h"

namespace sculpt {
namespace {

FemModel absurdModel() {
  std::string error;
  auto model = FemModel::create(test::hexGrid(3, 3, 3, 1.0 / 3.0),
                                FemSetup{1, false, Material{1000, 0, 1e12, 0.3}}, &error);
  EXPECT_TRUE(model) << error;
  return std::move(*model);
}

Points topForce(const FemModel& model, const Eigen::Vector3d& total) {
  const Points& rest = model.restControl();
  Points f = Points::Zero(rest.rows(), 3);
  int count = 0;
  for (Eigen::Index i = 0; i < rest.rows(); ++i) count += rest(i, 2) > 1 - 1e-9;
  for (Eigen::Index i = 0; i < rest.rows(); ++i)
    if (rest(i, 2) > 1 - 1e-9) f.row(i) = total.transpose() / count;
  return f;
}

class AbsurdInputs : public ::testing::TestWithParam<Integrator> {};

TEST_P(AbsurdInputs, HugeStiffnessStepAndForceStayFinite) {
  FemModel model = absurdModel();
  SimulationSettings settings;
  settings.integrator = GetParam();
  settings.timeStep = 10.0;
  settings.maxHalvings = 6;
  Simulator sim(model, settings);
  sim.fixInBox(Eigen::AlignedBox3d(Eigen::Vector3d(-1, -1, -1e-9), Eigen::Vector3d(2, 2, 1e-9)));
  sim.addLoad(std::make_unique<ControlForceForm>(topForce(model, {1e9, 0, -1e9})));
  for (int n = 0; n < 5; ++n) {
    const StepReport report = sim.step();
    ASSERT_TRUE(sim.positions().allFinite());
    ASSERT_TRUE(sim.velocities().allFinite());
    ASSERT_TRUE(std::isfinite(sim.kineticEnergy()));
    // Whatever happened is said: sub-steps or a refused step come with a sentence.
    if (!report.ok || report.substeps > 1) {
      EXPECT_FALSE(report.message.empty());
    }
    if (n == 0) std::printf("%s, E = 1e12, dt = 10 s, 1e9 N: ok=%d substeps=%d '%s'\n",
                            integratorName(GetParam()), report.ok, report.substeps,
                            report.message.c_str());
  }
}

TEST_P(AbsurdInputs, NonFiniteForceIsRefusedAndTheStateKept) {
  FemModel model = absurdModel();
  SimulationSettings settings;
  settings.integrator = GetParam();
  settings.maxHalvings = 3;
  Simulator sim(model, settings);
  sim.fixInBox(Eigen::AlignedBox3d(Eigen::Vector3d(-1, -1, -1e-9), Eigen::Vector3d(2, 2, 1e-9)));
  const Points before = sim.positions();
  sim.addLoad(std::make_unique<ControlForceForm>(
      topForce(model, {std::numeric_limits<double>::quiet_NaN(), 0, 0})));
  const StepReport report = sim.step();
  EXPECT_FALSE(report.ok);
  EXPECT_NE(report.message.find("kept"), std::string::npos) << report.message;
  EXPECT_EQ(sim.positions(), before);
}

INSTANTIATE_TEST_SUITE_P(BothIntegrators, AbsurdInputs,
                         ::testing::Values(Integrator::Paper, Integrator::Implicit),
                         [](const auto& param) {
                           return std::string(integratorName(param.param));
                         });

TEST(SimulatorSettings, InvalidSettingsAreRefusedWithASentence) {
  FemModel model = absurdModel();
  Simulator sim(model);
  SimulationSettings bad;
  bad.timeStep = -1;
  EXPECT_NE(sim.setSettings(bad), "");
  bad.timeStep = std::numeric_limits<double>::infinity();
  EXPECT_NE(sim.setSettings(bad), "");
  EXPECT_EQ(sim.settings().timeStep, SimulationSettings{}.timeStep);
}

}  // namespace
}  // namespace sculpt
