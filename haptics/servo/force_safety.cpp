#include "haptics/servo/force_safety.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sculpt::haptics {
namespace {

/// `v` scaled down to length `limit` when longer. Safe for huge components (no overflow in the
/// norm) and exact: the result's norm() never exceeds `limit`.
Eigen::Vector3d clampMagnitude(const Eigen::Vector3d& v, double limit, bool* clamped = nullptr) {
  if (clamped) *clamped = false;
  if (!(limit > 0)) {
    if (clamped) *clamped = !v.isZero(0.0);
    return Eigen::Vector3d::Zero();
  }
  const double largest = v.cwiseAbs().maxCoeff();
  if (largest == 0 || v.norm() <= limit) return v;
  if (clamped) *clamped = true;
  const Eigen::Vector3d unit = v / largest;  // norm in [1, sqrt 3]: no overflow
  Eigen::Vector3d out = unit * (limit / unit.norm());
  while (out.norm() > limit) out *= 1.0 - std::numeric_limits<double>::epsilon();
  return out;
}

/// `gain` moved by `dt` at the rate 1/time (instantly when time <= 0), kept in [0, 1].
double rise(double gain, double dt, double time) {
  return time > 0 ? std::min(1.0, gain + dt / time) : 1.0;
}
double fall(double gain, double dt, double time) {
  const double fallen = time > 0 ? gain - dt / time : 0.0;
  return fallen > 1e-12 ? fallen : 0.0;  // a sum of dt that reaches fadeTime gives exactly zero
}

}  // namespace

ForceSafety::ForceSafety(const SafetySettings& settings) : settings_(settings) {}

void ForceSafety::trip(const char* reason) {
  if (tripped()) return;
  tripReason_ = reason;
  ++stats_.trips;
}

Eigen::Vector3d ForceSafety::zero() {
  ++stats_.zeroedTicks;
  force_.setZero();
  ramp_ = 0.0;
  return force_;
}

Eigen::Vector3d ForceSafety::filter(const SafetyInput& in) {
  ++stats_.ticks;
  if (!in.desired.allFinite()) trip("non-finite desired force");
  if (!std::isfinite(in.dt)) trip("non-finite tick length (dt)");
  if (!std::isfinite(in.probeAge)) trip("non-finite probe age");
  if (in.panic) trip("panic");
  if (in.deviceError) trip("device error");
  if (tripped() || !in.connected || !in.focused || in.shuttingDown) return zero();

  const SafetySettings& s = settings_;
  const double dt = std::max(in.dt, 0.0);
  const double rampDt = std::min(dt, s.overrunDt);  // a stalled loop does not ramp faster
  const bool stale = in.probeAge > s.staleAfter;
  if (stale || dt > s.overrunDt) {
    ++stats_.fadingTicks;
    fade_ = fall(fade_, dt, s.fadeTime);
    if (stale) {
      // However the age got there: zero from staleAfter + fadeTime on.
      const double byAge = s.fadeTime > 0 ? 1.0 - (in.probeAge - s.staleAfter) / s.fadeTime : 0.0;
      fade_ = std::min(fade_, byAge > 1e-12 ? byAge : 0.0);
    }
  } else {
    fade_ = rise(fade_, rampDt, s.recoverTime >= 0 ? s.recoverTime : s.rampTime);
  }
  ramp_ = rise(ramp_, rampDt, s.rampTime);

  bool clamped = false, slewed = false;
  const Eigen::Vector3d target =
      std::min(ramp_, fade_) * clampMagnitude(in.desired, s.maxForce, &clamped);
  const Eigen::Vector3d step = clampMagnitude(target - force_, s.maxForceStep, &slewed);
  force_ = clampMagnitude(force_ + step, s.maxForce * fade_);
  if (clamped) ++stats_.clampedTicks;
  if (slewed) ++stats_.slewLimitedTicks;
  return force_;
}

void ForceSafety::rearm() {
  tripReason_.clear();
  force_.setZero();
  ramp_ = 0.0;
}

void ForceSafety::rampIn() { ramp_ = 0.0; }

}  // namespace sculpt::haptics
