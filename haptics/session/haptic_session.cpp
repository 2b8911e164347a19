#include "haptics/session/haptic_session.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "scene/scene_builder.h"

namespace sculpt::haptics {
namespace {

constexpr uint32_t kToolButton = 1u << 0, kClutchButton = 1u << 1;
constexpr auto kSessionPeriod = std::chrono::microseconds(2000);

// The servo's safety for a stylus on a scene: a probe counts as stale after 100 ms (zero at
// 150 ms), the upper end of the usual 50-100 ms, because a scene the machine cannot step in real
// time publishes probes 50-130 ms apart while it is alive and well; a fade recovers in 50 ms.
SafetySettings deviceSafety(const std::optional<SafetySettings>& safety, const DeviceInfo& device) {
  if (safety) return *safety;
  SafetySettings s = SafetySettings::forMaxForce(device.maxForce);
  s.staleAfter = 0.1;
  s.fadeTime = 0.05;
  s.recoverTime = 0.05;
  return s;
}

}  // namespace

HapticScene hapticSceneOf(const std::shared_ptr<const SceneGeometry>& shared,
                          const SceneSettings& settings) {
  HapticScene scene;
  const SceneGeometry& geometry = *shared;
  if (geometry.restPositions.rows() > 0 && !geometry.triangles.empty()) {
    scene.surfaceVertices = std::shared_ptr<const Points>(shared, &geometry.restPositions);
    scene.surfaceTriangles =
        std::shared_ptr<const std::vector<uint32_t>>(shared, &geometry.triangles);
  }
  const Points& points =
      geometry.restPositions.rows() > 0 ? geometry.restPositions : geometry.restControl;
  if (points.rows() > 0) {
    const Eigen::Vector3d lo = points.colwise().minCoeff().transpose();
    const Eigen::Vector3d hi = points.colwise().maxCoeff().transpose();
    scene.centre = 0.5 * (lo + hi);
    scene.radius = std::max(0.5 * (hi - lo).norm(), 1e-9);
  }
  scene.youngs = settings.material.youngs;
  return scene;
}

HapticSession::HapticSession(SimulationLoop& loop, HapticDevice& device, const HapticScene& scene,
                             HapticSessionSettings settings)
    : loop_(loop),
      device_(device),
      scene_(scene),
      mapping_(WorkspaceMapping::fit(device.info().workspaceRadius, scene.centre, scene.radius)),
      servo_(device, loop.openProbe(), deviceSafety(settings.safety, device.info()),
             settings.servoRateHz, settings.recordTicks),
      settings_(std::move(settings)) {
  forceFactor_ = settings_.forceFactor;
  scale_ =
      chooseForceScale(device.info(), mapping_.scale, scene.youngs, scene.radius, forceFactor_);
  status_.scale = scale_;
  status_.mapping = mapping_;
  status_.forceLimit = device.info().maxForce;
  status_.tool = settings_.tool;
}

HapticSession::~HapticSession() { stop(); }

void HapticSession::start() {
  if (started_) return;
  started_ = true;
  servo_.start();
  thread_ = std::thread([this] { run(); });
}

void HapticSession::stop() {
  stop_.store(true);
  if (thread_.joinable()) thread_.join();
  servo_.stop();
}

void HapticSession::setTool(HapticTool tool, bool paintWithProbe) {
  const std::lock_guard lock(mutex_);
  settings_.tool = tool;
  settings_.paintWithProbe = paintWithProbe;
}

void HapticSession::setForceFactor(double factor) {
  if (!(factor > 0) || !std::isfinite(factor)) return;
  const std::lock_guard lock(mutex_);
  forceFactor_ = factor;
}

void HapticSession::setRotation(const Eigen::Quaterniond& rotation) {
  const std::lock_guard lock(mutex_);
  rotation_ = rotation.normalized();
}

void HapticSession::setFocused(bool focused) {
  const std::lock_guard lock(mutex_);
  focused_ = focused;
}

void HapticSession::panic() {
  const std::lock_guard lock(mutex_);
  panic_ = true;
}

void HapticSession::rearm() {
  const std::lock_guard lock(mutex_);
  panic_ = false;
  ++rearms_;
}

HapticStatus HapticSession::status() const {
  const std::lock_guard lock(mutex_);
  return status_;
}

std::unique_ptr<Tool> HapticSession::makeTool(HapticTool tool, bool paint) const {
  switch (tool) {
    case HapticTool::Pull: {
      PullStroke::Settings pull;
      pull.stiffness = scale_.pullStiffness;  // 0 without force: the window's default
      return std::make_unique<PullStroke>(pull);
    }
    case HapticTool::Probe: {
      ContactStroke::Settings contact;
      const ForceScale scale = scale_;
      if (scale.deviceStableStiffness > 0)
        contact.stiffnessForYoungs = [scale](double youngs) {
          return scale.sceneStiffness(scale.contactDeviceStiffness(youngs));
        };
      if (paint) contact.paint = settings_.paint;
      contact.surfaceVertices = scene_.surfaceVertices;
      contact.surfaceTriangles = scene_.surfaceTriangles;
      return std::make_unique<ContactStroke>(contact);
    }
    case HapticTool::Inflate:
      return std::make_unique<InflateStroke>(settings_.inflate);
    case HapticTool::None:
      break;
  }
  return nullptr;
}

void HapticSession::run() {
  uint64_t stroke = 0;
  HapticTool strokeTool = HapticTool::None;
  bool strokePaint = false, clutching = false;
  Eigen::Vector3d clutchStart = Eigen::Vector3d::Zero(), offsetStart = Eigen::Vector3d::Zero();
  Eigen::Vector3d inflateAnchor = Eigen::Vector3d::Zero();
  ToolInput lastSent;
  auto deadline = std::chrono::steady_clock::now();

  auto endStroke = [&](const ToolInput& input) {
    if (stroke != 0) loop_.endStroke(stroke, input);
    stroke = 0;
    strokeTool = HapticTool::None;
  };

  while (!stop_.load(std::memory_order_relaxed)) {
    deadline += kSessionPeriod;
    std::this_thread::sleep_until(deadline);
    const HandState hand = servo_.latest();
    if (hand.tick == 0) continue;

    HapticTool tool;
    bool paint, focused, panic;
    double factor;
    uint64_t rearms;
    {
      const std::lock_guard lock(mutex_);
      tool = settings_.tool, paint = settings_.paintWithProbe;
      focused = focused_, panic = panic_, factor = forceFactor_, rearms = rearms_;
      mapping_.rotation = rotation_;
    }
    if (factor != appliedForceFactor_) {
      scale_ =
          chooseForceScale(device_.info(), mapping_.scale, scene_.youngs, scene_.radius, factor);
      appliedForceFactor_ = factor;
    }

    const bool connected = hand.device.connected;
    const uint32_t buttons = connected ? hand.device.buttons : 0;
    const Eigen::Vector3d& device = hand.device.position;
    if (connected && (buttons & kClutchButton)) {
      if (!clutching) clutchStart = device, offsetStart = mapping_.clutchOffset;
      mapping_.clutchOffset = offsetStart + (device - clutchStart);
      clutching = true;
    } else {
      clutching = false;
    }

    ToolInput input;
    input.position = mapping_.toScene(device);
    input.orientation = hand.device.orientation;
    input.buttons = buttons;
    const bool toolHeld = (buttons & kToolButton) != 0;
    bool want = false;
    switch (tool) {
      case HapticTool::Pull:
      case HapticTool::Inflate: want = connected && toolHeld && !clutching; break;
      case HapticTool::Probe: want = connected && !clutching; break;
      case HapticTool::None: break;
    }
    if (stroke != 0 && (!want || tool != strokeTool || paint != strokePaint)) endStroke(input);
    if (want && stroke == 0) {
      std::unique_ptr<Tool> made = makeTool(tool, paint);
      if (made) {
        stroke = loop_.beginStroke(std::move(made), input);
        strokeTool = tool, strokePaint = paint;
        inflateAnchor = device;
        lastSent = input;
      }
    } else if (stroke != 0 &&
               (input.position != lastSent.position || input.buttons != lastSent.buttons)) {
      loop_.updateStroke(stroke, input);
      lastSent = input;
    }

    ServoCommand command;
    command.strokeId = stroke;
    command.tool = stroke != 0 ? strokeTool : HapticTool::None;
    command.mapping = mapping_;
    command.forceScale = scale_.sceneNewtonsPerDeviceNewton;
    // Passivity of the sampled coupling needs b > k T / 2 (k = k_stable / 2 at 1 kHz): a tenth of
    // the device's recommended damping is several times that.
    command.damping = 0.1 * device_.info().damping;
    command.inflateStiffness = 0.1 * device_.info().stableStiffness;
    command.inflateAnchor = inflateAnchor;
    command.inflateMaxForce = 0.15 * device_.info().maxForce;
    command.rearmCount = rearms;
    command.focused = focused;
    command.panic = panic;
    servo_.command(command);
    publishStatus(hand, clutching, stroke != 0, tool);
  }
  ToolInput last;
  last.position = mapping_.toScene(servo_.latest().device.position);
  last.buttons = 0;
  endStroke(last);
  ServoCommand idle;
  idle.mapping = mapping_;
  servo_.command(idle);
}

void HapticSession::publishStatus(const HandState& hand, bool clutching, bool stroking,
                                  HapticTool tool) {
  const std::lock_guard lock(mutex_);
  status_.stroking = stroking;
  status_.tool = tool;
  status_.connected = hand.device.connected;
  status_.buttons = hand.device.buttons;
  status_.clutching = clutching;
  status_.acting = hand.result.acting;
  status_.tripped = hand.tripped;
  status_.toolScene = hand.result.toolScene;
  status_.force = hand.result.commanded;
  status_.probeAge = hand.probeAge;
  status_.scale = scale_;
  status_.mapping = mapping_;
  status_.servoTicks = hand.tick;
}

}  // namespace sculpt::haptics
