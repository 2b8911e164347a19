#include "haptics/mock/mock_phantom.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace sculpt::haptics {
namespace {

/// Longer gaps than this between reads are not integrated in full: the hand has long settled.
constexpr double kLongestCatchUp = 1.0;  // s

}  // namespace

DeviceInfo MockPhantom::modelInfo(PhantomModel model) {
  DeviceInfo info;
  const bool omni = model == PhantomModel::kOmni;
  info.model = omni ? "Mock Omni" : "Mock Touch";
  info.manufacturer = "sculpt (simulated)";
  info.maxForce = 3.3;
  info.stableStiffness = omni ? 700.0 : 400.0;
  info.damping = omni ? 5.0 : 4.0;
  info.workspaceRadius = phantomWorkspaceRadius(model);
  info.capabilities = kSensesPosition | kSensesRotation | kSensesButtons | kActuatesForce;
  return info;
}

MockPhantom::MockPhantom(DeviceScript script, size_t forceCapacity)
    : info_(modelInfo(script.model)),
      mode_(script.mode == ScriptMode::kHand ? MockMode::kHand : MockMode::kTrajectory),
      script_(std::move(script)),
      hand_(script_.hand),
      forceCapacity_(forceCapacity) {
  forces_.reserve(forceCapacity_);
}

MockPhantom::MockPhantom(PhantomModel model, const HandDynamics& hand, size_t forceCapacity)
    : info_(modelInfo(model)),
      mode_(MockMode::kExternal),
      hand_(hand),
      forceCapacity_(forceCapacity) {
  script_.model = model;
  // Into the limits a script is held to (the substeps stay stable there).
  const auto atLeast = [](double x, double low) { return x >= low ? x : low; };  // NaN: low
  hand_.stiffness = std::min(atLeast(hand_.stiffness, 1.0), DeviceScript::kMaxHandStiffness);
  hand_.damping = std::min(atLeast(hand_.damping, 0.0), 1e3);
  hand_.mass = std::min(atLeast(hand_.mass, DeviceScript::kMinHandMass), 1e3);
  forces_.reserve(forceCapacity_);
}

void MockPhantom::setHandTarget(const Eigen::Vector3d& position, uint32_t buttons) {
  target_.publish({position, buttons});
}

MockPhantom::Goal MockPhantom::goalAt(double t) const {
  if (mode_ == MockMode::kExternal) return {externalTarget_.position, Eigen::Vector3d::Zero()};
  const ScriptSample s = script_.sample(t);
  return {s.position, s.velocity};
}

void MockPhantom::moveHand(double to) {
  double from = std::max(time_, to - kLongestCatchUp);
  const double span = to - from;
  if (!(span > 0)) return;
  const int steps = static_cast<int>(std::ceil(span / kSubstep));
  const double h = span / steps;
  const double k = hand_.stiffness, c = hand_.damping, m = hand_.mass;
  for (int i = 1; i <= steps; ++i) {
    const Goal goal = goalAt(from + i * h);
    // m dv/dt = k (goal - x) + c (goal velocity - v) + F, the damper implicit in v.
    velocity_ =
        (velocity_ + h / m * (k * (goal.position - position_) + c * goal.velocity + rendered_)) /
        (1.0 + h * c / m);
    position_ += h * velocity_;
  }
  time_ = to;
}

DeviceSample MockPhantom::read(double now) {
  const bool connected = connected_.load(std::memory_order_relaxed);
  if (mode_ == MockMode::kExternal) externalTarget_ = target_.read();
  if (!connected) rendered_.setZero();  // an unplugged arm renders nothing

  DeviceSample sample;
  sample.time = now;
  sample.connected = connected;
  if (mode_ == MockMode::kTrajectory) {
    position_ = script_.sample(now).position;
    time_ = now;
  } else if (!started_ || !(now >= time_)) {
    position_ = goalAt(now).position;  // the hand starts (or restarts) at rest on its target
    velocity_.setZero();
    time_ = now;
  } else {
    moveHand(now);
  }
  started_ = true;

  if (mode_ == MockMode::kExternal) {
    sample.buttons = externalTarget_.buttons;
  } else {
    const ScriptSample s = script_.sample(now);
    sample.buttons = s.buttons | (s.clutch ? kClutchButton : 0u);
  }
  sample.position = position_;
  sample.velocity = velocityEstimator_.add(now, position_);
  return sample;
}

void MockPhantom::sendForce(const Eigen::Vector3d& force) {
  if (forces_.size() < forceCapacity_)
    forces_.push_back({time_, force});
  else
    ++dropped_;
  const bool connected = connected_.load(std::memory_order_relaxed);
  rendered_ = connected && force.allFinite() ? force : Eigen::Vector3d::Zero();
}

}  // namespace sculpt::haptics
