#pragma once
// A HID device of the device manager seen as a HapticDevice: read() takes the manager's newest
// decoded state without waiting (position = normalised translation, rotationRate = normalised
// rotation, both in [-1, 1]; a rate controller, so they are displacements to integrate), and
// sendForce() hands a force to the manager thread when the device's profile has a force output
// (and does nothing otherwise). Neither call touches the transport.

#include <memory>

#include "haptics/device/haptic_device.h"
#include "haptics/hid/device_manager.h"

namespace sculpt::haptics {

class HidInputDevice : public HapticDevice {
 public:
  /// Device `id` of `manager` (ManagedDevice::id). Throws std::invalid_argument for an unknown
  /// id. Keeps the device's channel, so it may outlive the manager (then it reads disconnected).
  /// Make one per device: it is the channel's only reader and force writer.
  HidInputDevice(const DeviceManager& manager, int id);

  /// Capabilities: position, rotation, buttons, rate control (and force when the profile has a
  /// force output with a max_force); maxForce from the profile, 0 otherwise.
  const DeviceInfo& info() const override { return info_; }
  /// The newest state, stamped `now`. Never blocks.
  DeviceSample read(double now) override;
  /// Queued for the manager thread when the profile has a force output; never blocks.
  void sendForce(const Eigen::Vector3d& force) override;

 private:
  std::shared_ptr<HidDeviceChannel> channel_;
  DeviceInfo info_;
  bool forceOutput_ = false;
};

}  // namespace sculpt::haptics
