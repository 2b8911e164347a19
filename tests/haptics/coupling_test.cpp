// The force laws between the scene and the hand, against their closed forms.

#include <gtest/gtest.h>

#include "haptics/mock/mock_phantom.h"

#include <cmath>

#include "haptics/servo/coupling.h"
#include "haptics/servo/force_scale.h"

namespace sculpt::haptics {
namespace {

DeviceInfo touch() { return MockPhantom::modelInfo(PhantomModel::kTouch); }

TEST(Coupling, TheHandFeelsTheOppositeOfTheSolidsForceScaledAndRotated) {
  WorkspaceMapping mapping = WorkspaceMapping::fit(0.075, Eigen::Vector3d(1, 2, 3), 7.5);
  mapping.rotation =
      Eigen::Quaterniond(Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()));
  ProbeStroke stroke;
  stroke.point = Eigen::Vector3d(1.2, 2.1, 2.9);
  stroke.stiffness = 5.0e4;
  CouplingInput in;
  in.stroke = &stroke;
  in.toolScene = Eigen::Vector3d(1.5, 2.6, 3.2);
  in.forceScale = 2.0e3;
  const CouplingForces f = couplingForces(in, mapping);
  ASSERT_TRUE(f.acting);
  EXPECT_LT((f.onSolid - 5.0e4 * (in.toolScene - stroke.point)).norm(), 1e-9 * f.onSolid.norm());
  // Back in the scene frame and scale, the hand's force is exactly -F.
  const Eigen::Vector3d handInScene = mapping.rotation * f.onHand * in.forceScale;
  EXPECT_LT((handInScene + f.onSolid).norm(), 1e-12 * f.onSolid.norm());
}

TEST(Coupling, ExtrapolatesTheMaterialPointOverTheProbeAgeUpToTheLimit) {
  const WorkspaceMapping mapping;
  ProbeStroke stroke;
  stroke.point = Eigen::Vector3d::Zero();
  stroke.velocity = Eigen::Vector3d(1, 0, 0);
  stroke.stiffness = 100;
  CouplingInput in;
  in.stroke = &stroke;
  in.toolScene = Eigen::Vector3d(0.5, 0, 0);
  in.probeAge = 0.01;
  EXPECT_NEAR(couplingForces(in, mapping).onSolid.x(), 100 * (0.5 - 0.01), 1e-12);
  in.probeAge = 1.0;  // clamped at maxExtrapolation
  EXPECT_NEAR(couplingForces(in, mapping).onSolid.x(), 100 * (0.5 - in.maxExtrapolation), 1e-12);
}

TEST(Coupling, AContactOnlyPushesWhileTheToolIsInside) {
  const WorkspaceMapping mapping;
  ProbeStroke stroke;
  stroke.point = Eigen::Vector3d::Zero();
  stroke.normal = Eigen::Vector3d::UnitY();
  stroke.stiffness = 100;
  CouplingInput in;
  in.stroke = &stroke;
  in.toolScene = Eigen::Vector3d(0.1, -0.02, 0);  // 2 cm inside
  const CouplingForces inside = couplingForces(in, mapping);
  ASSERT_TRUE(inside.acting);
  EXPECT_GT(inside.onHand.y(), 0) << "pushed out of the surface";
  in.toolScene.y() = 0.001;  // withdrawn: nothing, before the simulation notices
  EXPECT_FALSE(couplingForces(in, mapping).acting);
  EXPECT_EQ(couplingForces(in, mapping).onHand.norm(), 0.0);
}

TEST(ForceScale, ARigidGrabFeelsHalfTheStableStiffnessAndAFullPullEightyPercentOfTheLimit) {
  const DeviceInfo device = touch();
  const double sceneRadius = 7.88, youngs = 1.0e5;
  const double W = sceneRadius / device.workspaceRadius;
  const ForceScale scale = chooseForceScale(device, W, youngs, sceneRadius);
  const double S = scale.sceneNewtonsPerDeviceNewton;
  // Rigid grab: scene spring k_c seen through the mapping and the scale.
  EXPECT_NEAR(scale.pullStiffness * W / S, 0.5 * device.stableStiffness, 1e-9);
  // Full pull: coupling in series with the solid's E R, over one workspace radius.
  const double kSolid = youngs * sceneRadius, kc = scale.pullStiffness;
  const double felt = (kc * kSolid / (kc + kSolid)) * device.workspaceRadius * W / S;
  EXPECT_NEAR(felt, 0.8 * device.maxForce, 1e-9);
  // The user factor makes the scene lighter without changing the rigid feel.
  const ForceScale lighter = chooseForceScale(device, W, youngs, sceneRadius, 2.0);
  EXPECT_NEAR(lighter.sceneNewtonsPerDeviceNewton, 2 * S, 1e-9 * S);
  EXPECT_NEAR(lighter.pullStiffness * W / lighter.sceneNewtonsPerDeviceNewton, 200.0, 1e-9);
}

TEST(ForceScale, ContactStiffnessFollowsYoungsModulusInsideTheStableRange) {
  const ForceScale scale = chooseForceScale(touch(), 100, 1e5, 7.5);
  EXPECT_NEAR(scale.contactDeviceStiffness(1e5), 0.5 * 400, 1e-9);
  EXPECT_NEAR(scale.contactDeviceStiffness(1e6), 0.8 * 400, 1e-9);
  EXPECT_NEAR(scale.contactDeviceStiffness(1e4), 0.2 * 400, 1e-9);
  EXPECT_NEAR(scale.contactDeviceStiffness(1e9), 0.8 * 400, 1e-9) << "never above the range";
  EXPECT_GT(scale.contactDeviceStiffness(1e6), scale.contactDeviceStiffness(1e5));
}

TEST(ForceScale, ADeviceWithoutForceGetsUnitScale) {
  DeviceInfo mouse;
  mouse.capabilities = kSensesPosition;
  const ForceScale scale = chooseForceScale(mouse, 10, 1e5, 1);
  EXPECT_EQ(scale.sceneNewtonsPerDeviceNewton, 1.0);
  EXPECT_EQ(scale.pullStiffness, 0.0);
}

}  // namespace
}  // namespace sculpt::haptics
