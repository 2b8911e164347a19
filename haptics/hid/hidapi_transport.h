#pragma once
// The real HidTransport: hidapi 0.13.1's hidraw backend (the libusb one would detach the
// kernel driver). hid_init runs when the first instance is made and hid_exit when the last one
// goes. hidapi wants enumeration and opening on one thread: the device manager's.

#include <vector>

#include "haptics/hid/hid_transport.h"

namespace sculpt::haptics {

class HidapiTransport : public HidTransport {
 public:
  /// Throws std::runtime_error when hid_init fails.
  HidapiTransport();
  ~HidapiTransport() override;
  HidapiTransport(const HidapiTransport&) = delete;
  HidapiTransport& operator=(const HidapiTransport&) = delete;

  /// hid_enumerate(0, 0), one entry per path: hidapi lists a path once per top-level usage;
  /// the multi-axis controller entry (usage page 0x01, usage 0x08) is kept when there is one,
  /// the first listed otherwise.
  std::vector<HidDeviceInfo> enumerate() override;
  std::unique_ptr<HidConnection> open(const std::string& path, std::string* error) override;
};

}  // namespace sculpt::haptics
