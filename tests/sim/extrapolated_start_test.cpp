// The implicit step's extrapolated CG start (sim/extrapolated_start.h): when it is offered, and
// on a soft block sagging under its own weight into the inversion barrier, that it saves CG
// iterations and leaves the motion as it was, to the solver's tolerance.

#include <gtest/gtest.h>

#include <climits>
#include <cstdio>
#include <optional>
#include <stdexcept>
#include <string>

#include "sim/extrapolated_start.h"
#include "sim/simulator.h"
#include "sim/standard_forms.h"
#include "support/mesh_builders.h"

namespace sculpt {
namespace {

TEST(ExtrapolatedStart, IsTwiceTheLastCorrectionLessTheOneBeforeForTheSameStep) {
  ExtrapolatedStart history;
  Points first = Points::Constant(4, 3, 1.0), second = Points::Constant(4, 3, 1.5);
  second(2, 1) = 3.0;
  EXPECT_EQ(history.start(0.1, 0).rows(), 0);
  history.remember(first, 0.1, 9);
  EXPECT_EQ(history.start(0.1, 0).rows(), 0);  // one correction is no trend
  history.remember(second, 0.1, 9);
  const Points start = history.start(0.1, 8);
  ASSERT_EQ(start.rows(), 4);
  EXPECT_EQ(start(0, 0), 2.0);
  EXPECT_EQ(start(2, 1), 5.0);
  EXPECT_EQ(history.start(0.1, 10).rows(), 0);  // the last solve was quick: from zero
  EXPECT_EQ(history.start(0.05, 0).rows(), 0);  // corrections of another step
  history.remember(first, 0.05, 9);             // a sub-step: the history starts again
  EXPECT_EQ(history.start(0.05, 0).rows(), 0);
  history.remember(second, 0.05, 9);
  history.clear();
  EXPECT_EQ(history.start(0.05, 0).rows(), 0);
}

// A 1 m cube of 3x3x3 control cells at level 2, E = 1 kPa, bottom fixed, under gravity: it
// sags until most of its elements are in the inversion barrier.
FemModel softCube() {
  std::string error;
  std::optional<FemModel> model = FemModel::create(
      test::hexGrid(3, 3, 3, 1.0 / 3.0), FemSetup{2, false, Material{1000, 0, 1e3, 0.3}}, &error);
  if (!model) throw std::runtime_error(error);
  return std::move(*model);
}

struct SaggingBlock {
  FemModel model;
  std::unique_ptr<Simulator> simulator;
  explicit SaggingBlock(int extrapolatedStartIterations) : model(softCube()) {
    SimulationSettings settings;
    settings.extrapolatedStartIterations = extrapolatedStartIterations;
    simulator = std::make_unique<Simulator>(model, settings);
    simulator->fixInBox(
        Eigen::AlignedBox3d(Eigen::Vector3d(-1, -1, -1e-9), Eigen::Vector3d(2, 2, 1e-9)));
    simulator->addLoad(std::make_unique<GravityForm>(model, Eigen::Vector3d(0, 0, -9.81)));
  }
};

TEST(ExtrapolatedStart, SavesIterationsAndLeavesTheMotionAsItWas) {
  SaggingBlock fromZero(INT_MAX), extrapolated(0);
  long long iterationsFromZero = 0, iterationsExtrapolated = 0;
  double worstResidual = 0;
  for (int step = 0; step < 60; ++step) {
    const StepReport a = fromZero.simulator->step(), b = extrapolated.simulator->step();
    ASSERT_TRUE(a.ok && b.ok) << a.message << b.message;
    ASSERT_EQ(b.substeps, 1);
    iterationsFromZero += a.iterations;
    iterationsExtrapolated += b.iterations;
    worstResidual = std::max(worstResidual, b.residual);
  }
  const Points& x = fromZero.simulator->positions();
  const double sag = (x - fromZero.model.restControl()).cwiseAbs().maxCoeff();
  const double apart = (extrapolated.simulator->positions() - x).cwiseAbs().maxCoeff();
  std::printf("CG iterations over 60 steps: %lld from zero, %lld extrapolated (each with a "
              "product more); sag %.3f m, apart %.2e m; %u elements in the barrier\n",
              iterationsFromZero, iterationsExtrapolated, sag, apart,
              fromZero.model.elastic().barrierElements());
  EXPECT_GT(fromZero.model.elastic().barrierElements(), 0u);
  EXPECT_LE(worstResidual, 1e-6);
  EXPECT_LT(double(iterationsExtrapolated), 0.95 * double(iterationsFromZero));  // 0.92
  EXPECT_LT(apart, 1e-4 * sag);
}

}  // namespace
}  // namespace sculpt
