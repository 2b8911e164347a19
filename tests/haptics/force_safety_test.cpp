#include "haptics/servo/force_safety.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>

#include <gtest/gtest.h>

namespace sculpt::haptics {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

SafetyInput steady(const Eigen::Vector3d& desired, double dt = 0.001) {
  SafetyInput in;
  in.desired = desired;
  in.dt = dt;
  return in;
}

/// Settings with the ramp and the step limit out of the way, to look at one rule at a time.
SafetySettings instant() {
  SafetySettings s;
  s.rampTime = 0.0;
  s.maxForceStep = 1e9;
  return s;
}

TEST(ForceSafety, DefaultsFollowTheDesign) {
  const SafetySettings s = SafetySettings::forMaxForce(7.9);
  EXPECT_EQ(s.maxForce, 7.9);
  EXPECT_DOUBLE_EQ(s.maxForceStep, 0.05 * 7.9);
  EXPECT_EQ(s.rampTime, 0.5);
  EXPECT_EQ(s.staleAfter, 0.05);
  EXPECT_EQ(s.fadeTime, 0.05);
  EXPECT_EQ(s.overrunDt, 0.005);
}

TEST(ForceSafety, ClampsTheMagnitudeKeepingTheDirection) {
  ForceSafety safety(instant());
  const Eigen::Vector3d out = safety.filter(steady({30, 40, 0}));
  EXPECT_NEAR(out.x(), 3.3 * 0.6, 1e-12);
  EXPECT_NEAR(out.y(), 3.3 * 0.8, 1e-12);
  EXPECT_EQ(out.z(), 0.0);
  EXPECT_LE(out.norm(), 3.3);
  EXPECT_EQ(safety.stats().clampedTicks, 1u);
  // A small force passes unchanged.
  EXPECT_EQ(safety.filter(steady({0.5, -1, 0.25})), Eigen::Vector3d(0.5, -1, 0.25));
}

TEST(ForceSafety, ClampsHugeFiniteForcesWithoutOverflow) {
  ForceSafety safety(instant());
  const Eigen::Vector3d out = safety.filter(steady({1e308, -1e308, 1e308}));
  EXPECT_TRUE(out.allFinite());
  EXPECT_LE(out.norm(), 3.3);
  EXPECT_NEAR(out.x(), 3.3 / std::sqrt(3.0), 1e-12);
  EXPECT_NEAR(out.y(), -3.3 / std::sqrt(3.0), 1e-12);
  EXPECT_FALSE(safety.tripped());
}

TEST(ForceSafety, LimitsTheStepPerTick) {
  SafetySettings s = instant();
  s.maxForceStep = 0.165;
  ForceSafety safety(s);
  for (int k = 1; k <= 18; ++k)
    EXPECT_NEAR(safety.filter(steady({3, 0, 0})).x(), 0.165 * k, 1e-12) << "tick " << k;
  EXPECT_NEAR(safety.filter(steady({3, 0, 0})).x(), 3.0, 1e-12);
  EXPECT_NEAR(safety.filter(steady({3, 0, 0})).x(), 3.0, 1e-12);
  EXPECT_EQ(safety.stats().slewLimitedTicks, 18u);
  // Reversing: down by one step a tick too.
  EXPECT_NEAR(safety.filter(steady({-3, 0, 0})).x(), 3.0 - 0.165, 1e-12);
}

TEST(ForceSafety, RampsInLinearlyFromStart) {
  SafetySettings s = instant();
  s.rampTime = 0.5;
  ForceSafety safety(s);
  for (int k = 1; k <= 500; ++k)
    ASSERT_NEAR(safety.filter(steady({1, 0, 0})).x(), 0.002 * k, 1e-12) << "tick " << k;
  EXPECT_NEAR(safety.rampGain(), 1.0, 1e-12);
  EXPECT_EQ(safety.filter(steady({1, 0, 0})).x(), 1.0);
  // An overrun tick does not ramp faster than overrunDt allows.
  ForceSafety late(s);
  SafetyInput in = steady({1, 0, 0}, 0.02);
  in.probeAge = 0;
  late.filter(in);
  EXPECT_NEAR(late.rampGain(), 0.005 / 0.5, 1e-15);
}

TEST(ForceSafety, RampInOnGrabSlewsDownThenRampsAgain) {
  SafetySettings s;
  s.maxForceStep = 0.165;
  ForceSafety safety(s);
  for (int k = 0; k < 600; ++k) safety.filter(steady({2, 0, 0}));
  ASSERT_EQ(safety.lastForce().x(), 2.0);
  safety.rampIn();
  // The target is 0.002 * 2 N; the force comes down one step a tick (no drop).
  EXPECT_NEAR(safety.filter(steady({2, 0, 0})).x(), 2.0 - 0.165, 1e-12);
  for (int k = 0; k < 30; ++k) safety.filter(steady({2, 0, 0}));
  // 31 ticks after the grab: on the ramp, 31 * 0.002 of 2 N.
  EXPECT_NEAR(safety.lastForce().x(), 31 * 0.002 * 2.0, 1e-12);
}

void expectImmediateZeroThenRampIn(void (*set)(SafetyInput&, bool), bool latches) {
  ForceSafety safety(SafetySettings{});
  for (int k = 0; k < 600; ++k) safety.filter(steady({0, 3, 0}));
  ASSERT_EQ(safety.lastForce(), Eigen::Vector3d(0, 3, 0));
  SafetyInput in = steady({0, 3, 0});
  set(in, true);
  EXPECT_EQ(safety.filter(in), Eigen::Vector3d::Zero()) << "zero within the tick";
  EXPECT_EQ(safety.tripped(), latches);
  set(in, false);
  if (latches) {
    for (int k = 0; k < 10; ++k) EXPECT_EQ(safety.filter(in), Eigen::Vector3d::Zero());
    safety.rearm();
    EXPECT_FALSE(safety.tripped());
  }
  // Back: ramps in from zero (0.002 of 3 N on the first tick).
  EXPECT_NEAR(safety.filter(in).y(), 0.006, 1e-12);
  EXPECT_NEAR(safety.filter(in).y(), 0.012, 1e-12);
}

TEST(ForceSafety, ZeroesAtOnceOnDisconnectFocusLossAndShutdown) {
  expectImmediateZeroThenRampIn([](SafetyInput& in, bool on) { in.connected = !on; }, false);
  expectImmediateZeroThenRampIn([](SafetyInput& in, bool on) { in.focused = !on; }, false);
  expectImmediateZeroThenRampIn([](SafetyInput& in, bool on) { in.shuttingDown = on; }, false);
}

TEST(ForceSafety, PanicAndDeviceErrorsTripUntilRearmed) {
  expectImmediateZeroThenRampIn([](SafetyInput& in, bool on) { in.panic = on; }, true);
  expectImmediateZeroThenRampIn([](SafetyInput& in, bool on) { in.deviceError = on; }, true);
  ForceSafety safety;
  SafetyInput in = steady({1, 0, 0});
  in.panic = true;
  safety.filter(in);
  EXPECT_EQ(safety.tripReason(), "panic");
  EXPECT_EQ(safety.stats().trips, 1u);
}

TEST(ForceSafety, NonFiniteInputZeroesAndLatchesUntilRearm) {
  const auto nanDesired = [](SafetyInput& in, bool on) { in.desired.z() = on ? kNaN : 0.0; };
  const auto infDt = [](SafetyInput& in, bool on) { in.dt = on ? kInf : 0.001; };
  const auto nanAge = [](SafetyInput& in, bool on) { in.probeAge = on ? kNaN : 0.0; };
  const auto infDesired = [](SafetyInput& in, bool on) { in.desired.x() = on ? -kInf : 0.0; };
  expectImmediateZeroThenRampIn(nanDesired, true);
  expectImmediateZeroThenRampIn(infDt, true);
  expectImmediateZeroThenRampIn(nanAge, true);
  expectImmediateZeroThenRampIn(infDesired, true);

  ForceSafety safety;
  SafetyInput in = steady({1, 0, 0});
  in.dt = kNaN;
  safety.filter(in);
  EXPECT_EQ(safety.tripReason(), "non-finite tick length (dt)");
  // Rearming while the input is still bad trips again at once.
  safety.rearm();
  EXPECT_EQ(safety.filter(in), Eigen::Vector3d::Zero());
  EXPECT_TRUE(safety.tripped());
  EXPECT_EQ(safety.stats().trips, 2u);
}

TEST(ForceSafety, StaleProbeFadesToExactlyZeroAtStaleAfterPlusFadeTime) {
  ForceSafety safety(instant());
  SafetyInput in = steady({1, 0, 0});
  EXPECT_EQ(safety.filter(in).x(), 1.0);
  // The probe stops: its age grows by a tick each tick. 0.05 s is still fresh.
  for (int k = 1; k <= 100; ++k) {
    in.probeAge = 0.001 * k;
    const double expected = k <= 50 ? 1.0 : std::max(0.0, 1.0 - (k - 50) / 50.0);
    ASSERT_NEAR(safety.filter(in).x(), expected, 1e-9) << "age " << in.probeAge;
    if (k >= 100) {
      EXPECT_EQ(safety.lastForce().x(), 0.0);
    }
  }
  // Fresh again: the fade gain rises at the ramp rate (instant here).
  in.probeAge = 0;
  EXPECT_EQ(safety.filter(in).x(), 1.0);

  // Default ramp: back at 1/rampTime.
  ForceSafety ramped;
  SafetyInput r = steady({1, 0, 0});
  for (int k = 0; k < 600; ++k) ramped.filter(r);
  r.probeAge = 0.2;
  EXPECT_EQ(ramped.filter(r), Eigen::Vector3d::Zero()) << "an old probe: zero whatever the slew";
  r.probeAge = 0.0;
  EXPECT_NEAR(ramped.filter(r).x(), 0.002, 1e-12);
  EXPECT_NEAR(ramped.filter(r).x(), 0.004, 1e-12);
}

TEST(ForceSafety, TheFadeRecoversOverRecoverTimeWhenSet) {
  SafetySettings s;
  s.recoverTime = 0.05;
  ForceSafety safety(s);
  for (int k = 0; k < 600; ++k) safety.filter(steady({1, 0, 0}));
  SafetyInput in = steady({1, 0, 0});
  in.probeAge = 0.2;
  EXPECT_EQ(safety.filter(in), Eigen::Vector3d::Zero());
  in.probeAge = 0.0;
  // Back at 1/recoverTime (0.02 a tick), not at the ramp's 0.002.
  EXPECT_NEAR(safety.filter(in).x(), 0.02, 1e-12);
  EXPECT_NEAR(safety.filter(in).x(), 0.04, 1e-12);
  EXPECT_NEAR(safety.rampGain(), 1.0, 1e-12) << "the ramp itself was never reset";
}

TEST(ForceSafety, OverrunsFadeToZeroWithinFadeTime) {
  ForceSafety safety(SafetySettings{});
  for (int k = 0; k < 600; ++k) safety.filter(steady({3, 0, 0}));
  ASSERT_EQ(safety.lastForce().x(), 3.0);
  // 20 ms ticks: the fade gain loses 0.4 a tick. The target (fade * 3 N) is followed one step a
  // tick, and the ceiling maxForce * fade takes the force down faster when it must (towards
  // zero only): 3 -> min(3 - 0.165, 0.6 * 3.3) -> min(1.98 - 0.165, 0.2 * 3.3) -> 0.
  EXPECT_NEAR(safety.filter(steady({3, 0, 0}, 0.02)).x(), 1.98, 1e-12);
  EXPECT_NEAR(safety.filter(steady({3, 0, 0}, 0.02)).x(), 0.66, 1e-12);
  EXPECT_EQ(safety.filter(steady({3, 0, 0}, 0.02)).x(), 0.0);
  EXPECT_EQ(safety.stats().fadingTicks, 3u);
  // On time again: back at the ramp rate, 0.002 a tick.
  EXPECT_NEAR(safety.filter(steady({3, 0, 0})).x(), 0.006, 1e-12);
  EXPECT_NEAR(safety.filter(steady({3, 0, 0})).x(), 0.012, 1e-12);
  // A 5 ms tick is on time; just over is an overrun.
  ForceSafety edge(instant());
  EXPECT_EQ(edge.filter(steady({1, 0, 0}, 0.005)).x(), 1.0);
  EXPECT_NEAR(edge.filter(steady({1, 0, 0}, 0.006)).x(), 1.0 - 0.006 / 0.05, 1e-12);
}

// ---- Randomised invariants over millions of ticks -------------------------------------------

struct Scenario {
  SafetySettings settings;
  int ticks;
};

struct Coverage {
  uint64_t clamped = 0, slewed = 0, zeroed = 0, faded = 0, fadedToZero = 0, trips = 0,
           fastFades = 0, rearms = 0;
};

/// Runs `ticks` random ticks through one ForceSafety and checks every invariant at every tick.
void runRandomTicks(const SafetySettings& s, int ticks, std::mt19937_64& rng, Coverage& cover) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::normal_distribution<double> gauss(0.0, 1.0);
  const auto chance = [&](double p) { return unit(rng) < p; };
  const auto randomVector = [&] {
    return Eigen::Vector3d(2 * unit(rng) - 1, 2 * unit(rng) - 1, 2 * unit(rng) - 1);
  };
  const double tolerance = 1e-12 * std::max(1.0, s.maxForce);
  const double recoverTime = s.recoverTime >= 0 ? s.recoverTime : s.rampTime;

