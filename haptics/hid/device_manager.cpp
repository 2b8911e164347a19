#include "haptics/hid/device_manager.h"

#include <algorithm>
#include <cstdio>
#include <exception>

namespace sculpt::haptics {
namespace {

// Longer than any report a profile describes, so over-long reports are seen as such.
constexpr size_t kReadBufferBytes = 256;
// Reports taken from one device in one turn before moving on to the next device.
constexpr int kMaxReportsPerTurn = 32;

std::string idText(uint16_t vendorId, uint16_t productId) {
  char text[16];
  std::snprintf(text, sizeof text, "%04x:%04x", vendorId, productId);
  return text;
}

}  // namespace

struct DeviceManager::Device {
  ManagedDevice info;  // guarded by the manager's mutex
  std::shared_ptr<HidDeviceChannel> channel = std::make_shared<HidDeviceChannel>();
  // The manager thread's own:
  HidDeviceInfo listed;
  std::unique_ptr<HidConnection> connection;
  std::string matchedProfile;  // the profile the decoder was made for
  std::unique_ptr<HidReportDecoder> decoder;
  uint64_t forceSent = 0;  // sequence of the newest force request sent

  // The same physical device: vendor, product and serial (which may be empty) agree.
  bool sameDevice(const HidDeviceInfo& other) const {
    return listed.vendorId == other.vendorId && listed.productId == other.productId &&
           listed.serial == other.serial;
  }
};

void HidDeviceChannel::requestForce(const Eigen::Vector3d& forceN) {
  force_.publish({++forceRequests_, {forceN.x(), forceN.y(), forceN.z()}});
}

std::optional<ProfileMatch> matchProfile(const HidDeviceInfo& device,
                                         std::span<const HidProfile> userProfiles) {
  const bool usageKnown = device.usagePage != 0;
  for (const HidProfile& profile : userProfiles) {
    if (profile.vendorId != device.vendorId || profile.productId != device.productId) continue;
    if (profile.usagePage && usageKnown &&
        (device.usagePage != *profile.usagePage || device.usage != *profile.usage))
      continue;
    return ProfileMatch{profile.name, &profile, std::nullopt};
  }
  const std::optional<SpaceMouseLayout> layout =
      documentedLayout(device.vendorId, device.productId);
  if (layout && (!usageKnown || isMultiAxisController(device)))
    return ProfileMatch{spaceMouseProfile(*layout).name, nullptr, layout};
  return std::nullopt;
}

std::unique_ptr<HidReportDecoder> makeDecoder(const ProfileMatch& match,
                                              const SpaceMouseOptions& options) {
  if (match.userProfile != nullptr) return std::make_unique<ProfileDecoder>(*match.userProfile);
  return std::make_unique<SpaceMouseDecoder>(options, match.spaceMouseLayout);
}

DeviceManager::DeviceManager(HidTransport& transport, DeviceManagerOptions options)
    : options_(std::move(options)), transport_(&transport) {
  start();
}

DeviceManager::DeviceManager(TransportFactory makeTransport, DeviceManagerOptions options)
    : options_(std::move(options)), makeTransport_(std::move(makeTransport)) {
  start();
}

void DeviceManager::start() {
  startTime_ = std::chrono::steady_clock::now();
  thread_ = std::thread([this] { run(); });
  threadId_ = thread_.get_id();
}

DeviceManager::~DeviceManager() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

std::vector<ManagedDevice> DeviceManager::devices() const {
  std::lock_guard<std::mutex> lock(mutex_);
  std::vector<ManagedDevice> out;
  out.reserve(devices_.size());
  for (const auto& device : devices_) out.push_back(device->info);
  return out;
}

std::shared_ptr<HidDeviceChannel> DeviceManager::channel(int id) const {
  std::lock_guard<std::mutex> lock(mutex_);
  if (id < 0 || static_cast<size_t>(id) >= devices_.size()) return nullptr;
  return devices_[static_cast<size_t>(id)]->channel;
}

bool DeviceManager::setLed(int id, bool on) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (id < 0 || static_cast<size_t>(id) >= devices_.size() ||
        !devices_[static_cast<size_t>(id)]->info.hasLed)
      return false;
    ledRequests_.push_back({id, on});
  }
  wake_.notify_all();
  return true;
}

