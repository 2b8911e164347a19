#include "sculpt/real_time_factor.h"

#include <cmath>
#include <cstdio>

namespace sculpt::app {

std::optional<double> realTimeFactor(double simulatedAtStart, double simulatedAtEnd,
                                     double wallSeconds) {
  const double advanced = simulatedAtEnd - simulatedAtStart;
  if (!(wallSeconds > 0.0) || !std::isfinite(advanced) || advanced < 0.0) return std::nullopt;
  return advanced / wallSeconds;
}

std::optional<double> meanStepMs(uint64_t stepsAtStart, double totalMsAtStart,
                                 uint64_t stepsAtEnd, double totalMsAtEnd) {
  if (stepsAtEnd <= stepsAtStart || !(totalMsAtEnd >= totalMsAtStart)) return std::nullopt;
  return (totalMsAtEnd - totalMsAtStart) / static_cast<double>(stepsAtEnd - stepsAtStart);
}

std::string realTimeLabel(double factor) {
  // Two significant digits: enough to tell 0.28x from 0.3x, and the strip does not jitter.
  char text[48];
  std::snprintf(text, sizeof text, "%.2gx real time", factor);
  return text;
}

PaceMark paceMark(const SceneFrame& frame, std::chrono::steady_clock::time_point at) {
  return {at, frame.sceneId, frame.steps, frame.stepMsTotal, frame.simulatedTime};
}

Pace paceBetween(const PaceMark& start, const PaceMark& end) {
  Pace pace;
  pace.wallSeconds = std::chrono::duration<double>(end.at - start.at).count();
  if (end.sceneId != start.sceneId || end.steps < start.steps) return pace;
  pace.steps = end.steps - start.steps;
  if (pace.wallSeconds > 0.0)
    pace.stepsPerSecond = static_cast<double>(pace.steps) / pace.wallSeconds;
  pace.realTimeFactor = realTimeFactor(start.simulatedTime, end.simulatedTime, pace.wallSeconds);
  pace.meanStepMs = meanStepMs(start.steps, start.stepMsTotal, end.steps, end.stepMsTotal);
  return pace;
}

}  // namespace sculpt::app
