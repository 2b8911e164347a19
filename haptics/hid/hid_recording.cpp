#include "haptics/hid/hid_recording.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <optional>
#include <sstream>
#include <system_error>

#include "io/file_error.h"

namespace sculpt::haptics {
namespace {

// The words of a line, split at spaces and tabs.
std::vector<std::string_view> words(std::string_view line) {
  std::vector<std::string_view> out;
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    const size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
    if (i > start) out.push_back(line.substr(start, i - start));
  }
  return out;
}

std::optional<uint32_t> hexNumber(std::string_view word, uint32_t max) {
  uint32_t value = 0;
  if (word.empty() || word.size() > 8) return std::nullopt;
  const auto [end, ec] = std::from_chars(word.data(), word.data() + word.size(), value, 16);
  if (ec != std::errc() || end != word.data() + word.size() || value > max) return std::nullopt;
  return value;
}

std::optional<size_t> decimalSize(std::string_view word) {
  size_t value = 0;
  const auto [end, ec] = std::from_chars(word.data(), word.data() + word.size(), value);
  if (ec != std::errc() || end != word.data() + word.size()) return std::nullopt;
  return value;
}

// "<digits>[.<digits>]", at most 12 digits before the point.
std::optional<double> timestamp(std::string_view word) {
  const size_t dot = word.find('.');
  const std::string_view whole = word.substr(0, dot);
  const std::string_view fraction = dot == std::string_view::npos ? "" : word.substr(dot + 1);
  const auto digits = [](std::string_view part) {
    for (char c : part)
      if (c < '0' || c > '9') return false;
    return true;
  };
  if (whole.empty() || whole.size() > 12 || !digits(whole) || !digits(fraction) ||
      (dot != std::string_view::npos && fraction.empty()))
    return std::nullopt;
  double value = 0;
  const auto [end, ec] = std::from_chars(word.data(), word.data() + word.size(), value);
  if (ec != std::errc() || end != word.data() + word.size()) return std::nullopt;
  return value;
}

class LineParser {
 public:
  LineParser(const std::string& source, size_t lineNumber)
      : source_(source), lineNumber_(lineNumber) {}

  [[noreturn]] void fail(const std::string& problem) const {
    throw FileError(source_ + ": line " + std::to_string(lineNumber_) + ": " + problem);
  }

  // `count` (already checked against `limit`) bytes from words[first...]; `what` names the line.
  std::vector<uint8_t> bytes(const std::vector<std::string_view>& line, size_t first, size_t count,
                             const char* what) const {
    const size_t given = line.size() - first;
    if (given != count)
      fail(std::string(what) + " size " + std::to_string(count) + " disagrees with the " +
           std::to_string(given) + " bytes given");
    std::vector<uint8_t> out;
    out.reserve(count);
    for (size_t i = first; i < line.size(); ++i) {
      const std::optional<uint32_t> byte =
          line[i].size() == 2 ? hexNumber(line[i], 0xFF) : std::nullopt;
      if (!byte)
        fail(std::string(what) + " byte '" + std::string(line[i]) + "' is not two hex digits");
      out.push_back(static_cast<uint8_t>(*byte));
    }
    return out;
  }

  size_t size(std::string_view word, size_t limit, const char* what) const {
    const std::optional<size_t> value = decimalSize(word);
    if (!value) fail(std::string(what) + " size '" + std::string(word) + "' is not a number");
    if (*value > limit)
      fail(std::string(what) + " size " + std::string(word) + " is over the limit of " +
           std::to_string(limit) + " bytes");
    return *value;
  }

 private:
  const std::string& source_;
  size_t lineNumber_;
};

}  // namespace

