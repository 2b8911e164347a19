#include "sculpt/stylus_device.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "haptics/hid/hidapi_transport.h"
#include "sculpt/value_slider.h"

namespace sculpt::app {
namespace {

const char* toolLabel(haptics::HapticTool tool, bool paint) {
  switch (tool) {
    case haptics::HapticTool::Pull: return "pull";
    case haptics::HapticTool::Probe: return paint ? "stiffness paint" : "probe (feel stiffness)";
    case haptics::HapticTool::Inflate: return "inflate";
    case haptics::HapticTool::None: break;
  }
  return "none";
}

}  // namespace

StylusDevice::StylusDevice() = default;

StylusDevice::~StylusDevice() { stop(); }

void StylusDevice::enableHid() {
  if (devices_ || !devicesError_.empty()) return;
  try {  // HID devices are listed in the panel; none is normal
    devices_ = std::make_unique<haptics::DeviceManager>(
        [] { return std::make_unique<haptics::HidapiTransport>(); });
  } catch (const std::exception& e) {
    devicesError_ = e.what();
  }
}

bool StylusDevice::driveCamera(render::Camera& camera, float dt, int viewportHeight) {
  if (!devices_ || !(dt > 0)) return false;
  dt = std::min(dt, 0.1f);  // a stalled frame does not fling the camera
  bool moved = false;
  for (const haptics::ManagedDevice& device : devices_->devices()) {
    if (!device.connected || device.id < 0) continue;
    if (channels_.size() <= static_cast<size_t>(device.id)) channels_.resize(device.id + 1);
    auto& channel = channels_[device.id];
    if (!channel) channel = devices_->channel(device.id);
    if (!channel) continue;
    const haptics::HidInputState& s = channel->read();
    if (!s.connected) continue;
    // Rates at full deflection: half a turn per second, a viewport height per second, e^2 zoom.
    const auto& t = s.translation;
    const auto& r = s.rotation;
    if (r[0] != 0 || r[1] != 0)
      camera.orbitBy(static_cast<float>(-r[1] * M_PI * dt), static_cast<float>(r[0] * M_PI * dt));
    if (t[0] != 0 || t[1] != 0)
      camera.pan(static_cast<float>(t[0] * viewportHeight * dt),
                 static_cast<float>(-t[1] * viewportHeight * dt), viewportHeight);
    if (t[2] != 0) camera.zoom(static_cast<float>(std::exp(-2.0 * t[2] * dt)));
    moved |= r[0] != 0 || r[1] != 0 || t[0] != 0 || t[1] != 0 || t[2] != 0;
  }
  return moved;
}

void StylusDevice::stop() {
  if (session_) session_->stop();
  session_.reset();
  mock_.reset();
  sceneId_ = 0;
}

void StylusDevice::attach(SimulationLoop& loop,
                          const std::shared_ptr<const SceneGeometry>& geometry,
                          const SceneSettings& settings, bool physicsReady) {
  follow(loop, geometry, settings, physicsReady);
  shown_ = status();
}

void StylusDevice::follow(SimulationLoop& loop,
                          const std::shared_ptr<const SceneGeometry>& geometry,
                          const SceneSettings& settings, bool physicsReady) {
  if (!wanted_ || !geometry || !physicsReady) {
    if (!wanted_ && session_) stop();
    return;
  }
  if (session_ && sceneId_ == geometry->sceneId) return;
  stop();
  haptics::HandDynamics hand;  // a relaxed hand: the stylus lags visibly under load
  hand.stiffness = 150.0;
  hand.damping = 4.0;
  mock_ = std::make_unique<haptics::MockPhantom>(haptics::PhantomModel::kTouch, hand);
  const haptics::HapticScene scene = haptics::hapticSceneOf(geometry, settings);
  sceneRadius_ = scene.radius;
  haptics::HapticSessionSettings session;
  session.tool = tool_;
  session.paintWithProbe = paint_;
  session.forceFactor = forceFactor_;
  session.paint.brush.radius = 0.08 * scene.radius;
  session.paint.brush.target = settings.material;
  session.paint.brush.target.youngs *= 10.0;
  session.paint.brush.mirror.x = false;
  session.inflate.radius = 0.15 * scene.radius;
  session.inflate.pressure = 0.05 * settings.material.youngs;
  session_ = std::make_unique<haptics::HapticSession>(loop, *mock_, scene, session);
  session_->start();
  sceneId_ = geometry->sceneId;
  handScene_ = scene.centre + Eigen::Vector3d(0, 0, scene.radius * 0.9);
  moveHand(handScene_, false);
}

void StylusDevice::moveHand(const Eigen::Vector3d& scenePoint, bool button) {
  if (!session_ || !mock_) return;
  handScene_ = scenePoint;
  mock_->setHandTarget(session_->status().mapping.toDevice(scenePoint), button ? 1u : 0u);
}

void StylusDevice::setView(const render::Camera& camera) {
  if (!session_) return;
  const glm::vec3 r = camera.right(), u = camera.up(), b = camera.backward();
  Eigen::Matrix3d axes;
  axes.col(0) = Eigen::Vector3d(r.x, r.y, r.z);
  axes.col(1) = Eigen::Vector3d(u.x, u.y, u.z);
  axes.col(2) = Eigen::Vector3d(b.x, b.y, b.z);  // the device's z points at the user
  session_->setRotation(Eigen::Quaterniond(axes));
}

void StylusDevice::setFocused(bool focused) {
  if (session_) session_->setFocused(focused);
}

void StylusDevice::panic() {
  if (session_) session_->panic();
}

haptics::HapticStatus StylusDevice::status() const {
  return session_ ? session_->status() : haptics::HapticStatus{};
}

float StylusDevice::forceFraction() const {
  if (!session_) return 0.0f;
  const haptics::HapticStatus& s = shown_;
  return s.forceLimit > 0 ? static_cast<float>(std::clamp(s.force.norm() / s.forceLimit, 0.0, 1.0))
                          : 0.0f;
}

void StylusDevice::drawPanel(ImVec2 viewMin, ImVec2 viewMax) {
  (void)viewMax;
  ImGui::SetNextWindowPos(ImVec2(viewMin.x + 10, viewMin.y + 10), ImGuiCond_FirstUseEver);
  const float scale = ImGui::GetFontSize() / 13.0f;  // the limits follow the UI scale
  ImGui::SetNextWindowSizeConstraints(ImVec2(380 * scale, 0), ImVec2(600 * scale, 600 * scale));
  if (!ImGui::Begin("Stylus", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::End();
    return;
  }
  bool on = wanted_;
  if (ImGui::Checkbox("Simulated device (the mouse drives a mock Touch)", &on)) wanted_ = on;
  int tool = tool_ == haptics::HapticTool::Probe ? (paint_ ? 2 : 1)
             : tool_ == haptics::HapticTool::Inflate ? 3 : 0;
  const char* tools[] = {"Pull", "Probe (feel stiffness)", "Stiffness paint", "Inflate"};
  if (ImGui::Combo("Tool", &tool, tools, 4)) {
    tool_ = tool == 0 ? haptics::HapticTool::Pull
            : tool == 3 ? haptics::HapticTool::Inflate : haptics::HapticTool::Probe;
    paint_ = tool == 2;
    if (session_) session_->setTool(tool_, paint_);
  }
  if (valueSliderFloat("Scene force x", &forceFactor_, 0.1f, 10.0f, "%.2f",
                       ImGuiSliderFlags_Logarithmic) &&
      session_)
    session_->setForceFactor(forceFactor_);
  ImGui::Checkbox("Tint the background with the force", &tint_);
  if (session_) {
    const haptics::HapticStatus& s = shown_;
    ImGui::Text("%s: %s, %s%s", mock_ ? mock_->info().model.c_str() : "device",
                s.connected ? "connected" : "not connected", toolLabel(s.tool, paint_),
                s.stroking ? (s.acting ? ", acting" : ", holding") : "");
    const double f = s.force.norm();
    char label[64];
    std::snprintf(label, sizeof label, "%.2f / %.1f N", f, s.forceLimit);
    const float fraction = s.forceLimit > 0 ? static_cast<float>(f / s.forceLimit) : 0.0f;
    ImGui::PushStyleColor(ImGuiCol_PlotHistogram, fraction > 0.8f ? ImVec4(0.9f, 0.3f, 0.2f, 1)
                                                                  : ImVec4(0.3f, 0.7f, 0.4f, 1));
    ImGui::ProgressBar(fraction, ImVec2(-1, 0), label);
    ImGui::PopStyleColor();
    ImGui::TextWrapped("%s", s.scale.describe().c_str());
    ImGui::Text("Servo %llu ticks, probe %.0f ms old",
                static_cast<unsigned long long>(s.servoTicks), s.probeAge * 1e3);
    if (s.tripped) {
      ImGui::TextColored(ImVec4(1, 0.4f, 0.3f, 1), "Force tripped: zero until re-armed");
      if (ImGui::Button("Re-arm")) session_->rearm();
    }
    if (ImGui::Button("Panic: zero force (Esc)")) session_->panic();
    ImGui::SameLine();
    if (ImGui::Button("Re-arm##always")) session_->rearm();
  } else {
    ImGui::TextDisabled(wanted_ ? "waiting for the simulation" : "off");
  }
  ImGui::Separator();
  if (devices_) {
    const std::vector<haptics::ManagedDevice> found = devices_->devices();
    if (found.empty()) ImGui::TextDisabled("No HID devices (SpaceMouse family or a profile)");
    for (const haptics::ManagedDevice& d : found)
      ImGui::Text("%s (%s)%s", d.model.c_str(), d.profileName.c_str(),
                  d.connected ? "" : ", unplugged");
  } else if (!devicesError_.empty()) {
    ImGui::TextDisabled("HID: %s", devicesError_.c_str());
  }
  ImGui::End();
}

void StylusDevice::drawCursor(ImDrawList* draw, const render::Camera& camera, ImVec2 viewMin,
                              ImVec2 viewMax) const {
  if (!session_) return;
  const haptics::HapticStatus& s = shown_;
  const int width = std::max(1, static_cast<int>(viewMax.x - viewMin.x));
  const int height = std::max(1, static_cast<int>(viewMax.y - viewMin.y));
  const auto screen = [&](const Eigen::Vector3d& p) {
    const glm::vec3 q = camera.project(glm::vec3(p.x(), p.y(), p.z()), width, height);
    return ImVec2(viewMin.x + q.x, viewMin.y + q.y);
  };
  const ImVec2 tip = screen(s.toolScene), hand = screen(handScene_);
  const glm::vec3 right = camera.right();
  const double radius = (tool_ == haptics::HapticTool::Pull ? 0.02 : 0.08) * sceneRadius_;
  const ImVec2 edge = screen(s.toolScene + radius * Eigen::Vector3d(right.x, right.y, right.z));
  const float pixels = std::max(4.0f, std::hypot(edge.x - tip.x, edge.y - tip.y));
  const ImU32 colour = s.acting ? IM_COL32(255, 120, 60, 255) : IM_COL32(120, 220, 255, 255);
  draw->AddLine(hand, tip, IM_COL32(255, 255, 255, 90), 1.0f);  // the hand's lead
  draw->AddCircle(hand, 3.0f, IM_COL32(255, 255, 255, 140), 12, 1.0f);
  draw->AddCircleFilled(tip, 4.0f, colour, 16);
  draw->AddCircle(tip, pixels, colour, 48, 2.0f);
}

}  // namespace sculpt::app
