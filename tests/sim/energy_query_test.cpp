// Asking the simulator for its energies is a query: it must not change the steps that follow.
// The elastic energy finds the element rotations of the current state; they used to become the
// next step's warm start, so a command-line progress line (printed about once a second of wall
// time) changed the last bits of every later step and the same run gave different results.

#include <gtest/gtest.h>

#include "sim/simulator.h"
#include "sim/standard_forms.h"
#include "support/mesh_builders.h"

namespace sculpt {
namespace {

Points run(bool queryEveryStep) {
  std::string error;
  auto model = FemModel::create(test::hexGrid(3, 3, 3, 1.0 / 3.0),
                                FemSetup{1, false, Material{1000, 5, 1e5, 0.3}}, &error);
  EXPECT_TRUE(model) << error;
  SimulationSettings settings;
  settings.timeStep = 1.0 / 60.0;
  Simulator simulator(*model, settings);
  simulator.fixInBox(
      Eigen::AlignedBox3d(Eigen::Vector3d(-1, -1, -1e-9), Eigen::Vector3d(2, 2, 1e-9)));
  simulator.addLoad(std::make_unique<GravityForm>(*model, Eigen::Vector3d(0.3, 0.0, -9.81)));
  for (int i = 0; i < 40; ++i) {
    simulator.step();
    if (queryEveryStep) {
      EXPECT_TRUE(std::isfinite(simulator.elasticEnergy()));
      EXPECT_TRUE(std::isfinite(simulator.kineticEnergy()));
    }
  }
  return simulator.positions();
}

TEST(EnergyQuery, AskingForTheEnergiesDoesNotChangeLaterSteps) {
  const Points quiet = run(false), asked = run(true);
  ASSERT_EQ(quiet.rows(), asked.rows());
  EXPECT_EQ((quiet - asked).cwiseAbs().maxCoeff(), 0.0) << "bit for bit";
  EXPECT_GT((quiet - test::hexGrid(3, 3, 3, 1.0 / 3.0).positions).cwiseAbs().maxCoeff(), 1e-4)
      << "the block moved";
}

}  // namespace
}  // namespace sculpt