std::string DeviceManager::startError() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return startError_;
}

double DeviceManager::now() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - startTime_).count();
}

void DeviceManager::run() {
  if (makeTransport_) {
    try {
      ownedTransport_ = makeTransport_();
      transport_ = ownedTransport_.get();
    } catch (const std::exception& error) {
      std::lock_guard<std::mutex> lock(mutex_);
      startError_ = error.what();
    }
    if (transport_ == nullptr) {
      std::lock_guard<std::mutex> lock(mutex_);
      if (startError_.empty()) startError_ = "no transport";
      return;
    }
  }
  using Clock = std::chrono::steady_clock;
  Clock::time_point nextPoll = Clock::now();
  for (;;) {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (stopping_) break;
    }
    if (Clock::now() >= nextPoll) {
      poll();
      nextPoll = Clock::now() + options_.pollPeriod;
      ++polls_;
    }
    sendOutputs();
    bool anyOpen = false;
    for (const auto& device : devices_) {
      if (!device->connection) continue;
      anyOpen = true;
      serviceDevice(*device);
    }
    if (!anyOpen) {
      // Nothing to read: sleep until the next poll, an LED request or the end.
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait_until(lock, nextPoll, [this] { return stopping_ || !ledRequests_.empty(); });
    }
  }
  for (const auto& device : devices_)
    if (device->connection) markUnplugged(*device, "device manager stopped");
  ownedTransport_.reset();
}

void DeviceManager::poll() {
  std::vector<std::pair<HidDeviceInfo, ProfileMatch>> wanted;
  const std::vector<HidDeviceInfo> listed = transport_->enumerate();
  for (const HidDeviceInfo& entry : listed) {
    const bool seen = std::any_of(wanted.begin(), wanted.end(),
                                  [&](const auto& kept) { return kept.first.path == entry.path; });
    if (seen) continue;
    if (std::optional<ProfileMatch> match = matchProfile(entry, options_.profiles))
      wanted.emplace_back(entry, std::move(*match));
  }
  // An open device that is no longer listed is gone, whatever its reads say.
  for (const auto& device : devices_) {
    if (!device->connection) continue;
    const bool present = std::any_of(listed.begin(), listed.end(), [&](const HidDeviceInfo& e) {
      return e.path == device->listed.path;
    });
    if (!present) markUnplugged(*device, "no longer listed");
  }
  for (const auto& [entry, match] : wanted) {
    Device* known = nullptr;
    for (const auto& device : devices_)
      if (device->listed.path == entry.path && device->sameDevice(entry)) known = device.get();
    if (known != nullptr && known->connection) continue;
    if (known == nullptr) {
      // The same device back under another path, if one is waiting for it.
      for (const auto& device : devices_) {
        if (device->connection || !device->sameDevice(entry)) continue;
        const bool pathListed = std::any_of(wanted.begin(), wanted.end(), [&](const auto& w) {
          return w.first.path == device->listed.path;
        });
        if (!pathListed) {
          known = device.get();
          break;
        }
      }
    }
    if (known != nullptr) {
      openDevice(*known, entry, match);
      continue;
    }
    // A new device is listed only once its first open has filled in what it is (and, when the
    // open failed, why). Only this thread adds devices, so the size is read without the lock.
    auto device = std::make_unique<Device>();
    device->info.id = static_cast<int>(devices_.size());
    device->info.vendorId = entry.vendorId;
    device->info.productId = entry.productId;
    openDevice(*device, entry, match);
    std::lock_guard<std::mutex> lock(mutex_);
    devices_.push_back(std::move(device));
  }
}

