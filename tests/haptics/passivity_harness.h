#pragma once
// A 1-DOF haptic device pressing on a sampled virtual wall, to measure whether the wall adds
// energy. The device is a mass with physical viscous friction (PHANTOM-class figures: 50 g moving
// mass at the stylus, 0.5 N s/m of friction); a hand presses it into the wall with a steady force
// after giving it an initial velocity. The servo samples the position every T = 1 ms, estimates
// the velocity with a backward difference over the tick (the case Colgate analysed), and holds
// the wall force over the tick (zero-order hold). Between samples the motion under a constant
// force is integrated exactly and observed every 100 us.
//
// The energy is H = m v^2 / 2 + K x^2 / 2 (x < 0, the wall's spring) + F_hand x (the hand's
// potential), counted from its minimum (at rest at the equilibrium x = -F_hand / K), so zero at
// rest. A passive wall can only lose energy (the friction dissipates it): H stays at or under its
// initial value. A sampled wall that is too stiff gains energy on every contact and the device
// chatters against it, H growing to many times its initial value.

#include <algorithm>
#include <cmath>

#include "haptics/servo/virtual_wall.h"

namespace sculpt::haptics {

struct PassivityRig {
  double mass = 0.05;             ///< kg, the device's moving mass at the stylus
  double friction = 0.5;          ///< N s/m, the device's physical viscous friction b
  double period = 0.001;          ///< s, the servo's sample period T
  int substeps = 10;              ///< observations per period (100 us)
  double handForce = 1.0;         ///< N, the hand's steady push into the wall (-x)
  double initialVelocity = -0.2;  ///< m/s, into the wall, starting at its surface
  double duration = 5.0;          ///< s

  /// Colgate's bound on the stiffness of an undamped sampled wall: K < 2 b / T.
  double colgateStiffness() const { return 2.0 * friction / period; }
};

struct PassivityResult {
  double stiffness = 0, damping = 0;
  double initialEnergy = 0, peakEnergy = 0, finalEnergy = 0;  ///< J, counted from rest
  double peakRatio() const { return peakEnergy / initialEnergy; }
  double finalRatio() const { return finalEnergy / initialEnergy; }
  /// The energy never rose above its start (by more than 5%, for the sampling of the peak).
  bool passive() const { return peakEnergy <= 1.05 * initialEnergy + 1e-12; }
};

/// Runs the rig against a wall of this stiffness (N/m) and virtual damping (N s/m).
inline PassivityResult runWall(const PassivityRig& rig, double stiffness, double damping) {
  const double K = stiffness, m = rig.mass, b = rig.friction, T = rig.period;
  const double restEnergy = -rig.handForce * rig.handForce / (2.0 * K);
  const auto energy = [&](double x, double v) {
    return 0.5 * m * v * v + (x < 0 ? 0.5 * K * x * x : 0.0) + rig.handForce * x - restEnergy;
  };

  PassivityResult result;
  result.stiffness = K, result.damping = damping;
  double x = 0.0, v = rig.initialVelocity, sampledBefore = 0.0;
  result.initialEnergy = result.peakEnergy = energy(x, v);

  // Exact motion of m a = F - b v under a constant force F over a substep h:
  // v(h) = v_inf + (v - v_inf) e^{-h b/m}, v_inf = F / b.
  const double h = T / rig.substeps, rate = b / m, decay = std::exp(-rate * h);
  const long ticks = std::lround(rig.duration / T);
  for (long tick = 0; tick < ticks; ++tick) {
    const double sampled = x;  // the servo reads the encoder
    const double velocity = tick == 0 ? rig.initialVelocity : (sampled - sampledBefore) / T;
    sampledBefore = sampled;
    const double force = wallForce(sampled, velocity, K, damping) - rig.handForce;
    const double terminal = force / b;
    for (int s = 0; s < rig.substeps; ++s) {
      x += terminal * h + (v - terminal) * (1.0 - decay) / rate;
      v = terminal + (v - terminal) * decay;
      result.peakEnergy = std::max(result.peakEnergy, energy(x, v));
    }
  }
  result.finalEnergy = energy(x, v);
  return result;
}

}  // namespace sculpt::haptics
