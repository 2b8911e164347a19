#include "sculpt/real_time_factor.h"

#include <gtest/gtest.h>

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
}

TEST(RealTimeFactor, NothingForAResetOrAnEmptyWindow) {
  EXPECT_FALSE(realTimeFactor(5.0, 0.1, 1.0)) << "the simulated clock went back: a reset";
  EXPECT_FALSE(realTimeFactor(0.0, 1.0, 0.0));
  EXPECT_FALSE(realTimeFactor(0.0, 1.0, -1.0));
  const std::optional<double> paused = realTimeFactor(3.0, 3.0, 1.0);
  ASSERT_TRUE(paused);
  EXPECT_EQ(*paused, 0.0);
}

}  // namespace
}  // namespace sculpt::app
