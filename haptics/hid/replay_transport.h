#pragma once
// A HidTransport presenting one recorded device (hid_recording.h) as if it were plugged in: it
// is listed as "replay:<file>", and reading it returns the recorded reports in order, then -1
// (unplugged) after the last one, from when on it is no longer listed. By default reports come
// as fast as they are read; with honourTimestamps they come at their recorded times after open.

#include <chrono>
#include <memory>
#include <string>

#include "haptics/hid/hid_recording.h"
#include "haptics/hid/hid_transport.h"

namespace sculpt::haptics {

struct ReplayDeviceState;  // the recording and whether it has been played out

struct ReplayOptions {
  bool honourTimestamps = false;
};

class ReplayTransport : public HidTransport {
 public:
  /// `file` names the device's path ("replay:<file>").
  ReplayTransport(HidRecording recording, const std::string& file, ReplayOptions options = {});
  /// Loads `file` (throws FileError).
  explicit ReplayTransport(const std::string& file, ReplayOptions options = {});

  /// The recorded device (vendor and product from I:, product name from N:, usage from the
  /// descriptor's first collection), until a connection has read past its last report.
  std::vector<HidDeviceInfo> enumerate() override;
  /// Each open starts the recording from its first report.
  std::unique_ptr<HidConnection> open(const std::string& path, std::string* error) override;

  const std::string& path() const { return path_; }

 private:
  std::shared_ptr<ReplayDeviceState> shared_;
  std::string path_;
  ReplayOptions options_;
};

}  // namespace sculpt::haptics
