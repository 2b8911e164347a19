#pragma once
// A recorded HID device in the text format of hid-recorder (hid-tools): its name, bus and IDs,
// report descriptor and the input reports it sent, with their times. Recordings let the decoders
// and the device manager be checked against what a device really sends, without the device.
//
// Lines we read (docs/hid-devices.md):
//   # comment            ignored, as are empty lines
//   N: <name>            the device's name
//   I: <bus> <vid> <pid> three hexadecimal numbers ("I: 3 046d c626")
//   P: <phys>            physical path, ignored
//   R: <n> <n bytes>     the report descriptor, n and then n hexadecimal bytes
//   D: 0                 the device index; only single-device recordings (index 0) are read
//   E: <s.us> <n> <bytes> one input report: time in seconds, its size n, then n hexadecimal bytes
// Parsing is strict: any other line, a size that disagrees with the bytes given, a size over
// the limits below, a time that goes backwards, or a second N:/I:/R: line is an error naming the
// line number (the whole file is rejected; no event is silently dropped or marked).

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace sculpt::haptics {

/// Largest report we accept in an E: line (the kernel's hidraw buffer size).
inline constexpr size_t kMaxRecordedReportBytes = 16384;
/// Largest report descriptor we accept in an R: line (the kernel's limit).
inline constexpr size_t kMaxRecordedDescriptorBytes = 4096;
/// Largest recording file we read.
inline constexpr uintmax_t kMaxRecordingFileBytes = 64u << 20;

struct HidRecordedEvent {
  double time = 0.0;           ///< s, from the recording's own clock
  std::vector<uint8_t> bytes;  ///< the report as read from hidraw (report ID first when numbered)
};

struct HidRecording {
  std::string name;
  uint16_t bus = 0, vendorId = 0, productId = 0;
  std::vector<uint8_t> descriptor;
  std::vector<HidRecordedEvent> events;
};

/// Parses recording text. Throws FileError "<source>: line <n>: <problem>".
HidRecording parseHidRecording(std::string_view text, const std::string& source);
/// Reads and parses a file. Throws FileError naming the file.
HidRecording loadHidRecording(const std::filesystem::path& path);

/// The recording as hid-recorder text (N:, I:, R:, then one E: line per event), which
/// parseHidRecording reads back to the same values (times to the microsecond).
std::string formatHidRecording(const HidRecording& recording);
/// Writes formatHidRecording's text to `path`. Throws FileError when it cannot.
void writeHidRecording(const std::filesystem::path& path, const HidRecording& recording);

/// The usage page and usage of the first top-level collection in a report descriptor, or 0 and
/// 0 when it opens none (or is malformed before the first collection).
struct HidUsage {
  uint16_t page = 0, usage = 0;
};
HidUsage topLevelUsage(const std::vector<uint8_t>& descriptor);

}  // namespace sculpt::haptics
