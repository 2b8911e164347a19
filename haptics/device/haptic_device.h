#pragma once
// What every input or force device looks like to the servo (like CHAI3D's generic device): a
// sample of its state (position, orientation, estimated linear velocity, buttons) and, for a
// device with force, a force command. Devices are read and commanded from the servo thread only,
// and neither call may block: a device whose transport is slow (hidapi) is read on its own
// thread and hands its newest sample over (hid/hid_input_device.h).
//
// Units and frames: metres, newtons and seconds in the device's own frame (for a PHANTOM-class
// arm: x right, y up, z towards the user, origin at the workspace centre). The servo maps the
// device frame into the scene (servo/workspace_mapping.h).

#include <cstdint>
#include <string>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace sculpt::haptics {

/// What a device senses and actuates (DeviceInfo::capabilities).
enum DeviceCapability : uint32_t {
  kSensesPosition = 1u << 0,
  kSensesRotation = 1u << 1,
  kSensesButtons = 1u << 2,
  kActuatesForce = 1u << 3,
  /// An elastic 6-DOF controller (SpaceMouse): the position is a displacement from rest, to be
  /// read as a velocity and integrated, not a place in a workspace.
  kRateControl = 1u << 4,
};

/// A device's description and limits (CHAI3D's cHapticDeviceInfo).
struct DeviceInfo {
  std::string model;         ///< "Mock Touch", "SpaceNavigator", ...
  std::string manufacturer;
  double maxForce = 0.0;         ///< maximum continuous force, N (0: no force)
  double stableStiffness = 0.0;  ///< highest closed-loop stiffness at 1 kHz, N/m
  double damping = 0.0;          ///< recommended damping with its velocity estimate, N s/m
  double workspaceRadius = 0.0;  ///< radius of the largest sphere inside the workspace, m
  uint32_t capabilities = 0;     ///< DeviceCapability flags

  bool hasForce() const { return (capabilities & kActuatesForce) != 0 && maxForce > 0; }
  bool rateControl() const { return (capabilities & kRateControl) != 0; }
};

/// One reading of a device.
struct DeviceSample {
  double time = 0.0;  ///< s, the device's clock (the servo's for devices it polls)
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  ///< m (rate devices: normalised, [-1, 1])
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();  ///< m/s, estimated over a short window
  /// Rate devices: the rotation axes, normalised to [-1, 1] (zero for other devices).
  Eigen::Vector3d rotationRate = Eigen::Vector3d::Zero();
  uint32_t buttons = 0;     ///< bit i: button i held
  bool connected = false;   ///< false: unplugged, not opened, or failed (no force is rendered)
};

class HapticDevice {
 public:
  virtual ~HapticDevice() = default;
  virtual const DeviceInfo& info() const = 0;
  /// Servo thread: the newest state at servo time `now` (s). Never blocks.
  virtual DeviceSample read(double now) = 0;
  /// Servo thread: the force to render from now on (N, device frame). Ignored by devices without
  /// force. Never blocks. The servo has already made it safe (servo/force_safety.h).
  virtual void sendForce(const Eigen::Vector3d& force) = 0;
};

}  // namespace sculpt::haptics