  ForceSafety safety(s);
  Eigen::Vector3d desired = Eigen::Vector3d::Zero(), previous = Eigen::Vector3d::Zero();
  double previousFade = safety.fadeGain();
  double age = 0.0;
  int stallTicks = 0;
  bool connected = true, focused = true;
  bool latched = false;        // the test's own model of the trip latch
  double unhealthyTime = 0.0;  // consecutive stale or overrun time (s), zeroing ticks excluded
  double rampBound = 0.0;      // the ramp gain since the last zero (the test's own sum)
  bool rampChecked = true;     // false after rampIn() until the next zero

  for (int tick = 0; tick < ticks; ++tick) {
    // Desired force: a wandering force, sudden jumps, spikes of huge values.
    desired = 0.99 * desired + 0.03 * Eigen::Vector3d(gauss(rng), gauss(rng), gauss(rng));
    if (chance(0.01)) desired = 1.5 * s.maxForce * randomVector();

    SafetyInput in;
    in.desired = desired;
    if (chance(0.01)) in.desired = std::pow(10.0, 300 * unit(rng)) * randomVector();
    // dt: 1 ms with jitter, overruns of 5-20 ms, the odd zero.
    in.dt = 0.001 * (1.0 + 0.3 * gauss(rng));
    if (in.dt < 0) in.dt = 0;
    if (chance(0.01)) in.dt = 0.005 + 0.015 * unit(rng);
    if (chance(0.001)) in.dt = 0.0;
    // Probe age: fresh with a few ms of lag, stalls that go stale, old probes out of nowhere.
    age += in.dt;
    if (stallTicks > 0) {
      --stallTicks;
    } else if (chance(0.002)) {
      stallTicks = 20 + static_cast<int>(200 * unit(rng));
    } else if (chance(0.3)) {
      age = 0.01 * unit(rng);
    }
    if (chance(0.001)) age = 0.3 * unit(rng);
    in.probeAge = age;
    // Device and window state.
    // Short spells unplugged or out of focus.
    if (chance(connected ? 1e-4 : 0.01)) connected = !connected;
    if (chance(focused ? 1e-4 : 0.01)) focused = !focused;
    in.connected = connected;
    in.focused = focused;
    in.panic = chance(2e-5);
    in.deviceError = chance(1e-5);
    in.shuttingDown = chance(2e-5);
    // Non-finite injections anywhere.
    if (chance(5e-5)) in.desired[static_cast<int>(3 * unit(rng)) % 3] = chance(0.5) ? kNaN : -kInf;
    if (chance(2e-5)) in.dt = chance(0.5) ? kNaN : kInf;
    if (chance(2e-5)) in.probeAge = chance(0.5) ? kNaN : kInf;
    // The user re-arms a while after a trip; grabs now and then.
    if (latched && chance(0.005)) {
      safety.rearm();
      latched = false;
      previous.setZero();
      rampBound = 0.0;
      rampChecked = true;
      ++cover.rearms;
    }
    if (chance(1e-3)) {
      safety.rampIn();
      rampChecked = false;
    }

    const Eigen::Vector3d out = safety.filter(in);
    const double fade = safety.fadeGain();

    const bool nonFinite =
        !in.desired.allFinite() || !std::isfinite(in.dt) || !std::isfinite(in.probeAge);
    if (nonFinite || in.panic || in.deviceError) latched = true;
    const bool zeroing = latched || !in.connected || !in.focused || in.shuttingDown;

    ASSERT_TRUE(out.allFinite()) << "tick " << tick;
    ASSERT_LE(out.norm(), s.maxForce) << "tick " << tick;
    ASSERT_EQ(safety.tripped(), latched) << "tick " << tick;
    ASSERT_EQ(safety.tripReason().empty(), !latched) << "tick " << tick;
    if (zeroing) {
      // The exception to the step limit: zero, exactly, within the tick.
      ASSERT_EQ(out, Eigen::Vector3d::Zero()) << "tick " << tick;
      ++cover.zeroed;
      rampBound = 0.0;
      rampChecked = true;
    } else {
      const bool stale = in.probeAge > s.staleAfter, overrun = in.dt > s.overrunDt;
      const double dF = (out - previous).norm();
      rampBound =
          std::min(1.0, rampBound + std::min(std::max(in.dt, 0.0), s.overrunDt) / s.rampTime);
      if (stale || overrun) {
        ++cover.faded;
        unhealthyTime += in.dt;
        // The fade falls at least at 1/fadeTime, and to zero by staleAfter + fadeTime of age.
        ASSERT_LE(fade, std::max(0.0, previousFade - in.dt / s.fadeTime) + 1e-12) << tick;
        if (stale) {
          ASSERT_LE(fade, std::max(0.0, 1.0 - (in.probeAge - s.staleAfter) / s.fadeTime) + 1e-12)
              << "tick " << tick;
        }
        // The second exception: faster than the step limit only by the fade lost, towards zero.
        const double fadeLost = std::max(0.0, previousFade - fade);
        ASSERT_LE(dF, s.maxForceStep + s.maxForce * fadeLost + tolerance) << "tick " << tick;
        ASSERT_LE(out.norm(), previous.norm() + s.maxForceStep + tolerance) << "tick " << tick;
        if (dF > s.maxForceStep + tolerance) ++cover.fastFades;
        if (unhealthyTime >= s.fadeTime + 1e-12 ||
            (stale && in.probeAge >= s.staleAfter + s.fadeTime)) {
          ASSERT_EQ(out, Eigen::Vector3d::Zero()) << "tick " << tick;
          ++cover.fadedToZero;
        }
      } else {
        unhealthyTime = 0.0;
        ASSERT_LE(dF, s.maxForceStep + tolerance) << "tick " << tick;
        ASSERT_LE(fade,
                  std::min(1.0, previousFade + std::min(in.dt, s.overrunDt) / recoverTime) + 1e-12)
            << "tick " << tick;
      }
      // Ramp in from every zero: never above the ramp's share of the maximum.
      if (rampChecked) {
        ASSERT_LE(out.norm(), s.maxForce * rampBound + tolerance) << "tick " << tick;
      }
    }
    previous = out;
    previousFade = fade;
  }
  cover.clamped += safety.stats().clampedTicks;
  cover.slewed += safety.stats().slewLimitedTicks;
  cover.trips += safety.stats().trips;
  EXPECT_EQ(safety.stats().ticks, static_cast<uint64_t>(ticks));
}

