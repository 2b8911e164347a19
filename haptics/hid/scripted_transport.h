#pragma once
// A HidTransport driven by a test: devices are plugged in, unplugged and plugged in again on
// cue, each path reads a script of steps (a report, a timeout, a disconnect), writes can be made
// to fail, and every output and feature report sent is kept with the thread that sent it. All of
// it is thread-safe: a device-manager thread reads and writes while the test thread scripts and
// inspects. Nothing here sleeps on a schedule; a read with no step waits (up to its timeout)
// for one.

#include <cstdint>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "haptics/hid/hid_transport.h"

namespace sculpt::haptics {

struct ScriptedTransportState;  // the devices and scripts, shared with the connections

/// One step of a path's read script.
struct ScriptStep {
  enum class Kind : uint8_t {
    kReport,      ///< read returns these bytes (cut to the reader's buffer)
    kTimeout,     ///< read returns 0 at once
    kDisconnect,  ///< read returns -1 and the path is unplugged (see ScriptedTransport::unplug)
  };
  Kind kind = Kind::kReport;
  std::vector<uint8_t> bytes;

  static ScriptStep report(std::vector<uint8_t> bytes) { return {Kind::kReport, std::move(bytes)}; }
  static ScriptStep timeout() { return {Kind::kTimeout, {}}; }
  static ScriptStep disconnect() { return {Kind::kDisconnect, {}}; }
  /// `size` bytes of a fixed pseudo-random sequence chosen by `seed` (a report of noise).
  static ScriptStep garbage(size_t size, uint32_t seed);
};

/// An output or feature report a connection was asked to send.
struct SentReport {
  enum class Kind : uint8_t { kOutput, kFeature };
  std::string path;
  Kind kind = Kind::kOutput;
  std::vector<uint8_t> bytes;
  std::thread::id thread;
  bool failed = false;  ///< the call returned -1 (failWrites)
};

class ScriptedTransport : public HidTransport {
 public:
  ScriptedTransport();
  ~ScriptedTransport() override;

  /// Plugs in an interface. Adding a path again lists it again, as hidapi lists a path once per
  /// top-level usage.
  void addDevice(const HidDeviceInfo& device);
  /// Appends steps to the script of `path`, read in order by whichever connection is open.
  void script(const std::string& path, std::vector<ScriptStep> steps);
  void pushReport(const std::string& path, std::vector<uint8_t> bytes);
  /// Unplugs `path` now: enumerate stops listing it, opens fail, and the open connection's next
  /// read (or write) returns -1. The script's remaining steps wait for a replug.
  void unplug(const std::string& path);
  /// Plugs an unplugged path in again: listed and openable.
  void replug(const std::string& path);
  /// The next `count` output or feature reports sent to `path` fail.
  void failWrites(const std::string& path, int count);
  /// The next `count` opens of `path` fail with `message`.
  void failOpens(const std::string& path, int count, const std::string& message);
  /// What getFeatureReport returns for the report ID bytes[0].
  void setFeatureReport(const std::string& path, std::vector<uint8_t> bytes);

  std::vector<SentReport> sentReports() const;
  /// Each thread that called enumerate, open or any connection method, once.
  std::vector<std::thread::id> callingThreads() const;
  /// Script steps of `path` not yet read.
  size_t pendingSteps(const std::string& path) const;
  /// Successful opens of `path`.
  int openCount(const std::string& path) const;

  std::vector<HidDeviceInfo> enumerate() override;
  std::unique_ptr<HidConnection> open(const std::string& path, std::string* error) override;

 private:
  std::shared_ptr<ScriptedTransportState> state_;
};

}  // namespace sculpt::haptics
