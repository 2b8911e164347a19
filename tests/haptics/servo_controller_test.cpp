// The servo's tick on a manual clock: which stroke it renders, ramps, and the safety's last word.

#include <gtest/gtest.h>

#include "haptics/mock/mock_phantom.h"

#include "haptics/servo/servo_controller.h"

namespace sculpt::haptics {
namespace {

DeviceInfo touch() { return MockPhantom::modelInfo(PhantomModel::kTouch); }

struct Bench {
  ServoController servo{touch(), SafetySettings::forMaxForce(3.3)};
  SceneProbe probe;
  ServoTickInput in;
  Bench() {
    probe.generation = 1;
    probe.strokeCount = 1;
    probe.strokes[0].strokeId = 7;
    probe.strokes[0].point = Eigen::Vector3d::Zero();
    probe.strokes[0].stiffness = 1000;  // scene N/m
    in.probe = &probe;
    in.device.connected = true;
    in.device.position = Eigen::Vector3d(0.001, 0, 0);  // 1 mm: 1 N of coupling at S = 1
    in.command.strokeId = 7;
    in.command.tool = HapticTool::Pull;
    in.command.forceScale = 1.0;
  }
  ServoTickResult run(int ticks) {
    ServoTickResult r;
    for (int i = 0; i < ticks; ++i) r = servo.tick(in);
    return r;
  }
};

TEST(ServoController, RendersTheCommandedStrokesCouplingAfterTheRamp) {
  Bench b;
  const ServoTickResult first = b.run(1);
  EXPECT_NEAR(first.desired.x(), -1.0, 1e-12) << "the coupling pulls the hand back to the point";
  EXPECT_LT(first.commanded.norm(), 0.01) << "ramped in from zero on grab";
  const ServoTickResult settled = b.run(600);  // past the 0.5 s ramp
  EXPECT_NEAR(settled.commanded.x(), -1.0, 1e-12);
  EXPECT_TRUE(settled.acting);
  EXPECT_NEAR(settled.onSolid.x(), 1.0, 1e-12);
}

TEST(ServoController, AStrokeNotInTheProbeYetGivesNoForce) {
  Bench b;
  b.in.command.strokeId = 8;
  const ServoTickResult r = b.run(600);
  EXPECT_FALSE(r.acting);
  EXPECT_EQ(r.commanded.norm(), 0.0);
}

TEST(ServoController, DisconnectFocusLossAndPanicZeroAtOnce) {
  Bench b;
  ASSERT_GT(b.run(600).commanded.norm(), 0.9);
  b.in.device.connected = false;
  EXPECT_EQ(b.run(1).commanded.norm(), 0.0) << "unplugged: zero in the same tick";
  b.in.device.connected = true;
  EXPECT_LT(b.run(1).commanded.norm(), 0.01) << "back: ramps in again";
  ASSERT_GT(b.run(600).commanded.norm(), 0.9);
  b.in.command.focused = false;
  EXPECT_EQ(b.run(1).commanded.norm(), 0.0);
  b.in.command.focused = true;
  b.run(600);
  b.in.command.panic = true;
  EXPECT_EQ(b.run(1).commanded.norm(), 0.0);
  b.in.command.panic = false;
  EXPECT_EQ(b.run(600).commanded.norm(), 0.0) << "panic latches until re-armed";
  b.in.command.rearmCount = 1;
  EXPECT_GT(b.run(600).commanded.norm(), 0.9);
}

TEST(ServoController, InflateResistanceIsASmallCappedSpringToTheAnchor) {
  Bench b;
  b.in.command.tool = HapticTool::Inflate;
  b.in.command.inflateStiffness = 40;
  b.in.command.inflateMaxForce = 0.5;
  b.in.command.inflateAnchor = Eigen::Vector3d::Zero();
  b.in.device.position = Eigen::Vector3d(0, 0.01, 0);
  EXPECT_NEAR(b.run(600).commanded.y(), -0.4, 1e-12);
  b.in.device.position = Eigen::Vector3d(0, 0.1, 0);
  EXPECT_NEAR(b.run(100).commanded.norm(), 0.5, 1e-12) << "capped";
}

TEST(ServoController, FindStrokeMatchesTheIdAmongTheProbesStrokes) {
  SceneProbe probe;
  probe.strokeCount = 3;
  for (int i = 0; i < 3; ++i) probe.strokes[i].strokeId = 10 + i;
  EXPECT_EQ(findStroke(probe, 11), &probe.strokes[1]);
  EXPECT_EQ(findStroke(probe, 13), nullptr);
  EXPECT_EQ(findStroke(probe, 0), nullptr);
}

}  // namespace
}  // namespace sculpt::haptics
