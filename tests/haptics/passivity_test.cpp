// The sampled virtual wall on a PHANTOM-class 1-DOF device (passivity_harness.h): passive at the
// devices' stable stiffness, visibly active (energy growing many times over) well above it, with
// the onset near Colgate's bound K = 2 b / T.

#include <cstdio>

#include <gtest/gtest.h>

#include "tests/haptics/passivity_harness.h"

namespace sculpt::haptics {
namespace {

struct Device {
  const char* name;
  double stableStiffness;  // N/m at 1 kHz (CHAI3D's figures)
};
constexpr Device kTouch{"Touch", 400.0}, kOmni{"Omni", 700.0};

PassivityResult runAndPrint(const PassivityRig& rig, const char* label, double K, double B) {
  const PassivityResult r = runWall(rig, K, B);
  std::printf(
      "passivity: %-12s K = %6.0f N/m, b_virtual = %.2f N s/m: peak energy %.3fx initial, "
      "final %.3gx (%s)\n",
      label, K, B, r.peakRatio(), r.finalRatio(), r.passive() ? "passive" : "ACTIVE");
  return r;
}

TEST(Passivity, WallAtTheStableStiffnessNeverGainsEnergyAndDecays) {
  const PassivityRig rig;
  for (const Device& device : {kTouch, kOmni}) {
    for (const double damping : {0.0, 0.1}) {
      const PassivityResult r = runAndPrint(rig, device.name, device.stableStiffness, damping);
      EXPECT_TRUE(r.passive()) << device.name << " damping " << damping;
      EXPECT_LE(r.peakEnergy, 1.05 * r.initialEnergy + 1e-12);
      EXPECT_LT(r.finalRatio(), 0.01) << "the energy decays to rest";
    }
  }
}

TEST(Passivity, TheSameHarnessFlagsAWallTenToTwentyTimesTooStiff) {
  const PassivityRig rig;
  for (const Device& device : {kTouch, kOmni}) {
    for (const double factor : {10.0, 20.0}) {
      for (const double damping : {0.0, 0.1}) {
        const double K = factor * device.stableStiffness;
        const PassivityResult r = runAndPrint(rig, device.name, K, damping);
        EXPECT_FALSE(r.passive()) << device.name << " K " << K;
        EXPECT_GT(r.peakRatio(), factor >= 20.0 ? 10.0 : 5.0) << device.name << " K " << K;
        EXPECT_GT(r.finalRatio(), 1.0) << "still chattering at the end";
      }
    }
  }
}

TEST(Passivity, EnergyGrowthStartsNearColgatesBound) {
  const PassivityRig rig;
  const double bound = rig.colgateStiffness();  // 2 b / T = 1000 N/m
  double onset = 0;
  for (double K = 0.5 * bound; K <= 3.0 * bound; K += 0.05 * bound) {
    const PassivityResult r = runWall(rig, K, 0.0);
    if (!r.passive()) {
      onset = K;
      break;
    }
  }
  std::printf("passivity: energy growth starts at K = %.0f N/m; Colgate's 2 b / T = %.0f N/m\n",
              onset, bound);
  EXPECT_GE(onset, 0.8 * bound);
  EXPECT_LE(onset, 1.6 * bound);
  // Just under the bound the energy still dies away.
  EXPECT_LT(runWall(rig, 0.8 * bound, 0.0).finalRatio(), 0.01);
}

TEST(Passivity, ASingleBounceWithoutTheHandShowsTheSameVerdict) {
  // Pushed in at 0.2 m/s and let go: the device bounces off once and leaves.
  PassivityRig rig;
  rig.handForce = 0.0;
  for (const Device& device : {kTouch, kOmni}) {
    EXPECT_TRUE(runAndPrint(rig, device.name, device.stableStiffness, 0.0).passive());
    const PassivityResult stiff = runAndPrint(rig, device.name, 20 * device.stableStiffness, 0.0);
    EXPECT_FALSE(stiff.passive());
    EXPECT_GT(stiff.peakRatio(), 1.2) << "it leaves faster than it came";
  }
}

TEST(Passivity, WallForceLaw) {
  EXPECT_EQ(wallForce(0.001, -1.0, 400, 2), 0.0) << "outside: nothing";
  EXPECT_EQ(wallForce(0.0, -1.0, 400, 2), 0.0) << "on the surface: nothing";
  EXPECT_DOUBLE_EQ(wallForce(-0.01, 0.0, 400, 2), 4.0) << "spring";
  EXPECT_DOUBLE_EQ(wallForce(-0.01, -0.5, 400, 2), 5.0) << "damper resists going in";
  EXPECT_DOUBLE_EQ(wallForce(-0.01, 1.0, 400, 2), 2.0) << "damper slows going out";
  EXPECT_EQ(wallForce(-0.01, 3.0, 400, 2), 0.0) << "never pulls into the wall";
}

}  // namespace
}  // namespace sculpt::haptics
