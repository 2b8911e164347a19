#pragma once
// How the simulation keeps up with the clock: simulated seconds per wall-clock second, as the
// status strip shows it ("0.28x real time", amber below 0.95x, when a stylus or a recording would
// feel the solid lag behind the hand), and what its steps cost over the same window.

#include <chrono>
#include <cstdint>
#include <optional>
#include <string>

#include "scene/scene_physics.h"

namespace sculpt::app {

/// Simulated seconds advanced per wall-clock second over a window; nothing when the window is
/// empty or the simulated clock went back (a reset inside the window).
std::optional<double> realTimeFactor(double simulatedAtStart, double simulatedAtEnd,
                                     double wallSeconds);

/// "0.28x real time", "1.9x real time", "12x real time".
std::string realTimeLabel(double factor);

/// Below real time by more than a one-second window can tell: the simulation falls behind the
/// clock. A simulation that keeps up reads 58 to 62 steps of 1/60 s in one window and the next
/// (the steps are whole, the window is the UI's frames), so one that loses less than a step in
/// twenty (0.95x) is not flagged.
inline bool behindRealTime(double factor) { return factor < 0.95; }

/// The mean wall time (ms) of the steps taken between two frames, from their step counts and
/// summed step times (SceneFrame::steps, stepMsTotal): the strip's figure, steadier than the
/// last step's time, which jumps with every rotation probe or factor taken; nothing when no
/// step was taken or the count went back (the physics of another scene).
std::optional<double> meanStepMs(uint64_t stepsAtStart, double totalMsAtStart,
                                 uint64_t stepsAtEnd, double totalMsAtEnd);

/// Where the simulation stood when the UI looked: the newest frame's counts, and the clock.
struct PaceMark {
  std::chrono::steady_clock::time_point at;
  uint64_t sceneId = 0, steps = 0;
  double stepMsTotal = 0, simulatedTime = 0;
};
PaceMark paceMark(const SceneFrame& frame, std::chrono::steady_clock::time_point at);

/// From one mark to a later one within one scene's physics: the steps taken, per second, the
/// real-time factor and the mean step time as above (nothing but the wall time across a change
/// of scene, whose counts start anew).
struct Pace {
  double wallSeconds = 0;
  uint64_t steps = 0;
  std::optional<double> stepsPerSecond, realTimeFactor, meanStepMs;
};
Pace paceBetween(const PaceMark& start, const PaceMark& end);

}  // namespace sculpt::app
