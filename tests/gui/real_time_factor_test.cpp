#include "sculpt/real_time_factor.h"

#include <gtest/gtest.h>

#include <cmath>

namespace sculpt::app {
namespace {

TEST(RealTimeFactor, IsSimulatedSecondsPerWallSecond) {
  // 17 steps of 1/60 s in one second of the clock: 0.28x, as a slow default scene showed.
  const std::optional<double> slow = realTimeFactor(2.0, 2.0 + 17.0 / 60.0, 1.0);
  ASSERT_TRUE(slow);
  EXPECT_DOUBLE_EQ(*slow, 17.0 / 60.0);
  EXPECT_EQ(realTimeLabel(*slow), "0.28x real time");
  EXPECT_TRUE(behindRealTime(*slow));
  // 120 steps of 1/60 s in 1.25 s: 1.6x, ahead of the clock.
  const std::optional<double> fast = realTimeFactor(0.0, 2.0, 1.25);
  ASSERT_TRUE(fast);
  EXPECT_DOUBLE_EQ(*fast, 1.6);
  EXPECT_EQ(realTimeLabel(*fast), "1.6x real time");
  EXPECT_FALSE(behindRealTime(*fast));
  EXPECT_EQ(realTimeLabel(12.4), "12x real time");
  EXPECT_FALSE(behindRealTime(1.0));
  // A simulation on pace whose window caught 58 of its 60 steps, and one that lost 6.
  EXPECT_FALSE(behindRealTime(58.0 / 60.0));
  EXPECT_TRUE(behindRealTime(54.0 / 60.0));
}

TEST(RealTimeFactor, NothingForAResetOrAnEmptyWindow) {
  EXPECT_FALSE(realTimeFactor(5.0, 0.1, 1.0)) << "the simulated clock went back: a reset";
  EXPECT_FALSE(realTimeFactor(0.0, 1.0, 0.0));
  EXPECT_FALSE(realTimeFactor(0.0, 1.0, -1.0));
  const std::optional<double> paused = realTimeFactor(3.0, 3.0, 1.0);
  ASSERT_TRUE(paused);
  EXPECT_EQ(*paused, 0.0);
}

TEST(MeanStepMs, IsTheWindowsStepTimeOverItsSteps) {
  // 60 steps in the window that took 372 ms together: 6.2 ms each.
  const std::optional<double> mean = meanStepMs(120, 1000.0, 180, 1372.0);
  ASSERT_TRUE(mean);
  EXPECT_DOUBLE_EQ(*mean, 6.2);
  // One slow step among fast ones weighs by its share, not as the last step's time would.
  const std::optional<double> withSlow = meanStepMs(0, 0.0, 10, 9 * 5.0 + 41.0);
  ASSERT_TRUE(withSlow);
  EXPECT_DOUBLE_EQ(*withSlow, 8.6);
}

TEST(MeanStepMs, NothingWithoutStepsOrWhenTheCountWentBack) {
  EXPECT_FALSE(meanStepMs(40, 250.0, 40, 250.0)) << "paused: no step in the window";
  EXPECT_FALSE(meanStepMs(400, 2600.0, 30, 300.0)) << "another scene's physics counts anew";
  EXPECT_FALSE(meanStepMs(10, 100.0, 20, 90.0)) << "summed times never go back";
  EXPECT_FALSE(meanStepMs(10, 100.0, 20, std::nan("")));
}

TEST(PaceBetween, FramesStepsRealTimeAndMeanStepWithinOneScene) {
  const auto origin = std::chrono::steady_clock::now();
  const PaceMark start{origin, 7, 40, 300.0, 2.0};
  // 2 s later: 120 steps of 1/60 s that took 1500 ms together.
  const PaceMark end{origin + std::chrono::seconds(2), 7, 160, 1800.0, 4.0};
  const Pace pace = paceBetween(start, end);
  EXPECT_DOUBLE_EQ(pace.wallSeconds, 2.0);
  EXPECT_EQ(pace.steps, 120u);
  ASSERT_TRUE(pace.stepsPerSecond);
  EXPECT_DOUBLE_EQ(*pace.stepsPerSecond, 60.0);
  ASSERT_TRUE(pace.realTimeFactor);
  EXPECT_DOUBLE_EQ(*pace.realTimeFactor, 1.0);
  ASSERT_TRUE(pace.meanStepMs);
  EXPECT_DOUBLE_EQ(*pace.meanStepMs, 12.5);
  // Another scene's physics since the start: its counts and clock are not comparable.
  PaceMark other = end;
  other.sceneId = 8;
  const Pace across = paceBetween(start, other);
  EXPECT_DOUBLE_EQ(across.wallSeconds, 2.0);
  EXPECT_EQ(across.steps, 0u);
  EXPECT_FALSE(across.stepsPerSecond);
  EXPECT_FALSE(across.realTimeFactor);
  EXPECT_FALSE(across.meanStepMs);
  // Paused while painting: frames are published, no step is taken.
  const Pace paused = paceBetween(end, PaceMark{end.at + std::chrono::seconds(1), 7, 160,
                                                1800.0, 4.0});
  ASSERT_TRUE(paused.stepsPerSecond);
  EXPECT_EQ(*paused.stepsPerSecond, 0.0);
  EXPECT_FALSE(paused.meanStepMs);
}

TEST(PaceBetween, AMarkTakesTheFramesCounts) {
  SceneFrame frame;
  frame.sceneId = 3;
  frame.steps = 9;
  frame.stepMsTotal = 81.5;
  frame.simulatedTime = 0.15;
  const auto at = std::chrono::steady_clock::now();
  const PaceMark mark = paceMark(frame, at);
  EXPECT_EQ(mark.at, at);
  EXPECT_EQ(mark.sceneId, 3u);
  EXPECT_EQ(mark.steps, 9u);
  EXPECT_EQ(mark.stepMsTotal, 81.5);
  EXPECT_EQ(mark.simulatedTime, 0.15);
}

}  // namespace
}  // namespace sculpt::app
