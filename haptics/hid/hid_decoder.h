#pragma once
// Turning HID input reports into a device state: six normalised axes, a button mask and what
// else the device tells (battery). One decoder per device keeps the newest value of everything,
// because devices send their axes in several reports. The profile-driven decoder here is the one
// piece of code that reads axes and buttons out of reports; the SpaceMouse decoder
// (spacemouse.h) only chooses which built-in profile a report follows.
//
// Reports that cannot be decoded are ignored and counted, never trusted: shorter than the
// profile's fields (truncated), longer than the device's layout (over-long, for layouts that fix
// their length), or with a report ID the profile does not describe (unknown ID).

#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "haptics/hid/hid_profile.h"

namespace sculpt::haptics {

enum class ReportOutcome : uint8_t { kDecoded, kTruncated, kOverLong, kUnknownId };

struct HidReportCounts {
  uint64_t decoded = 0, truncated = 0, overLong = 0, unknownId = 0;
  uint64_t ignored() const { return truncated + overLong + unknownId; }
};

/// A device's newest decoded state. Small and trivially copyable: it is handed between threads
/// by value (util/triple_buffer.h).
struct HidInputState {
  bool connected = false;
  double time = 0.0;  ///< s, when the newest decoded report came (the decoder's caller's clock)
  std::array<double, 3> translation{};  ///< tx, ty, tz in [-1, 1]
  std::array<double, 3> rotation{};     ///< rx, ry, rz in [-1, 1]
  /// The device's own counts, before sign, scale or mapping, in the profile's axis order (for
  /// the SpaceMouse: X, Y, Z, RX, RY, RZ as they come in the reports). rawCount are used.
  std::array<int64_t, kAxisCount> raw{};
  size_t rawCount = 0;
  uint32_t buttons = 0;     ///< bit i: button i held
  int batteryPercent = -1;  ///< 0-100, -1 when the device has not said
  HidReportCounts counts;
};

/// counts * scale, clamped to [-1, 1], with the dead zone taken out and the rest stretched back
/// to full range: 0 when |v| <= deadZone, else sign(v) (|v| - deadZone) / (1 - deadZone).
double normaliseAxis(int64_t counts, double scale, double deadZone);

/// Reads the axes and buttons `profile` places in `report` into `state` (axes, raw counts,
/// buttons; nothing else is touched). Bytes past the last field are ignored. A button whose byte
/// is past the end of the report reads as released, but the report must reach every axis and the
/// first button byte of its report ID, else it is truncated.
ReportOutcome applyProfileReport(const HidProfile& profile, std::span<const uint8_t> report,
                                 HidInputState& state);

/// A decoder for one device: keeps its state and the counts of decoded and ignored reports.
class HidReportDecoder {
 public:
  virtual ~HidReportDecoder() = default;
  /// Decodes one input report that came at `time` (s). Never throws.
  ReportOutcome decode(std::span<const uint8_t> report, double time);
  const HidInputState& state() const { return state_; }
  /// Opened: connected, nothing held yet.
  void connect();
  /// Unplugged or closed: not connected, axes zero, no buttons, battery unknown; counts kept.
  void disconnect();
  /// The profile the device's reports follow ("spacemouse-separate", a user profile's name).
  virtual std::string profileName() const = 0;
  /// The output report that lights the device's LED, empty when it has none.
  virtual std::vector<uint8_t> ledReport(bool on) const;
  /// The force output the profile describes, if any.
  virtual const HidForceOutput* forceOutput() const { return nullptr; }

 protected:
  virtual ReportOutcome decodeReport(std::span<const uint8_t> report, HidInputState& state) = 0;

 private:
  HidInputState state_;
};

/// The decoder of a user profile.
class ProfileDecoder : public HidReportDecoder {
 public:
  explicit ProfileDecoder(HidProfile profile) : profile_(std::move(profile)) {}
  const HidProfile& profile() const { return profile_; }
  std::string profileName() const override { return profile_.name; }
  const HidForceOutput* forceOutput() const override {
    return profile_.forceOutput ? &*profile_.forceOutput : nullptr;
  }

 protected:
  ReportOutcome decodeReport(std::span<const uint8_t> report, HidInputState& state) override {
    return applyProfileReport(profile_, report, state);
  }

 private:
  HidProfile profile_;
};

}  // namespace sculpt::haptics
