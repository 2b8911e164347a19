#pragma once
// The thread that owns every HID call: it polls the transport's device list (hidapi 0.13.1 has
// no hot-plug notice), opens the devices it has a profile for, reads them all round robin with
// a short timeout, decodes their reports and publishes each device's newest state through a
// triple buffer, so that readers (the servo) never wait. Output (LED, force) is asked for from
// any thread and sent by this one: no other thread ever calls the transport.
//
// A read that fails means unplugged: the device's state turns disconnected at once (zero axes,
// no buttons) and the device is opened again when it is listed again. A device keeps its id
// across unplugging, even when it comes back under another path (same vendor, product and serial).

#include <Eigen/Core>
#include <array>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <span>
#include <string>
#include <thread>
#include <vector>

#include "haptics/hid/hid_decoder.h"
#include "haptics/hid/hid_transport.h"
#include "haptics/hid/spacemouse.h"
#include "util/triple_buffer.h"

namespace sculpt::haptics {

struct DeviceManagerOptions {
  std::chrono::milliseconds pollPeriod{1500};  ///< how often the device list is read
  int readTimeoutMs = 2;                       ///< each device's read waits at most this long
  SpaceMouseOptions spaceMouse;
  /// User profiles; one matching a device's vendor and product ID wins over the built-in ones.
  std::vector<HidProfile> profiles;
};

/// What the manager knows of one device (a copy, taken under its lock).
struct ManagedDevice {
  int id = -1;        ///< stable for the manager's lifetime, 0, 1, 2, ...
  std::string model;  ///< the device's product string, else "<profile> <vid>:<pid>"
  std::string manufacturer;
  std::string path;  ///< where it was last seen
  std::string profileName;
  uint16_t vendorId = 0, productId = 0;
  bool connected = false;
  std::string lastError;   ///< why it is not connected ("" when it is)
  HidReportCounts counts;  ///< reports decoded and ignored since it was first opened
  uint64_t outputsSent = 0, outputsFailed = 0;
  bool hasLed = false;
  bool hasForceOutput = false;
  double maxForce = 0.0;  ///< N, from the profile's force output (0: unknown)
};

/// The wait-free hand-over for one device: one reader thread takes the newest state, one writer
/// thread asks for forces; the manager thread publishes the state and sends the forces.
class HidDeviceChannel {
 public:
  /// Reader thread: the newest state (disconnected before the first).
  const HidInputState& read() { return state_.read(); }
  /// Force writer thread: the force (N, device frame) to send from now on. Only the newest
  /// request is sent; ignored when the device's profile has no force output.
  void requestForce(const Eigen::Vector3d& forceN);

 private:
  friend class DeviceManager;
  struct ForceCommand {
    uint64_t sequence = 0;  // 0: none asked for yet
    std::array<double, 3> forceN{};
  };
  TripleBuffer<HidInputState> state_;
  TripleBuffer<ForceCommand> force_;
  uint64_t forceRequests_ = 0;  // the force writer's own count
};

/// The profile that decodes a device, if any: a user profile matching its IDs (and its usage,
/// when the profile names one and the transport reports usages), else the built-in SpaceMouse
/// profile for a known ID on its multi-axis controller collection (usage page 0x01, usage 0x08)
/// or on an interface whose usage the transport does not report.
struct ProfileMatch {
  std::string profileName;
  const HidProfile* userProfile = nullptr;           ///< points into the given list
  std::optional<SpaceMouseLayout> spaceMouseLayout;  ///< set for a built-in match
};
std::optional<ProfileMatch> matchProfile(const HidDeviceInfo& device,
                                         std::span<const HidProfile> userProfiles);
/// The decoder for a match.
std::unique_ptr<HidReportDecoder> makeDecoder(const ProfileMatch& match,
                                              const SpaceMouseOptions& options);

class DeviceManager {
 public:
  using TransportFactory = std::function<std::unique_ptr<HidTransport>()>;

  /// Starts the thread over `transport`, which from now on only that thread calls; it must
  /// outlive the manager.
  explicit DeviceManager(HidTransport& transport, DeviceManagerOptions options = {});
  /// Starts the thread, which makes its own transport (so that hidapi is initialised on the
  /// thread that uses it). A factory that throws leaves the manager with no devices and
  /// startError() set.
  explicit DeviceManager(TransportFactory makeTransport, DeviceManagerOptions options = {});
  /// Stops the thread; every device is closed and published as disconnected.
  ~DeviceManager();
  DeviceManager(const DeviceManager&) = delete;
  DeviceManager& operator=(const DeviceManager&) = delete;

  /// Every device seen so far, by id.
  std::vector<ManagedDevice> devices() const;
  /// The device's state hand-over (null for an unknown id). It outlives the manager (then
  /// showing the device disconnected). One reader and one force writer per channel.
  std::shared_ptr<HidDeviceChannel> channel(int id) const;
  /// Asks for the device's LED to be switched; false when the device has no LED.
  bool setLed(int id, bool on);

  /// Device-list polls completed so far.
  uint64_t pollCount() const { return polls_.load(); }
  /// The manager thread, the only one that calls the transport.
  std::thread::id threadId() const { return threadId_; }
  /// Why the transport could not be made ("" when it was).
  std::string startError() const;

 private:
  struct Device;

  void start();
  void run();
  void poll();
  void openDevice(Device& device, const HidDeviceInfo& listed, const ProfileMatch& match);
  void serviceDevice(Device& device);
  void sendOutputs();
  void markUnplugged(Device& device, const std::string& why);
  void publish(Device& device);
  double now() const;

  DeviceManagerOptions options_;
  TransportFactory makeTransport_;
  std::unique_ptr<HidTransport> ownedTransport_;
  HidTransport* transport_ = nullptr;
  std::chrono::steady_clock::time_point startTime_;

  mutable std::mutex mutex_;  // guards devices_ (the list and each ManagedDevice), the queue below,
                              // stopping_ and startError_
  std::condition_variable wake_;
  std::vector<std::unique_ptr<Device>> devices_;
  struct LedRequest {
    int id;
    bool on;
  };
  std::vector<LedRequest> ledRequests_;
  bool stopping_ = false;
  std::string startError_;

  std::atomic<uint64_t> polls_{0};
  std::thread::id threadId_;
  std::thread thread_;
};

}  // namespace sculpt::haptics
