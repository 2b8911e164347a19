#include "haptics/mock/mock_phantom.h"

#include <cmath>
#include <limits>
#include <thread>

#include <gtest/gtest.h>

namespace sculpt::haptics {
namespace {

DeviceScript script(ScriptMode mode, std::vector<ScriptKey> keys,
                    PhantomModel model = PhantomModel::kTouch) {
  DeviceScript s;
  s.model = model;
  s.mode = mode;
  s.hand = {300.0, 5.0, 0.1};
  s.keys = std::move(keys);
  return s;
}

TEST(MockPhantom, HasTouchAndOmniLimits) {
  const DeviceInfo touch = MockPhantom::modelInfo(PhantomModel::kTouch);
  EXPECT_EQ(touch.model, "Mock Touch");
  EXPECT_EQ(touch.maxForce, 3.3);
  EXPECT_EQ(touch.stableStiffness, 400.0);
  EXPECT_EQ(touch.damping, 4.0);
  EXPECT_EQ(touch.workspaceRadius, 0.075);
  EXPECT_EQ(touch.capabilities,
            kSensesPosition | kSensesRotation | kSensesButtons | kActuatesForce);
  EXPECT_TRUE(touch.hasForce());
  EXPECT_FALSE(touch.rateControl());
  const DeviceInfo omni = MockPhantom::modelInfo(PhantomModel::kOmni);
  EXPECT_EQ(omni.model, "Mock Omni");
  EXPECT_EQ(omni.maxForce, 3.3);
  EXPECT_EQ(omni.stableStiffness, 700.0);
  EXPECT_EQ(omni.damping, 5.0);
  EXPECT_EQ(omni.workspaceRadius, 0.10);
  MockPhantom device(
      script(ScriptMode::kTrajectory, {{0, {0, 0, 0}, 0, false}}, PhantomModel::kOmni));
  EXPECT_EQ(device.info().model, "Mock Omni");
  EXPECT_EQ(device.mode(), MockMode::kTrajectory);
}

TEST(MockPhantom, TrajectoryFollowsTheScriptExactlyWhateverTheForce) {
  MockPhantom device(script(ScriptMode::kTrajectory, {{0.0, {0, 0, 0}, 0, false},
                                                      {0.5, {0.05, -0.02, 0.01}, 1, false},
                                                      {1.0, {0.05, -0.02, 0.01}, 0, true}}));
  for (int tick = 0; tick <= 1200; ++tick) {
    const double t = 0.001 * tick;
    const DeviceSample s = device.read(t);
    ASSERT_EQ(s.position, device.script().sample(t).position) << "t " << t;
    ASSERT_TRUE(s.connected);
    EXPECT_EQ(s.time, t);
    EXPECT_TRUE(s.orientation.isApprox(Eigen::Quaterniond::Identity()));
    if (tick == 250) {
      EXPECT_EQ(s.buttons, 0u);
      EXPECT_NEAR((s.velocity - Eigen::Vector3d(0.1, -0.04, 0.02)).norm(), 0.0, 1e-9)
          << "velocity from the estimator";
    }
    if (tick == 700) {
      EXPECT_EQ(s.buttons, 1u);
    }
    if (tick == 1100) {
      EXPECT_EQ(s.buttons, MockPhantom::kClutchButton) << "the clutch button";
    }
    device.sendForce(Eigen::Vector3d(3.3, -3.3, 3.3));  // no effect on a trajectory
  }
}

TEST(MockPhantom, HandSettlesAtTheScriptPlusForceOverHandStiffness) {
  const Eigen::Vector3d home(0.01, 0.02, -0.01);
  MockPhantom device(script(ScriptMode::kHand, {{0.0, home, 0, false}}));
  EXPECT_EQ(device.read(0.0).position, home) << "the hand starts at rest on the script";
  const Eigen::Vector3d force(0.9, -0.6, 0.3);
  DeviceSample s;
  for (int tick = 1; tick <= 3000; ++tick) {
    device.sendForce(force);
    s = device.read(0.001 * tick);
  }
  const Eigen::Vector3d expected = home + force / 300.0;  // 3 mm, 2 mm, 1 mm away
  EXPECT_LT((s.position - expected).norm(), 0.01 * (force / 300.0).norm())
      << s.position.transpose() << " vs " << expected.transpose();
  EXPECT_LT(s.velocity.norm(), 1e-6);
  // Released: back on the script.
  for (int tick = 3001; tick <= 6000; ++tick) {
    device.sendForce(Eigen::Vector3d::Zero());
    s = device.read(0.001 * tick);
  }
  EXPECT_LT((s.position - home).norm(), 1e-6);
}

TEST(MockPhantom, HandFollowsAMovingScriptWithoutLagWhenNoForceIsSent) {
  // The hand's damper acts on the velocity relative to the script's, so a steady motion is
  // tracked once the start-up transient has died (to the substep's h v = 5 um).
  MockPhantom device(
      script(ScriptMode::kHand, {{0.0, {-0.05, 0, 0}, 0, false}, {2.0, {0.05, 0, 0}, 0, false}}));
  DeviceSample s;
  for (int tick = 0; tick <= 1500; ++tick) s = device.read(0.001 * tick);
  EXPECT_LT((s.position - device.script().sample(1.5).position).norm(), 1e-5);
  EXPECT_NEAR(s.velocity.x(), 0.05, 1e-6);
  // A force makes it lag behind by force / stiffness.
  for (int tick = 1501; tick <= 1900; ++tick) {
    device.sendForce(Eigen::Vector3d(-1.5, 0, 0));
    s = device.read(0.001 * tick);
  }
  EXPECT_NEAR(s.position.x() - device.script().sample(1.9).position.x(), -1.5 / 300.0, 5e-5);
}

TEST(MockPhantom, RecordsEveryForceInOrderWithItsTime) {
  MockPhantom device(script(ScriptMode::kHand, {{0.0, {0, 0, 0}, 0, false}}));
  for (int tick = 0; tick < 10; ++tick) {
    device.read(0.001 * tick);
    device.sendForce(Eigen::Vector3d(0.1 * tick, 0, -0.1 * tick));
  }
  ASSERT_EQ(device.forces().size(), 10u);
  for (int tick = 0; tick < 10; ++tick) {
    EXPECT_EQ(device.forces()[tick].time, 0.001 * tick);
    EXPECT_EQ(device.forces()[tick].force, Eigen::Vector3d(0.1 * tick, 0, -0.1 * tick));
  }
  EXPECT_EQ(device.droppedForces(), 0u);
}

TEST(MockPhantom, RecordsNonFiniteForcesButRendersThemAsZero) {
  const Eigen::Vector3d home(0, 0.01, 0);
  MockPhantom device(script(ScriptMode::kHand, {{0.0, home, 0, false}}));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  DeviceSample s = device.read(0.0);
  for (int tick = 1; tick <= 500; ++tick) {
    device.sendForce(Eigen::Vector3d(nan, 1.0, std::numeric_limits<double>::infinity()));
    s = device.read(0.001 * tick);
  }
  EXPECT_EQ(s.position, home) << "nothing rendered";
  ASSERT_EQ(device.forces().size(), 500u);
  EXPECT_TRUE(std::isnan(device.forces().back().force.x()));
}

TEST(MockPhantom, StopsRecordingAtItsCapacityAndCounts) {
  MockPhantom device(script(ScriptMode::kTrajectory, {{0.0, {0, 0, 0}, 0, false}}), 3);
  for (int i = 0; i < 5; ++i) device.sendForce(Eigen::Vector3d(i, 0, 0));
  ASSERT_EQ(device.forces().size(), 3u);
  EXPECT_EQ(device.forces()[2].force.x(), 2.0);
  EXPECT_EQ(device.droppedForces(), 2u);
}

TEST(MockPhantom, UnpluggedReadsDisconnectedAndRendersNoForce) {
  const Eigen::Vector3d home(0, 0, 0.02);
  MockPhantom device(script(ScriptMode::kHand, {{0.0, home, 0, false}}));
  EXPECT_TRUE(device.read(0.0).connected);
  device.setConnected(false);
  DeviceSample s;
  for (int tick = 1; tick <= 300; ++tick) {
    device.sendForce(Eigen::Vector3d(2.0, 0, 0));
    s = device.read(0.001 * tick);
    ASSERT_FALSE(s.connected);
  }
  EXPECT_EQ(s.position, home);
  device.setConnected(true);
  device.sendForce(Eigen::Vector3d(2.0, 0, 0));
  s = device.read(0.301);
  EXPECT_TRUE(s.connected);
  EXPECT_GT(s.position.x(), 0.0) << "the force is felt again";
}

TEST(MockPhantom, ExternalModeFollowsTheSetPointFromAnotherThread) {
  MockPhantom device(PhantomModel::kTouch, HandDynamics{400.0, 6.0, 0.1});
  EXPECT_EQ(device.mode(), MockMode::kExternal);
  EXPECT_EQ(device.read(0.0).position, Eigen::Vector3d::Zero()) << "the centre until set";
  const Eigen::Vector3d target(0.02, -0.01, 0.03);
  std::thread window([&] { device.setHandTarget(target, 1u); });
  window.join();
  DeviceSample s;
  for (int tick = 1; tick <= 2000; ++tick) {
    device.sendForce(Eigen::Vector3d(0, 0.8, 0));
    s = device.read(0.001 * tick);
  }
  EXPECT_EQ(s.buttons, 1u);
  EXPECT_LT((s.position - (target + Eigen::Vector3d(0, 0.8 / 400.0, 0))).norm(), 1e-6);
}

}  // namespace
}  // namespace sculpt::haptics
