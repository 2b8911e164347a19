#include "haptics/hid/replay_transport.h"

#include <algorithm>
#include <atomic>
#include <cstring>
#include <thread>

namespace sculpt::haptics {

struct ReplayDeviceState {
  HidRecording recording;
  std::atomic<bool> finished{false};  // a connection read past the last report
};

namespace {

using Clock = std::chrono::steady_clock;

class ReplayConnection : public HidConnection {
 public:
  ReplayConnection(std::shared_ptr<ReplayDeviceState> shared, bool honourTimestamps)
      : shared_(std::move(shared)), honourTimestamps_(honourTimestamps), opened_(Clock::now()) {}

  int read(uint8_t* data, size_t size, int timeoutMs) override;
  int write(const uint8_t*, size_t) override { return fail("a recording takes no output"); }
  int getFeatureReport(uint8_t*, size_t) override { return fail("a recording has no features"); }
  int sendFeatureReport(const uint8_t*, size_t) override {
    return fail("a recording has no features");
  }
  std::string lastError() const override { return error_; }

 private:
  int fail(const char* why) {
    error_ = why;
    return -1;
  }

  std::shared_ptr<ReplayDeviceState> shared_;
  bool honourTimestamps_;
  Clock::time_point opened_;
  size_t next_ = 0;
  std::string error_;
};

int ReplayConnection::read(uint8_t* data, size_t size, int timeoutMs) {
  const std::vector<HidRecordedEvent>& events = shared_->recording.events;
  if (next_ >= events.size()) {
    shared_->finished = true;
    return fail("the recording has ended");
  }
  const HidRecordedEvent& event = events[next_];
  if (honourTimestamps_) {
    const double offset = event.time - events.front().time;
    const auto due = opened_ + std::chrono::duration_cast<Clock::duration>(
                                   std::chrono::duration<double>(offset));
    const auto now = Clock::now();
    if (due > now) {
      if (timeoutMs >= 0 && due - now > std::chrono::milliseconds(timeoutMs)) {
        std::this_thread::sleep_for(std::chrono::milliseconds(timeoutMs));
        return 0;
      }
      std::this_thread::sleep_until(due);
    }
  }
  ++next_;
  // As hidraw does, a report longer than the buffer is cut to it.
  const size_t copied = std::min(size, event.bytes.size());
  if (copied > 0) std::memcpy(data, event.bytes.data(), copied);
  return static_cast<int>(copied);
}

}  // namespace

ReplayTransport::ReplayTransport(HidRecording recording, const std::string& file,
                                 ReplayOptions options)
    : shared_(std::make_shared<ReplayDeviceState>()), path_("replay:" + file), options_(options) {
  shared_->recording = std::move(recording);
}

ReplayTransport::ReplayTransport(const std::string& file, ReplayOptions options)
    : ReplayTransport(loadHidRecording(file), file, options) {}

std::vector<HidDeviceInfo> ReplayTransport::enumerate() {
  if (shared_->finished) return {};
  const HidRecording& recording = shared_->recording;
  HidDeviceInfo device;
  device.path = path_;
  device.vendorId = recording.vendorId;
  device.productId = recording.productId;
  device.product = recording.name;
  const HidUsage usage = topLevelUsage(recording.descriptor);
  device.usagePage = usage.page;
  device.usage = usage.usage;
  return {device};
}

std::unique_ptr<HidConnection> ReplayTransport::open(const std::string& path, std::string* error) {
  if (path != path_ || shared_->finished) {
    if (error != nullptr) *error = path + ": no such recorded device";
    return nullptr;
  }
  return std::make_unique<ReplayConnection>(shared_, options_.honourTimestamps);
}

}  // namespace sculpt::haptics
