#pragma once
// The seam between the HID device code and whatever carries HID reports: the real hidapi library
// (hidapi_transport.h), a recorded device (replay_transport.h) or a test script
// (scripted_transport.h). The calls mirror hidapi's, so the device manager behaves the same over
// all three, and everything above this seam is tested without hardware.
//
// Report buffers follow hidapi: byte 0 of an output or feature report is its report ID (0 for a
// device without numbered reports); an input report from a device with numbered reports starts
// with its ID.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace sculpt::haptics {

/// One HID interface as enumeration lists it.
struct HidDeviceInfo {
  std::string path;  ///< what open() takes ("/dev/hidraw3", "replay:file.txt", ...)
  uint16_t vendorId = 0;
  uint16_t productId = 0;
  std::string manufacturer, product, serial;  ///< UTF-8, empty when the device has none
  /// Top-level collection usage; 0 and 0 when the transport does not report usages.
  uint16_t usagePage = 0;
  uint16_t usage = 0;
  int interfaceNumber = -1;
};

/// An open device. Not thread-safe: one thread makes all calls on one connection.
class HidConnection {
 public:
  virtual ~HidConnection() = default;
  /// Reads one input report into `data` (at most `size` bytes), waiting up to `timeoutMs`
  /// (-1: until one comes). Returns the bytes read, 0 on timeout, -1 when the device is gone or
  /// failed (as hid_read_timeout).
  virtual int read(uint8_t* data, size_t size, int timeoutMs) = 0;
  /// Sends an output report; returns the bytes written or -1.
  virtual int write(const uint8_t* data, size_t size) = 0;
  /// Fills a feature report whose ID is data[0]; returns the bytes read or -1.
  virtual int getFeatureReport(uint8_t* data, size_t size) = 0;
  /// Sends a feature report; returns the bytes written or -1.
  virtual int sendFeatureReport(const uint8_t* data, size_t size) = 0;
  /// What went wrong in the last failed call, in UTF-8.
  virtual std::string lastError() const = 0;
};

/// Lists and opens devices. Not thread-safe: one thread enumerates and opens.
class HidTransport {
 public:
  virtual ~HidTransport() = default;
  /// Every HID interface present now (a path may repeat, once per top-level usage).
  virtual std::vector<HidDeviceInfo> enumerate() = 0;
  /// Opens `path`; on failure returns null and, when `error` is given, sets it to the reason.
  virtual std::unique_ptr<HidConnection> open(const std::string& path, std::string* error) = 0;
};

/// The multi-axis controller collection (generic desktop page 0x01, usage 0x08).
inline bool isMultiAxisController(const HidDeviceInfo& device) {
  return device.usagePage == 0x01 && device.usage == 0x08;
}

/// One entry per path, in order of first listing; where a path is listed more than once, the
/// multi-axis controller entry is kept when there is one, the first listed otherwise.
inline std::vector<HidDeviceInfo> deduplicateByPath(const std::vector<HidDeviceInfo>& devices) {
  std::vector<HidDeviceInfo> unique;
  for (const HidDeviceInfo& device : devices) {
    const auto same = std::find_if(unique.begin(), unique.end(), [&](const HidDeviceInfo& kept) {
      return kept.path == device.path;
    });
    if (same == unique.end()) {
      unique.push_back(device);
    } else if (!isMultiAxisController(*same) && isMultiAxisController(device)) {
      *same = device;
    }
  }
  return unique;
}

}  // namespace sculpt::haptics