HidRecording parseHidRecording(std::string_view text, const std::string& source) {
  HidRecording recording;
  bool haveName = false, haveIds = false, haveDescriptor = false;
  size_t lineNumber = 0;
  size_t start = 0;
  while (start < text.size()) {
    size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(start, end - start);
    start = end + 1;
    ++lineNumber;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    const LineParser parse(source, lineNumber);
    const std::vector<std::string_view> parts = words(line);
    if (parts.empty() || parts[0][0] == '#') continue;
    const std::string_view tag = parts[0];

    if (tag == "N:") {
      if (haveName) parse.fail("a second N: line (one device per recording)");
      const size_t at = line.find("N:") + 2;
      const size_t first = line.find_first_not_of(" \t", at);
      recording.name = first == std::string_view::npos ? "" : std::string(line.substr(first));
      haveName = true;
    } else if (tag == "I:") {
      if (haveIds) parse.fail("a second I: line (one device per recording)");
      if (parts.size() != 4) parse.fail("I: needs a bus, a vendor ID and a product ID in hex");
      const auto bus = hexNumber(parts[1], 0xFFFF), vid = hexNumber(parts[2], 0xFFFF),
                 pid = hexNumber(parts[3], 0xFFFF);
      if (!bus || !vid || !pid) parse.fail("I: values must be hexadecimal numbers up to ffff");
      recording.bus = static_cast<uint16_t>(*bus);
      recording.vendorId = static_cast<uint16_t>(*vid);
      recording.productId = static_cast<uint16_t>(*pid);
      haveIds = true;
    } else if (tag == "P:") {
      // The physical path says where the device was plugged in; nothing to decode.
    } else if (tag == "D:") {
      if (parts.size() != 2 || parts[1] != "0")
        parse.fail("only single-device recordings (D: 0) are supported");
    } else if (tag == "R:") {
      if (haveDescriptor) parse.fail("a second R: line (one device per recording)");
      if (parts.size() < 2) parse.fail("R: needs the descriptor length");
      const size_t count = parse.size(parts[1], kMaxRecordedDescriptorBytes, "R:");
      recording.descriptor = parse.bytes(parts, 2, count, "R:");
      haveDescriptor = true;
    } else if (tag == "E:") {
      if (parts.size() < 3) parse.fail("E: needs a time, a size and the report bytes");
      const std::optional<double> time = timestamp(parts[1]);
      if (!time) parse.fail("E: time '" + std::string(parts[1]) + "' is not <seconds>.<micros>");
      if (!recording.events.empty() && *time < recording.events.back().time)
        parse.fail("E: time " + std::string(parts[1]) + " is before the previous event's");
      const size_t count = parse.size(parts[2], kMaxRecordedReportBytes, "E:");
      if (count == 0) parse.fail("E: a report has at least one byte");
      recording.events.push_back({*time, parse.bytes(parts, 3, count, "E:")});
    } else {
      const std::string shown(tag.substr(0, 16));
      parse.fail("unknown line '" + shown + "' (expected N:, I:, P:, R:, D:, E: or #)");
    }
  }
  if (!haveIds) throw FileError(source + ": no I: line (bus, vendor and product IDs)");
  return recording;
}

HidRecording loadHidRecording(const std::filesystem::path& path) {
  const std::string name = path.string();
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error))
    throw FileError(name + ": not a readable file");
  const uintmax_t size = std::filesystem::file_size(path, error);
  if (error) throw FileError(name + ": cannot read its size (" + error.message() + ")");
  if (size > kMaxRecordingFileBytes)
    throw FileError(name + ": " + std::to_string(size) + " bytes is over the limit of " +
                    std::to_string(kMaxRecordingFileBytes) + " for a recording");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw FileError(name + ": cannot open it");
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  if (in.bad()) throw FileError(name + ": read failed");
  return parseHidRecording(text, name);
}

std::string formatHidRecording(const HidRecording& recording) {
  std::ostringstream out;
  const auto hexBytes = [&out](const std::vector<uint8_t>& bytes) {
    char byte[4];
    for (uint8_t b : bytes) {
      std::snprintf(byte, sizeof byte, " %02x", b);
      out << byte;
    }
  };
  char line[64];
  out << "N: " << recording.name << '\n';
  std::snprintf(line, sizeof line, "I: %x %04x %04x\n", recording.bus, recording.vendorId,
                recording.productId);
  out << line;
  out << "R: " << recording.descriptor.size();
  hexBytes(recording.descriptor);
  out << '\n';
  for (const HidRecordedEvent& event : recording.events) {
    const auto micros = static_cast<long long>(std::llround(std::max(0.0, event.time) * 1e6));
    std::snprintf(line, sizeof line, "E: %06lld.%06lld %zu", micros / 1000000, micros % 1000000,
                  event.bytes.size());
    out << line;
    hexBytes(event.bytes);
    out << '\n';
  }
  return out.str();
}

void writeHidRecording(const std::filesystem::path& path, const HidRecording& recording) {
  std::ofstream out(path, std::ios::binary);
  out << formatHidRecording(recording);
  out.close();
  if (!out) throw FileError(path.string() + ": cannot write the recording");
}

HidUsage topLevelUsage(const std::vector<uint8_t>& descriptor) {
  // Short items: a prefix byte (tag in bits 7-4, type in bits 3-2, data size 0/1/2/4 in bits
  // 1-0) and its data, little-endian. Long items (prefix 0xFE) carry their size in the next byte.
  HidUsage found;
  size_t i = 0;
  while (i < descriptor.size()) {
    const uint8_t prefix = descriptor[i];
    if (prefix == 0xFE) {
      if (i + 1 >= descriptor.size()) return {};
      i += 3 + size_t{descriptor[i + 1]};
      continue;
    }
    const size_t size = (prefix & 3) == 3 ? 4 : (prefix & 3);
    if (i + 1 + size > descriptor.size()) return {};
    uint32_t data = 0;
    for (size_t k = 0; k < size; ++k) data |= uint32_t{descriptor[i + 1 + k]} << (8 * k);
    const uint8_t item = prefix & 0xFC;
    if (item == 0x04) found.page = static_cast<uint16_t>(data);  // Usage Page (global)
    if (item == 0x08) {                                          // Usage (local)
      if (size == 4) found.page = static_cast<uint16_t>(data >> 16);
      found.usage = static_cast<uint16_t>(data);
    }
    if (item == 0xA0) return found;  // Collection: the first one is the top level
    i += 1 + size;
  }
  return {};
}

}  // namespace sculpt::haptics
