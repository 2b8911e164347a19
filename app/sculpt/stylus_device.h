#pragma once
// The window's stylus: a haptic session (haptics/session/haptic_session.h) on the running scene,
// with its device panel, its 3D cursor and the background's tint (McDonnell-Qin Fig. 8: the
// background's saturation shows the force felt). Without hardware, "simulated device" mode
// drives the mock PHANTOM-class arm from the mouse: the mouse moves the hand's set point and the
// mock's hand spring lags behind it by the force the servo renders, so the whole force path can
// be seen and tried. HID devices found by the device manager (SpaceMouse family, profiles) are
// listed in the panel.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <imgui.h>

#include "haptics/hid/device_manager.h"
#include "haptics/mock/mock_phantom.h"
#include "haptics/session/haptic_session.h"
#include "render/camera.h"
#include "scene/scene_builder.h"
#include "scene/simulation_loop.h"

namespace sculpt::app {

class StylusDevice {
 public:
  StylusDevice();
  ~StylusDevice();

  /// Looks for HID devices (a device-manager thread polling hidapi); off in headless runs.
  void enableHid();
  /// A SpaceMouse (or any HID 6-DOF device) orbits, pans and zooms the camera by rate control:
  /// its displacement is a velocity. Returns true when the camera moved. UI thread.
  bool driveCamera(render::Camera& camera, float dt, int viewportHeight);
  /// Simulated-device mode on or off (applied at the next attach()).
  void setSimulated(bool on) { wanted_ = on; }
  bool simulated() const { return wanted_; }
  /// Follows the scene: (re)starts the session on a newly running scene, stops it when the mode
  /// is off. Call once per frame: it also reads the status the frame shows (shownStatus()).
  void attach(SimulationLoop& loop, const std::shared_ptr<const SceneGeometry>& geometry,
              const SceneSettings& settings, bool physicsReady);
  void stop();
  bool active() const { return session_ != nullptr; }

  /// The mouse, in simulated mode: where the hand means the stylus to be (scene m) and whether
  /// its button is held.
  void moveHand(const Eigen::Vector3d& scenePoint, bool button);
  /// The camera turns the device's axes (right on the device is right on the screen).
  void setView(const render::Camera& camera);
  void setFocused(bool focused);
  /// Zero force until re-armed (the panel's button, Esc in the window).
  void panic();

  /// The status read by this frame's attach(): the meter, the cursor and the background's tint
  /// all show it, so that they agree within a frame (the servo changes it a thousand times a
  /// second).
  const haptics::HapticStatus& shownStatus() const { return shown_; }
  /// Force shown, as a fraction of the device's limit (0 when off).
  float forceFraction() const;
  /// The background's tint in [0, 1]: the force fraction, or 0 when tinting is switched off.
  float backgroundTint() const { return tint_ ? forceFraction() : 0.0f; }
  /// The device panel (an ImGui window), first placed at the upper left of the view.
  void drawPanel(ImVec2 viewMin, ImVec2 viewMax);
  /// The stylus' cursor and, when probing or painting, its brush radius, in the view.
  void drawCursor(ImDrawList* draw, const render::Camera& camera, ImVec2 viewMin,
                  ImVec2 viewMax) const;
  haptics::HapticTool tool() const { return tool_; }
  /// The session's status now (the servo's latest).
  haptics::HapticStatus status() const;

 private:
  void follow(SimulationLoop& loop, const std::shared_ptr<const SceneGeometry>& geometry,
              const SceneSettings& settings, bool physicsReady);

  bool wanted_ = false, tint_ = true, paint_ = false;
  haptics::HapticTool tool_ = haptics::HapticTool::Pull;
  float forceFactor_ = 1.0f;
  uint64_t sceneId_ = 0;
  double sceneRadius_ = 1.0;
  std::unique_ptr<haptics::MockPhantom> mock_;
  std::unique_ptr<haptics::HapticSession> session_;
  std::unique_ptr<haptics::DeviceManager> devices_;
  std::string devicesError_;
  std::vector<std::shared_ptr<haptics::HidDeviceChannel>> channels_;  // by device id
  Eigen::Vector3d handScene_ = Eigen::Vector3d::Zero();
  haptics::HapticStatus shown_;
};

}  // namespace sculpt::app
