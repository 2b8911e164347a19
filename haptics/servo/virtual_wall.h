#pragma once
// The simplest haptic force law, a 1-DOF penalty wall at x = 0 with the free side x >= 0: inside
// (x < 0) a spring pushes out and a damper resists motion, outside nothing. The damper may slow
// the hand on its way out but never pull it back in, so the force is never negative. Sampled at
// the servo rate and held between samples it is the textbook case for passivity (Colgate: a
// device with physical damping b stays passive at sample period T while b > K T / 2 + |damping|),
// which tests/haptics/passivity_test.cpp checks.

#include <algorithm>

namespace sculpt::haptics {

/// Force (N, along +x) of a wall at x = 0 for position x (m), velocity v (m/s), stiffness (N/m)
/// and damping (N s/m).
inline double wallForce(double x, double v, double stiffness, double damping) {
  if (!(x < 0)) return 0.0;
  return std::max(0.0, -stiffness * x - damping * v);
}

}  // namespace sculpt::haptics
