#include "haptics/hid/scripted_transport.h"

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstring>
#include <deque>
#include <map>
#include <mutex>

namespace sculpt::haptics {

namespace {

struct ScriptedDevice {
  std::vector<HidDeviceInfo> entries;  // one per listing
  bool plugged = true;
  uint64_t plugging = 0;  // counts unplugs: a connection opened before one is dead
  std::deque<ScriptStep> steps;
  int writesToFail = 0;
  int opensToFail = 0;
  std::string openError;
  int opens = 0;
  std::map<uint8_t, std::vector<uint8_t>> features;
};

}  // namespace

struct ScriptedTransportState {
  mutable std::mutex mutex;
  std::condition_variable changed;
  std::map<std::string, ScriptedDevice> devices;
  std::vector<SentReport> sent;
  std::vector<std::thread::id> threads;

  // With the mutex held.
  void noteThread() {
    const std::thread::id self = std::this_thread::get_id();
    if (std::find(threads.begin(), threads.end(), self) == threads.end()) threads.push_back(self);
  }
  void unplug(ScriptedDevice& device) {
    if (!device.plugged) return;
    device.plugged = false;
    ++device.plugging;
  }
};

namespace {

class ScriptedConnection : public HidConnection {
 public:
  ScriptedConnection(std::shared_ptr<ScriptedTransportState> state, std::string path,
                     uint64_t plugging)
      : state_(std::move(state)), path_(std::move(path)), plugging_(plugging) {}

  int read(uint8_t* data, size_t size, int timeoutMs) override {
    std::unique_lock<std::mutex> lock(state_->mutex);
    state_->noteThread();
    ScriptedDevice& device = state_->devices.at(path_);
    const auto ready = [&] { return !alive(device) || !device.steps.empty(); };
    if (timeoutMs < 0) {
      state_->changed.wait(lock, ready);
    } else if (!state_->changed.wait_for(lock, std::chrono::milliseconds(timeoutMs), ready)) {
      return 0;
    }
    if (!alive(device)) return fail("device unplugged");
    const ScriptStep step = std::move(device.steps.front());
    device.steps.pop_front();
    switch (step.kind) {
      case ScriptStep::Kind::kTimeout:
        return 0;
      case ScriptStep::Kind::kDisconnect:
        state_->unplug(device);
        return fail("device unplugged");
      case ScriptStep::Kind::kReport:
        break;
    }
    const size_t copied = std::min(size, step.bytes.size());
    if (copied > 0) std::memcpy(data, step.bytes.data(), copied);
    return static_cast<int>(copied);
  }

  int write(const uint8_t* data, size_t size) override {
    return send(SentReport::Kind::kOutput, data, size);
  }
  int sendFeatureReport(const uint8_t* data, size_t size) override {
    return send(SentReport::Kind::kFeature, data, size);
  }
  int getFeatureReport(uint8_t* data, size_t size) override {
    std::lock_guard<std::mutex> lock(state_->mutex);
    state_->noteThread();
    ScriptedDevice& device = state_->devices.at(path_);
    if (!alive(device)) return fail("device unplugged");
    if (size == 0) return fail("no room for a report ID");
    const auto feature = device.features.find(data[0]);
    if (feature == device.features.end()) return fail("no such feature report");
    const size_t copied = std::min(size, feature->second.size());
    std::memcpy(data, feature->second.data(), copied);
    return static_cast<int>(copied);
  }
  std::string lastError() const override {
    std::lock_guard<std::mutex> lock(state_->mutex);
    return error_;
  }

 private:
  bool alive(const ScriptedDevice& device) const {
    return device.plugged && device.plugging == plugging_;
  }
  // With the mutex held.
  int fail(const char* why) {
    error_ = why;
    return -1;
  }

  int send(SentReport::Kind kind, const uint8_t* data, size_t size) {
    std::lock_guard<std::mutex> lock(state_->mutex);
    state_->noteThread();
    ScriptedDevice& device = state_->devices.at(path_);
    SentReport sent{path_, kind, std::vector<uint8_t>(data, data + size),
                    std::this_thread::get_id(), false};
    int result = static_cast<int>(size);
    if (!alive(device)) {
      result = fail("device unplugged");
    } else if (device.writesToFail > 0) {
      --device.writesToFail;
      result = fail("scripted write failure");
    }
    sent.failed = result < 0;
    state_->sent.push_back(std::move(sent));
    return result;
  }

