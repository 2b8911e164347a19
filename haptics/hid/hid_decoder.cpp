#include "haptics/hid/hid_decoder.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace sculpt::haptics {
namespace {

// A little-endian number of `size` bytes at `offset` (the caller has checked it fits).
int64_t fieldValue(std::span<const uint8_t> report, size_t offset, size_t size, bool isSigned) {
  uint64_t value = 0;
  for (size_t k = 0; k < size; ++k) value |= uint64_t{report[offset + k]} << (8 * k);
  if (isSigned && size < 8 && (value >> (8 * size - 1)) != 0) value |= ~uint64_t{0} << (8 * size);
  return static_cast<int64_t>(value);
}

bool unnumbered(const HidProfile& profile) {
  // parseHidProfile does not let report ID 0 mix with numbered reports.
  if (!profile.axes.empty()) return profile.axes.front().reportId == 0;
  return !profile.buttons.empty() && profile.buttons.front().reportId == 0;
}

}  // namespace

double normaliseAxis(int64_t counts, double scale, double deadZone) {
  const double v = std::clamp(static_cast<double>(counts) * scale, -1.0, 1.0);
  const double magnitude = std::abs(v);
  if (magnitude <= deadZone) return 0.0;
  return std::copysign((magnitude - deadZone) / (1.0 - deadZone), v);
}

ReportOutcome applyProfileReport(const HidProfile& profile, std::span<const uint8_t> report,
                                 HidInputState& state) {
  if (report.empty()) return ReportOutcome::kTruncated;
  const uint8_t id = unnumbered(profile) ? 0 : report[0];

  // How long a report with this ID must be: every axis whole, and the first button byte.
  bool described = false;
  size_t needed = 0, firstButtonByte = SIZE_MAX;
  for (const HidAxisField& axis : profile.axes)
    if (axis.reportId == id) {
      described = true;
      needed = std::max(needed, axis.byteOffset + axis.size);
    }
  for (const HidButtonField& button : profile.buttons)
    if (button.reportId == id) {
      described = true;
      firstButtonByte = std::min(firstButtonByte, button.byteOffset);
    }
  if (!described) return ReportOutcome::kUnknownId;
  if (firstButtonByte != SIZE_MAX) needed = std::max(needed, firstButtonByte + 1);
  if (report.size() < needed) return ReportOutcome::kTruncated;

  state.rawCount = std::min(profile.axes.size(), kAxisCount);
  for (size_t i = 0; i < state.rawCount; ++i) {
    const HidAxisField& axis = profile.axes[i];
    if (axis.reportId != id) continue;
    const int64_t counts = fieldValue(report, axis.byteOffset, axis.size, axis.isSigned);
    state.raw[i] = counts;
    const auto target = static_cast<size_t>(axis.target);
    double& out = target < 3 ? state.translation[target] : state.rotation[target - 3];
    out = normaliseAxis(counts, axis.scale, axis.deadZone);
  }
  for (const HidButtonField& button : profile.buttons) {
    if (button.reportId != id) continue;
    const uint32_t mask = 1u << button.button;
    const bool held =
        button.byteOffset < report.size() && ((report[button.byteOffset] >> button.bit) & 1) != 0;
    state.buttons = held ? (state.buttons | mask) : (state.buttons & ~mask);
  }
  return ReportOutcome::kDecoded;
}

ReportOutcome HidReportDecoder::decode(std::span<const uint8_t> report, double time) {
  const ReportOutcome outcome = decodeReport(report, state_);
  switch (outcome) {
    case ReportOutcome::kDecoded:
      ++state_.counts.decoded;
      state_.time = time;
      break;
    case ReportOutcome::kTruncated:
      ++state_.counts.truncated;
      break;
    case ReportOutcome::kOverLong:
      ++state_.counts.overLong;
      break;
    case ReportOutcome::kUnknownId:
      ++state_.counts.unknownId;
      break;
  }
  return outcome;
}

void HidReportDecoder::connect() {
  disconnect();
  state_.connected = true;
}

void HidReportDecoder::disconnect() {
  const HidReportCounts counts = state_.counts;
  const double time = state_.time;
  state_ = HidInputState{};
  state_.counts = counts;
  state_.time = time;
}

std::vector<uint8_t> HidReportDecoder::ledReport(bool) const { return {}; }

}  // namespace sculpt::haptics
