#pragma once
// How the simulation keeps up with the clock: simulated seconds per wall-clock second, as the
// status strip shows it ("0.28x real time", amber below 1x, when a stylus or a recording would
// feel the solid lag behind the hand).

#include <optional>
#include <string>

namespace sculpt::app {

/// Simulated seconds advanced per wall-clock second over a window; nothing when the window is
/// empty or the simulated clock went back (a reset inside the window).
std::optional<double> realTimeFactor(double simulatedAtStart, double simulatedAtEnd,
                                     double wallSeconds);

/// "0.28x real time", "1.9x real time", "12x real time".
std::string realTimeLabel(double factor);

/// Below real time: the simulation falls behind the clock.
inline bool behindRealTime(double factor) { return factor < 1.0; }

}  // namespace sculpt::app
