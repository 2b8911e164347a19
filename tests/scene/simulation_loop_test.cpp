// The simulation loop on its own thread: paced by its own clock at the set ratio of simulated
// to real time while a tool is updated at 1 kHz (no step taken because of a command, the newest
// input applied once per step), step observers that see every step, and the probe read from a
// second thread at 1 kHz (ThreadSanitizer checks these tests in scripts/test.sh --tsan).

#include "scene/simulation_loop.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <mutex>
#include <thread>
#include <vector>

#include "support/paced_rate.h"
#include "tools/strokes.h"

namespace sculpt {
namespace {

using Clock = std::chrono::steady_clock;

std::unique_ptr<ScenePhysics> blockPhysics(const SceneSettings& settings) {
  const SceneSource source(SceneKind::ControlMesh,
                           std::string(SCULPT_SOURCE_DIR) + "/assets/block3.json");
  std::optional<SceneBuildPhase1> phase1 = buildSceneGeometry(source, settings, 1);
  EXPECT_TRUE(phase1.has_value());
  StageTimes times;
  return ScenePhysics::build(phase1->geometry, phase1->solid, settings, nullptr, &times);
}

void install(SimulationLoop& loop, std::unique_ptr<ScenePhysics> physics) {
  SceneFrame first;
  physics->fillFrame(first);
  loop.install(std::move(physics), std::move(first));
}

double seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }

// The median wall time of a few steps of `physics` after its first two (the first makes the
// preconditioner's factor).
double medianStepSeconds(ScenePhysics& physics) {
  std::vector<double> samples;
  for (int k = 0; k < 7; ++k) {
    const Clock::time_point start = Clock::now();
    physics.simulator().step();
    if (k >= 2) samples.push_back(seconds(Clock::now() - start));
  }
  std::sort(samples.begin(), samples.end());
  return samples[samples.size() / 2];
}

// The wall and simulated times of every step a loop takes, recorded by its step observer.
// Declared before the loop, so that it outlives the loop's thread.
struct StepLog {
  std::mutex mutex;
  std::vector<double> wall, simulated;
  const Clock::time_point origin = Clock::now();
  // Records a step; returns how many are recorded.
  size_t record(const StepState& state) {
    const std::lock_guard lock(mutex);
    wall.push_back(seconds(Clock::now() - origin));
    simulated.push_back(state.simulatedTime);
    return wall.size();
  }
};

// The status strip's step time is the mean over a window of frames: each frame carries the
// steps so far and their summed times, a reset included.
TEST(ScenePhysicsSteps, FramesCountTheStepsAndSumTheirTimes) {
  std::unique_ptr<ScenePhysics> physics = blockPhysics(SceneSettings());
  ASSERT_NE(physics, nullptr);
  SceneFrame frame;
  physics->fillFrame(frame);
  EXPECT_EQ(frame.steps, 1u) << "the build's first step";
  EXPECT_GT(frame.stepMs, 0.0);
  EXPECT_EQ(frame.stepMsTotal, frame.stepMs);
  double total = frame.stepMsTotal;
  for (int k = 0; k < 3; ++k) {
    physics->step();
    physics->fillFrame(frame);
    EXPECT_GT(frame.stepMs, 0.0);
    total += frame.stepMs;
  }
  EXPECT_EQ(frame.steps, 4u);
  EXPECT_EQ(frame.stepMsTotal, total) << "the same times added in the same order";
  physics->reset();
  physics->step();
  physics->fillFrame(frame);
  EXPECT_EQ(frame.steps, 5u) << "a reset goes on counting";
  EXPECT_EQ(frame.stepMsTotal, total + frame.stepMs);
}

// A step that takes three shares of the clock (a stall of the machine, a factor taken) is made
// up by the next ones starting at once: the simulated time keeps the set rate. Rebased instead,
// every fourth step long would leave it at two thirds of the rate.
TEST(SimulationLoop, LateStepsAreMadeUpByTheNextOnes) {
  SceneSettings settings;
  std::unique_ptr<ScenePhysics> physics = blockPhysics(settings);
  // A share of 40 ms, or of sixteen steps of this build where that is longer: the three steps
  // after a long one keep pace even where they take four times the median (a loaded machine).
  const double share = std::max(0.04, 16.0 * medianStepSeconds(*physics));
  const double rate = settings.timeStep / share;
  StepLog log;
  SimulationLoop loop(true);
  loop.setRealTimeRate(rate);
  loop.addStepObserver([&](const StepState& state) {
    if (log.record(state) % 4 == 0)
      std::this_thread::sleep_for(std::chrono::duration<double>(3.0 * share));
  });
  install(loop, std::move(physics));
  std::this_thread::sleep_for(std::chrono::duration<double>(std::max(2.0, 30.0 * share)));
  loop.setPlaying(false);

  const std::lock_guard lock(log.mutex);
  // From the first step after the first long one to the last step at the same place of its
  // group of four: whole groups.
  ASSERT_GE(log.wall.size(), 21u);
  const size_t first = 4, last = first + 4 * ((log.wall.size() - 1 - first) / 4);
  const double simulated = log.simulated[last] - log.simulated[first];
  const double wall = log.wall[last] - log.wall[first];
  std::printf("[ measured ] %zu steps, every fourth %.0f ms long: simulated %.3f s in %.3f s wall, "
              "ratio %.4f (set %.4f)\n",
              last - first, 3e3 * share, simulated, wall, simulated / wall, rate);
  EXPECT_NEAR(simulated / wall, rate, 0.1 * rate);
}

TEST(SimulationLoop, StepsAtTheSetRateWhileAToolIsUpdatedAt1kHz) {
  SceneSettings settings;  // dt = 1/60 s
  // Simulated seconds per wall second: half of real time, or a quarter of what this build can
  // step where that is less (a sanitizer build, a loaded machine), so that every step fits in
  // its period with room to spare.
  std::unique_ptr<ScenePhysics> physics = blockPhysics(settings);
  const double stepSeconds = medianStepSeconds(*physics);
  const double rate = test::pacedRate(0.5, settings.timeStep, stepSeconds, 4.0);
  const double period = settings.timeStep / rate;
  // The drag: 2 s, or twelve periods where that is longer, so that the measured ratio spans
  // enough steps for a late one not to sway it.
  const double drag = std::max(2.0, 12.0 * period);
  std::printf("[ measured ] this build steps block3 at %.2fx real time\n",
              settings.timeStep / stepSeconds);
  StepLog log;
  SimulationLoop loop(true);
  loop.setRealTimeRate(rate);
  loop.addStepObserver([&](const StepState& state) { log.record(state); });
  std::shared_ptr<ProbeChannel> probe = loop.openProbe();
  install(loop, std::move(physics));

  // Let it settle into its pace (its first steps may run late, a sanitizer build's above all,
  // and the loop makes up as many as kCatchUpSteps of them), then drag a pull stroke with an
  // update every millisecond.
  std::this_thread::sleep_for(std::chrono::duration<double>(
      std::max(0.3, (SimulationLoop::kCatchUpSteps + 2) * period)));
  ToolInput input;
  input.position = input.restPoint.emplace(1.5, 1.5, 1.5);
  const uint64_t stroke =
      loop.beginStroke(std::make_unique<PullStroke>(PullStroke::Settings{}), input);
  input.restPoint.reset();
  const Clock::time_point start = Clock::now();
  Clock::time_point next = start;
  int updates = 0;
  while (seconds(Clock::now() - start) < drag) {
    input.position = Eigen::Vector3d(1.5 + seconds(Clock::now() - start) / drag, 1.5, 1.5);
    loop.updateStroke(stroke, input);
    ++updates;
    next += std::chrono::milliseconds(1);
    std::this_thread::sleep_until(next);
  }
  const double windowStart = seconds(start - log.origin);
  const double windowEnd = seconds(Clock::now() - log.origin);
  const SceneProbe seen = probe->read();
  loop.endStroke(stroke, input);

  const std::lock_guard lock(log.mutex);
  // The steps inside the window of updates and the simulated time they covered.
  std::vector<size_t> inside;
  for (size_t i = 0; i < log.wall.size(); ++i)
    if (log.wall[i] >= windowStart && log.wall[i] <= windowEnd) inside.push_back(i);
  ASSERT_GE(inside.size(), 4u);
  const double simulated = log.simulated[inside.back()] - log.simulated[inside.front()];
  const double wall = log.wall[inside.back()] - log.wall[inside.front()];
  double shortest = 1e9;
  for (size_t k = 1; k < inside.size(); ++k)
    shortest = std::min(shortest, log.wall[inside[k]] - log.wall[inside[k - 1]]);
  std::printf("[ measured ] %d updates in %.3f s; %zu steps; simulated %.4f s in %.4f s wall: "
              "ratio %.4f (set %.3f); shortest step interval %.2f ms (period %.2f ms)\n",
              updates, windowEnd - windowStart, inside.size(), simulated, wall, simulated / wall,
              rate, 1e3 * shortest, 1e3 * period);
  EXPECT_GT(updates, 500 * drag);
  EXPECT_NEAR(simulated / wall, rate, 0.1 * rate);
  // A command never triggers a step: over a command a millisecond there are no more steps than
  // the clock allows, and the few late ones it makes up (the shortest interval is printed only:
  // on a loaded machine a late step is followed at once by the next one that is due).
  EXPECT_LE(static_cast<double>(inside.size()),
            wall / period + 2.0 + SimulationLoop::kCatchUpSteps);
  // The probe saw the stroke with the newest target the loop had applied.
  ASSERT_EQ(seen.strokeCount, 1);
  EXPECT_EQ(seen.strokes[0].strokeId, stroke);
  // The drag reached x = 2.5 at the end; the newest step that applied it is at most a period or
  // two (a late step) before the end.
  EXPECT_GT(seen.strokes[0].target.x(), 1.5 + (drag - 2.0 * period - 0.1) / drag);
  EXPECT_LE(seen.strokes[0].target.x(), 2.5 + 1e-9);
  EXPECT_GT(seen.strokes[0].stiffness, 0.0);
}

TEST(SimulationLoop, ProbeIsReadFromAnotherThreadAt1kHz) {
  std::atomic<uint64_t> observedSteps{0};
  SimulationLoop loop(true);
  std::shared_ptr<ProbeChannel> probe = loop.openProbe();
  loop.addStepObserver([&](const StepState& state) { observedSteps = state.step; });
  install(loop, blockPhysics(SceneSettings{}));
  ToolInput input;
  input.position = input.restPoint.emplace(1.5, 2.0, 1.5);
  const uint64_t stroke =
      loop.beginStroke(std::make_unique<PullStroke>(PullStroke::Settings{}), input);

  // The servo starts once the stroke is in the probe (the scene's first step may come before it).
  const auto deadline = Clock::now() + std::chrono::seconds(30);
  while (probe->read().strokeCount != 1 && Clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  ASSERT_EQ(probe->read().strokeCount, 1);
  // The servo: 1,000 reads a second for a second, each O(1) and without a lock.
  std::atomic<bool> ok{true};
  std::atomic<int> reads{0}, distinct{0};
  std::thread servo([&] {
    uint64_t lastGeneration = 0;
    double lastTime = 0.0;
    Clock::time_point next = Clock::now();
    for (int i = 0; i < 1000; ++i) {
      const SceneProbe& p = probe->read();
      if (p.generation < lastGeneration || p.simulatedTime < lastTime) ok = false;
      if (p.generation > lastGeneration) {
        ++distinct;
        if (p.strokeCount != 1 || !p.strokes[0].point.allFinite() ||
            !p.strokes[0].velocity.allFinite() || !(p.strokes[0].force >= 0.0))
          ok = false;
      }
      lastGeneration = p.generation;
      lastTime = p.simulatedTime;
      ++reads;
      next += std::chrono::milliseconds(1);
      std::this_thread::sleep_until(next);
    }
  });
  for (int i = 0; i < 100; ++i) {  // the UI moves the stroke meanwhile
    input.position.x() += 0.005;
    loop.updateStroke(stroke, input);
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  servo.join();
  loop.endStroke(stroke, input);
  std::printf("[ measured ] %d probe reads, %d distinct probes, %llu steps observed\n",
              reads.load(), distinct.load(), static_cast<unsigned long long>(observedSteps.load()));
  EXPECT_TRUE(ok);
  EXPECT_EQ(reads, 1000);
  // One probe per step (and the stroke's begin): at real time about 60 in the second (fewer in
  // the sanitizer builds, whose steps are slower).
  EXPECT_GE(distinct, 3);
  EXPECT_LE(static_cast<uint64_t>(distinct), observedSteps + 2);
}

TEST(SimulationLoop, ObserversSeeEveryStepAndCommandsWaitForTheStepBoundary) {
  std::vector<uint64_t> steps;
  SimulationLoop loop(false);
  loop.addStepObserver([&](const StepState& state) {
    steps.push_back(state.step);
    EXPECT_NE(state.control, nullptr);
    EXPECT_NE(state.report, nullptr);
  });
  install(loop, blockPhysics(SceneSettings{}));
  ToolInput input;
  input.position = input.restPoint.emplace(1.5, 1.5, 1.5);
  const uint64_t stroke =
      loop.beginStroke(std::make_unique<PullStroke>(PullStroke::Settings{}), input);
  for (int i = 0; i < 5; ++i) {
    input.position.x() += 0.1;
    loop.updateStroke(stroke, input);
    loop.updateStroke(stroke, input);  // coalesced: one command per step
  }
  SceneFrame frame;
  EXPECT_TRUE(loop.iterate());
  ASSERT_TRUE(loop.fetchNewer(frame));
  ASSERT_EQ(frame.springs.size(), 1u);
  EXPECT_EQ(frame.springs[0].target.x(), input.position.x()) << "the newest input, once";
  for (int i = 0; i < 4; ++i) loop.iterate();
  EXPECT_EQ(steps, (std::vector<uint64_t>{1, 2, 3, 4, 5}));
}

}  // namespace
}  // namespace sculpt