TEST(ForceSafety, RandomTicksKeepEveryInvariant) {
  std::mt19937_64 rng(0x5afe7ULL);
  std::vector<Scenario> scenarios;
  scenarios.push_back({SafetySettings::forMaxForce(3.3), 800000});  // Touch, Omni
  scenarios.push_back({SafetySettings::forMaxForce(7.9), 500000});  // Desktop
  SafetySettings quick = SafetySettings::forMaxForce(8.0);          // Falcon, short times
  quick.rampTime = 0.05, quick.fadeTime = 0.01, quick.staleAfter = 0.02;
  scenarios.push_back({quick, 400000});
  SafetySettings gentle = SafetySettings::forMaxForce(3.3);  // tiny steps, long fades
  gentle.maxForceStep = 0.01, gentle.fadeTime = 0.2, gentle.rampTime = 1.0;
  scenarios.push_back({gentle, 400000});
  SafetySettings recovering = SafetySettings::forMaxForce(3.3);  // the session's quick recovery
  recovering.recoverTime = 0.05;
  scenarios.push_back({recovering, 400000});

  Coverage cover;
  int total = 0;
  const auto start = std::chrono::steady_clock::now();
  for (const Scenario& scenario : scenarios) {
    for (int run = 0; run < 4; ++run) {
      runRandomTicks(scenario.settings, scenario.ticks / 4, rng, cover);
      if (HasFatalFailure()) return;
    }
    total += scenario.ticks;
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf(
      "force safety: %d random ticks in %.3f s: %llu clamped, %llu slew-limited, "
      "%llu zeroed, %llu fading (%llu faded to zero, %llu faster than the step), "
      "%llu trips, %llu rearms\n",
      total, seconds, static_cast<unsigned long long>(cover.clamped),
      static_cast<unsigned long long>(cover.slewed), static_cast<unsigned long long>(cover.zeroed),
      static_cast<unsigned long long>(cover.faded),
      static_cast<unsigned long long>(cover.fadedToZero),
      static_cast<unsigned long long>(cover.fastFades),
      static_cast<unsigned long long>(cover.trips), static_cast<unsigned long long>(cover.rearms));
  EXPECT_GE(total, 2000000);
  // Every rule was exercised, many times.
  EXPECT_GT(cover.clamped, 10000u);
  EXPECT_GT(cover.slewed, 10000u);
  EXPECT_GT(cover.zeroed, 10000u);
  EXPECT_GT(cover.faded, 10000u);
  EXPECT_GT(cover.fadedToZero, 1000u);
  EXPECT_GT(cover.fastFades, 100u);
  EXPECT_GT(cover.trips, 100u);
  EXPECT_GT(cover.rearms, 100u);
}

}  // namespace
}  // namespace sculpt::haptics
