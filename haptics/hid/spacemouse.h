#pragma once
// The 3Dconnexion SpaceMouse family over HID: which vendor and product IDs are SpaceMice, their
// two report layouts as built-in profiles, and a decoder that picks the layout of each report by
// its length. No force: these are elastic 6-DOF rate controllers.
//
// Layouts (numbers are int16 little-endian; byte 0 is the report ID):
//   separate reports (older devices): report 1 = X, Y, Z at bytes 1, 3, 5 (7 bytes);
//                                     report 2 = RX, RY, RZ at bytes 1, 3, 5 (7 bytes)
//   combined report (newer devices):  report 1 = X, Y, Z, RX, RY, RZ at bytes 1..11 (13 bytes)
//   both: report 3 = button mask from byte 1 (1 to 4 bytes, least significant first);
//         report 0x17 = battery percent in byte 1 (wireless devices);
//         output report 4 = one byte, LED off (0) or on (1).
// The device's axes: X right, Y towards the user, Z down, rotations about them. The default
// table maps them onto our frame (x right, y up, z towards the user): tx = X, ty = -Z, tz = Y,
// rx = RX, ry = -RZ, rz = RY (docs/hid-devices.md).

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "haptics/hid/hid_decoder.h"
#include "haptics/hid/hid_profile.h"

namespace sculpt::haptics {

inline constexpr uint16_t kLogitechVendorId = 0x046d;
inline constexpr uint16_t k3DconnexionVendorId = 0x256f;

enum class SpaceMouseLayout : uint8_t {
  kSeparateReports,  ///< 7-byte report 1 (translation) and report 2 (rotation)
  kCombinedReport,   ///< one 13-byte report 1 with all six axes
};

/// Where one of the device's axes (X, Y, Z, RX, RY, RZ, in report order) goes, with its sign.
struct AxisAssignment {
  AxisTarget target = AxisTarget::kTx;
  int sign = 1;  ///< +1 or -1
};
using SpaceMouseAxisTable = std::array<AxisAssignment, kAxisCount>;

/// tx = X, ty = -Z, tz = Y, rx = RX, ry = -RZ, rz = RY.
SpaceMouseAxisTable defaultSpaceMouseAxes();

struct SpaceMouseOptions {
  double fullScale = 350.0;  ///< counts that read as 1 (the devices' logical range is about ±350)
  double deadZone = 0.03;    ///< fraction of full scale that reads as 0
  SpaceMouseAxisTable axes = defaultSpaceMouseAxes();
};

/// True for the known SpaceMouse IDs (docs/hid-devices.md lists them).
bool isSpaceMouse(uint16_t vendorId, uint16_t productId);
/// The layout the ID is documented to send; nullopt for IDs that are not SpaceMice. The decoder
/// still decides by the length of report 1.
std::optional<SpaceMouseLayout> documentedLayout(uint16_t vendorId, uint16_t productId);

/// A layout as a profile: the six axes in report order, 32 buttons of report 3.
HidProfile spaceMouseProfile(SpaceMouseLayout layout, const SpaceMouseOptions& options = {});
/// The built-in profile of a known SpaceMouse ID (its documented layout), else nullopt.
std::optional<HidProfile> profileFor(uint16_t vendorId, uint16_t productId,
                                     const SpaceMouseOptions& options = {});

/// Output report 4: {0x04, on ? 1 : 0}.
std::array<uint8_t, 2> spaceMouseLedReport(bool on);

/// Decodes either layout. Report 1 of 7 bytes follows the separate layout and of 13 bytes the
/// combined one; other lengths of report 1 are truncated (under 13) or over-long. Report 2 must be
/// 7 bytes, report 3 2 to 5 bytes; report 0x17 needs at least 2 (later bytes ignored; a value
/// over 100 reads as 100). Every other ID is unknown.
class SpaceMouseDecoder : public HidReportDecoder {
 public:
  /// `expected`: the layout to name before the first report 1 or 2 tells (documentedLayout).
  explicit SpaceMouseDecoder(const SpaceMouseOptions& options = {},
                             std::optional<SpaceMouseLayout> expected = std::nullopt);
  /// "spacemouse-separate" or "spacemouse-combined" ("spacemouse" while unknown).
  std::string profileName() const override;
  std::vector<uint8_t> ledReport(bool on) const override;
  /// The layout of the last report 1 or 2 decoded (the expected one before the first).
  std::optional<SpaceMouseLayout> layout() const { return layout_; }

 protected:
  ReportOutcome decodeReport(std::span<const uint8_t> report, HidInputState& state) override;

 private:
  HidProfile separate_, combined_;
  std::optional<SpaceMouseLayout> layout_;
};

}  // namespace sculpt::haptics
