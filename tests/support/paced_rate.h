#pragma once
// The real-time rate a timing test runs the simulation at: what the test wants, or, where this
// build cannot step that fast with room to spare (a sanitizer build, a loaded machine), a
// fraction of what it can. Tests that assume the clock then hold in every build.

#include <algorithm>

namespace sculpt::test {

/// Simulated seconds per wall second: `wanted`, or `stepSeconds`'s capacity (`timeStep /
/// stepSeconds`, how many times faster than the clock the build steps) divided by `headroom`
/// where that is less.
inline double pacedRate(double wanted, double timeStep, double stepSeconds, double headroom) {
  return std::min(wanted, timeStep / stepSeconds / headroom);
}

}  // namespace sculpt::test
