// A locally subdivided block simulates: its split neighbours are general polyhedra, which
// MacCracken–Joy refines into cells that need pyramid elements; under gravity with the bottom
// fixed, a few implicit steps stay finite and the block sags.

#include <gtest/gtest.h>

#include <cstdio>

#include "edit/topology_edit.h"
#include "sim/simulator.h"
#include "sim/standard_forms.h"
#include "support/edit_fixtures.h"

namespace sculpt {
namespace {

void sagsUnderGravity(int level) {
  const CellComplex control = subdivideCells(test::block3(), std::vector<uint32_t>{13}).mesh;
  FemSetup setup;
  setup.level = level;
  setup.material.youngs = 2e5;
  const auto model = test::buildModel(control, setup);
  ASSERT_TRUE(model);
  const ElementCounts counts = model->mesh().counts();
  std::printf("K=%d: %u control points, %u tricubic, %u trilinear, %u pyramid elements\n", level,
              model->numControlPoints(), counts.tricubic, counts.trilinear, counts.pyramid);
  EXPECT_GT(counts.pyramid, 0u);
  EXPECT_GT(counts.tricubic, 0u);

  Simulator sim(*model);
  SimulationSettings settings;
  settings.timeStep = 0.02;
  ASSERT_EQ(sim.setSettings(settings), "");
  ASSERT_GT(sim.fixInBox(
                Eigen::AlignedBox3d(Eigen::Vector3d(-1, -1, -1e-9), Eigen::Vector3d(4, 4, 1e-9))),
            0u);
  sim.addLoad(std::make_unique<GravityForm>(*model, Eigen::Vector3d(0, 0, -9.81)));
  for (int step = 0; step < 5; ++step) {
    const StepReport report = sim.step();
    ASSERT_TRUE(report.ok) << report.message;
  }
  const Points displacement = sim.positions() - model->restControl();
  ASSERT_TRUE(displacement.allFinite());
  double topSag = 0;
  int top = 0;
  for (Eigen::Index i = 0; i < displacement.rows(); ++i) {
    const double z = model->restControl()(i, 2);
    if (z < 1e-9) {
      EXPECT_EQ(displacement.row(i).norm(), 0.0) << "fixed point " << i << " moved";
    } else if (z > 3 - 1e-9) {
      topSag += displacement(i, 2);
      ++top;
    }
  }
  topSag /= top;
  std::printf("K=%d: mean top displacement after 5 steps %.3g m\n", level, topSag);
  EXPECT_LT(topSag, -1e-4);
  EXPECT_GT(topSag, -1.0);
}

TEST(LocalSubdivision, SimulatesAtLevel1) { sagsUnderGravity(1); }
TEST(LocalSubdivision, SimulatesAtLevel2) { sagsUnderGravity(2); }

}  // namespace
}  // namespace sculpt
