#pragma once
// A description of where a HID device puts its axes and buttons in its input reports (and,
// optionally, where a force goes in an output report), so that any HID device can drive the
// sculpting tools without code. Users write profiles as JSON (docs/hid-devices.md); the built-in
// SpaceMouse layouts are profiles too (spacemouse.h), decoded by the same code (hid_decoder.h).
//
// Byte offsets count the report-ID byte as byte 0, so the first data byte of a numbered report
// is byte 1. Report ID 0 means a device without numbered reports: its input reports carry no ID
// byte, so their offsets start at 0; an output report still starts with the 0 ID byte.

#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace sculpt::haptics {

/// Longest report a profile may describe (a full-speed USB HID report).
inline constexpr size_t kMaxProfileReportBytes = 64;

/// The six decoded axes: translation x, y, z, then rotation about x, y, z (device frame of
/// haptic_device.h: x right, y up, z towards the user).
enum class AxisTarget : uint8_t { kTx = 0, kTy = 1, kTz = 2, kRx = 3, kRy = 4, kRz = 5 };
inline constexpr size_t kAxisCount = 6;
/// "tx" ... "rz".
const char* axisTargetName(AxisTarget target);

/// One little-endian number of an input report, normalised onto one axis.
struct HidAxisField {
  uint8_t reportId = 1;
  size_t byteOffset = 1;
  size_t size = 2;  ///< bytes: 1, 2 or 4
  bool isSigned = true;
  double scale = 1.0 / 350.0;  ///< normalised units per count; a negative scale inverts the axis
  double deadZone = 0.03;  ///< |normalised value| below this reads as 0 (fraction of full scale)
  AxisTarget target = AxisTarget::kTx;
};

/// One bit of an input report, read as one button.
struct HidButtonField {
  uint8_t reportId = 1;
  size_t byteOffset = 1;
  int bit = 0;     ///< 0 (least significant) to 7
  int button = 0;  ///< 0 to 31: bit `button` of the decoded button mask
};

enum class ForceAxis : uint8_t { kFx = 0, kFy = 1, kFz = 2 };

/// Where a force command goes: consecutive little-endian numbers of one output report.
struct HidForceOutput {
  uint8_t reportId = 1;
  size_t byteOffset = 1;  ///< of the first number; the next ones follow, `size` bytes apart
  size_t size = 2;
  bool isSigned = true;
  double countsPerNewton = 1.0;
  std::vector<ForceAxis> axes;  ///< which force component each number carries, in order
  double maxForce = 0.0;        ///< N, the device's continuous maximum; 0 when not given
};

struct HidProfile {
  std::string name;
  uint16_t vendorId = 0, productId = 0;
  /// Only the interface with this top-level usage is opened (when the transport reports usages).
  std::optional<uint16_t> usagePage, usage;
  std::vector<HidAxisField> axes;  ///< at most one per target; their order is the raw order
  std::vector<HidButtonField> buttons;
  std::optional<HidForceOutput> forceOutput;
};

/// Parses a profile. Throws FileError "<source>: <field>: <problem>" (one sentence).
HidProfile parseHidProfile(std::string_view jsonText, const std::string& source);
/// Reads and parses a profile file. Throws FileError naming the file.
HidProfile loadHidProfile(const std::filesystem::path& path);

/// The output report carrying `forceN` (N, device frame): the ID byte, zeros up to the first
/// number, then each listed component times countsPerNewton, rounded and clamped to the
/// number's range (a non-finite component sends 0).
std::vector<uint8_t> buildForceReport(const HidForceOutput& output, const Eigen::Vector3d& forceN);

}  // namespace sculpt::haptics