  std::shared_ptr<ScriptedTransportState> state_;
  std::string path_;
  uint64_t plugging_;
  std::string error_;  // guarded by the state's mutex
};

}  // namespace

ScriptStep ScriptStep::garbage(size_t size, uint32_t seed) {
  std::vector<uint8_t> bytes(size);
  uint32_t x = seed * 2654435761u + 1;
  for (uint8_t& byte : bytes) {
    x ^= x << 13;
    x ^= x >> 17;
    x ^= x << 5;
    byte = static_cast<uint8_t>(x >> 24);
  }
  return report(std::move(bytes));
}

ScriptedTransport::ScriptedTransport() : state_(std::make_shared<ScriptedTransportState>()) {}
ScriptedTransport::~ScriptedTransport() = default;

void ScriptedTransport::addDevice(const HidDeviceInfo& device) {
  std::lock_guard<std::mutex> lock(state_->mutex);
  state_->devices[device.path].entries.push_back(device);
}

void ScriptedTransport::script(const std::string& path, std::vector<ScriptStep> steps) {
  {
    std::lock_guard<std::mutex> lock(state_->mutex);
    std::deque<ScriptStep>& queue = state_->devices[path].steps;
    for (ScriptStep& step : steps) queue.push_back(std::move(step));
  }
  state_->changed.notify_all();
}

void ScriptedTransport::pushReport(const std::string& path, std::vector<uint8_t> bytes) {
  script(path, {ScriptStep::report(std::move(bytes))});
}

void ScriptedTransport::unplug(const std::string& path) {
  {
    std::lock_guard<std::mutex> lock(state_->mutex);
    state_->unplug(state_->devices[path]);
  }
  state_->changed.notify_all();
}

void ScriptedTransport::replug(const std::string& path) {
  std::lock_guard<std::mutex> lock(state_->mutex);
  state_->devices[path].plugged = true;
}

void ScriptedTransport::failWrites(const std::string& path, int count) {
  std::lock_guard<std::mutex> lock(state_->mutex);
  state_->devices[path].writesToFail = count;
}

void ScriptedTransport::failOpens(const std::string& path, int count, const std::string& message) {
  std::lock_guard<std::mutex> lock(state_->mutex);
  ScriptedDevice& device = state_->devices[path];
  device.opensToFail = count;
  device.openError = message;
}

void ScriptedTransport::setFeatureReport(const std::string& path, std::vector<uint8_t> bytes) {
  if (bytes.empty()) return;
  std::lock_guard<std::mutex> lock(state_->mutex);
  state_->devices[path].features[bytes[0]] = std::move(bytes);
}

std::vector<SentReport> ScriptedTransport::sentReports() const {
  std::lock_guard<std::mutex> lock(state_->mutex);
  return state_->sent;
}

std::vector<std::thread::id> ScriptedTransport::callingThreads() const {
  std::lock_guard<std::mutex> lock(state_->mutex);
  return state_->threads;
}

size_t ScriptedTransport::pendingSteps(const std::string& path) const {
  std::lock_guard<std::mutex> lock(state_->mutex);
  const auto device = state_->devices.find(path);
  return device == state_->devices.end() ? 0 : device->second.steps.size();
}

int ScriptedTransport::openCount(const std::string& path) const {
  std::lock_guard<std::mutex> lock(state_->mutex);
  const auto device = state_->devices.find(path);
  return device == state_->devices.end() ? 0 : device->second.opens;
}

std::vector<HidDeviceInfo> ScriptedTransport::enumerate() {
  std::lock_guard<std::mutex> lock(state_->mutex);
  state_->noteThread();
  std::vector<HidDeviceInfo> listed;
  for (const auto& [path, device] : state_->devices)
    if (device.plugged) listed.insert(listed.end(), device.entries.begin(), device.entries.end());
  return listed;
}

std::unique_ptr<HidConnection> ScriptedTransport::open(const std::string& path,
                                                       std::string* error) {
  std::lock_guard<std::mutex> lock(state_->mutex);
  state_->noteThread();
  const auto found = state_->devices.find(path);
  const auto refuse = [&](const std::string& why) -> std::unique_ptr<HidConnection> {
    if (error != nullptr) *error = why;
    return nullptr;
  };
  if (found == state_->devices.end() || found->second.entries.empty() || !found->second.plugged)
    return refuse(path + ": no such device");
  ScriptedDevice& device = found->second;
  if (device.opensToFail > 0) {
    --device.opensToFail;
    return refuse(device.openError);
  }
  ++device.opens;
  return std::make_unique<ScriptedConnection>(state_, path, device.plugging);
}

}  // namespace sculpt::haptics