void DeviceManager::openDevice(Device& device, const HidDeviceInfo& listed,
                               const ProfileMatch& match) {
  if (!device.decoder || device.matchedProfile != match.profileName) {
    device.decoder = makeDecoder(match, options_.spaceMouse);
    device.matchedProfile = match.profileName;
  }
  device.listed = listed;
  const HidForceOutput* force = device.decoder->forceOutput();
  {
    // What the device is, known before it opens, so that a device that cannot be opened is
    // listed with its reason.
    std::lock_guard<std::mutex> lock(mutex_);
    ManagedDevice& info = device.info;
    info.path = listed.path;
    info.manufacturer = listed.manufacturer;
    info.profileName = device.decoder->profileName();
    info.model = !listed.product.empty()
                     ? listed.product
                     : info.profileName + " " + idText(listed.vendorId, listed.productId);
    info.hasLed = !device.decoder->ledReport(true).empty();
    info.hasForceOutput = force != nullptr;
    info.maxForce = force != nullptr ? force->maxForce : 0.0;
  }
  std::string error;
  std::unique_ptr<HidConnection> connection = transport_->open(listed.path, &error);
  if (!connection) {
    std::lock_guard<std::mutex> lock(mutex_);
    device.info.lastError = error.empty() ? "cannot open " + listed.path : error;
    return;
  }
  device.decoder->connect();
  device.connection = std::move(connection);
  // A force asked for while the device was away is not sent now: wait for a new request.
  device.forceSent = device.channel->force_.read().sequence;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    device.info.connected = true;
    device.info.lastError.clear();
  }
  publish(device);
}

void DeviceManager::serviceDevice(Device& device) {
  std::array<uint8_t, kReadBufferBytes> buffer{};
  bool decodedAny = false;
  for (int turn = 0; turn < kMaxReportsPerTurn; ++turn) {
    const int got = device.connection->read(buffer.data(), buffer.size(),
                                            turn == 0 ? options_.readTimeoutMs : 0);
    if (got == 0) break;
    if (got < 0) {
      const std::string why = device.connection->lastError();
      markUnplugged(device, why.empty() ? "read failed" : why);
      return;
    }
    device.decoder->decode(std::span<const uint8_t>(buffer.data(), static_cast<size_t>(got)),
                           now());
    decodedAny = true;
  }
  if (decodedAny) publish(device);

  const HidForceOutput* force = device.decoder->forceOutput();
  if (force == nullptr) return;
  const HidDeviceChannel::ForceCommand& command = device.channel->force_.read();
  if (command.sequence == device.forceSent) return;
  device.forceSent = command.sequence;
  const std::vector<uint8_t> report = buildForceReport(
      *force, Eigen::Vector3d(command.forceN[0], command.forceN[1], command.forceN[2]));
  const bool sent = device.connection->write(report.data(), report.size()) >= 0;
  std::lock_guard<std::mutex> lock(mutex_);
  ++(sent ? device.info.outputsSent : device.info.outputsFailed);
}

void DeviceManager::sendOutputs() {
  std::vector<LedRequest> requests;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    requests.swap(ledRequests_);
  }
  for (const LedRequest& request : requests) {
    Device& device = *devices_[static_cast<size_t>(request.id)];
    if (!device.connection) continue;  // an LED switched while unplugged is dropped
    const std::vector<uint8_t> report = device.decoder->ledReport(request.on);
    const bool sent = device.connection->write(report.data(), report.size()) >= 0;
    std::lock_guard<std::mutex> lock(mutex_);
    ++(sent ? device.info.outputsSent : device.info.outputsFailed);
  }
}

void DeviceManager::markUnplugged(Device& device, const std::string& why) {
  device.decoder->disconnect();
  publish(device);
  device.connection.reset();
  std::lock_guard<std::mutex> lock(mutex_);
  device.info.connected = false;
  device.info.lastError = why;
}

void DeviceManager::publish(Device& device) {
  const HidInputState& state = device.decoder->state();
  device.channel->state_.publish(state);
  std::lock_guard<std::mutex> lock(mutex_);
  device.info.counts = state.counts;
  device.info.profileName = device.decoder->profileName();
}

}  // namespace sculpt::haptics
