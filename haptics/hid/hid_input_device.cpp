#include "haptics/hid/hid_input_device.h"

#include <stdexcept>
#include <string>

namespace sculpt::haptics {

HidInputDevice::HidInputDevice(const DeviceManager& manager, int id)
    : channel_(manager.channel(id)) {
  if (!channel_) throw std::invalid_argument("no HID device " + std::to_string(id));
  for (const ManagedDevice& device : manager.devices()) {
    if (device.id != id) continue;
    info_.model = device.model;
    info_.manufacturer = device.manufacturer;
    forceOutput_ = device.hasForceOutput;
    info_.maxForce = device.maxForce;
  }
  info_.capabilities = kSensesPosition | kSensesRotation | kSensesButtons | kRateControl;
  if (forceOutput_ && info_.maxForce > 0) info_.capabilities |= kActuatesForce;
}

DeviceSample HidInputDevice::read(double now) {
  const HidInputState& state = channel_->read();
  DeviceSample sample;
  sample.time = now;
  sample.connected = state.connected;
  sample.position =
      Eigen::Vector3d(state.translation[0], state.translation[1], state.translation[2]);
  sample.rotationRate = Eigen::Vector3d(state.rotation[0], state.rotation[1], state.rotation[2]);
  sample.buttons = state.buttons;
  return sample;
}

void HidInputDevice::sendForce(const Eigen::Vector3d& force) {
  if (forceOutput_) channel_->requestForce(force);
}

}  // namespace sculpt::haptics
