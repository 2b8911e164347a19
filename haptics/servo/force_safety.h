#pragma once
// The safety layer every force passes through once per servo tick before it reaches a device.
// The force laws upstream may be wrong (a NaN from the simulation, a huge coupling force, a probe
// that stopped updating, a loop that stalled); this layer alone guarantees what the hand feels:
//
//   1. |F| <= maxForce, always.
//   2. |F - F_previous| <= maxForceStep per tick (no clank), with two documented exceptions where
//      safety beats slew:
//      a. Zeroing: disconnect, focus loss, shutdown, panic, device error and any non-finite input
//         take the force to exactly zero within the same tick.
//      b. Fading: while the probe is stale or the loop overruns, the force may fall faster than the
//         step limit when ticks are late (a 20 ms overrun removes 40% of the fade gain at once),
//         but only towards zero: the change is then at most
//         maxForceStep + maxForce * (fade gain lost this tick).
//   3. Non-finite input (desired force, dt or probe age), panic and device errors trip the layer:
//      the force stays zero until rearm(). Disconnect, focus loss and shutdown hold it at zero only
//      while they last.
//   4. A stale probe (age > staleAfter) or an overrun (dt > overrunDt) lowers a fade gain
//      linearly at 1/fadeTime, so after fadeTime of unhealthy ticks (and whenever the probe is
//      older than staleAfter + fadeTime) the force is exactly zero; once healthy again the gain
//      rises back over recoverTime.
//   5. The force ramps in linearly from zero over rampTime: at start, on rampIn() (a grab), after
//      rearm() and after any zeroing.
//
// The output is F = fadeCeiling(slew(F_previous -> gain * clamp(desired))), gain = min(ramp,
// fade), fadeCeiling = maxForce * fade. Pure: no clock, no threads; one instance per servo.

#include <cstdint>
#include <string>

#include <Eigen/Core>

namespace sculpt::haptics {

struct SafetySettings {
  double maxForce = 3.3;  ///< N, the device's maximum continuous force (DeviceInfo::maxForce)
  /// N per tick. 5% of maxForce: full scale in 20 ticks (20 ms at 1 kHz), faster than a hand
  /// reaches a wall's force at the device's stable stiffness, slow enough not to clank.
  double maxForceStep = 0.05 * 3.3;
  double rampTime = 0.5;     ///< s, the linear ramp from zero to full gain
  double staleAfter = 0.05;  ///< s, a probe older than this starts the fade
  double fadeTime = 0.05;    ///< s, fade gain 1 -> 0 (zero at 0.1 s of probe age by default)
  double overrunDt = 0.005;  ///< s, a tick longer than this is an overrun and fades too
  /// s, the fade gain's rise from 0 back to 1 once healthy again; negative: rampTime. A
  /// simulation slower than real time (probes 50-130 ms apart) needs it short, or every late
  /// probe costs half a second of force (the haptic session sets 0.05 s).
  double recoverTime = -1.0;

  /// The defaults above for a device with this maximum force (step 5% of it).
  static SafetySettings forMaxForce(double maxForce) {
    SafetySettings s;
    s.maxForce = maxForce;
    s.maxForceStep = 0.05 * maxForce;
    return s;
  }
};

/// One tick's input. `desired` in N (device frame); `dt` the tick's measured length (s);
/// `probeAge` how old the simulation's coupling data are (s).
struct SafetyInput {
  Eigen::Vector3d desired = Eigen::Vector3d::Zero();
  double dt = 0.001;
  double probeAge = 0.0;
  bool connected = true;
  bool focused = true;
  bool panic = false;
  bool deviceError = false;
  bool shuttingDown = false;
};

struct SafetyStats {
  uint64_t ticks = 0;
  uint64_t clampedTicks = 0;      ///< |desired| was over maxForce and was scaled down
  uint64_t slewLimitedTicks = 0;  ///< the step limit held the force back
  uint64_t zeroedTicks = 0;       ///< zero by a zeroing condition or a trip
  uint64_t fadingTicks = 0;       ///< stale probe or overrun
  uint64_t trips = 0;             ///< latching events (non-finite input, panic, device error)
};

class ForceSafety {
 public:
  explicit ForceSafety(const SafetySettings& settings = {});

  /// One servo tick: the force to send to the device.
  Eigen::Vector3d filter(const SafetyInput& input);
  /// Clears a trip; the force ramps in from zero again.
  void rearm();
  /// Restarts the ramp from zero (on grab): the force slews down to zero and ramps in.
  void rampIn();

  bool tripped() const { return !tripReason_.empty(); }
  /// Why the layer tripped ("" when it has not).
  const std::string& tripReason() const { return tripReason_; }
  const SafetyStats& stats() const { return stats_; }
  const SafetySettings& settings() const { return settings_; }
  /// The force of the latest tick (N).
  const Eigen::Vector3d& lastForce() const { return force_; }
  double rampGain() const { return ramp_; }
  double fadeGain() const { return fade_; }

 private:
  void trip(const char* reason);
  Eigen::Vector3d zero();

  SafetySettings settings_;
  SafetyStats stats_;
  std::string tripReason_;
  Eigen::Vector3d force_ = Eigen::Vector3d::Zero();
  double ramp_ = 0.0;  ///< [0, 1], rises at 1/rampTime
  double fade_ = 1.0;  ///< [0, 1], falls at 1/fadeTime while unhealthy
};

}  // namespace sculpt::haptics
