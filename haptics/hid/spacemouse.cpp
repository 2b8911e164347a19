#include "haptics/hid/spacemouse.h"

#include <algorithm>

namespace sculpt::haptics {
namespace {

constexpr uint8_t kTranslationReport = 1;  // or all six axes in the combined layout
constexpr uint8_t kRotationReport = 2;
constexpr uint8_t kButtonReport = 3;
constexpr uint8_t kLedReport = 4;
constexpr uint8_t kBatteryReport = 0x17;
constexpr size_t kSeparateLength = 7, kCombinedLength = 13;
constexpr size_t kShortestButtonReport = 2, kLongestButtonReport = 5;
constexpr size_t kButtonBytes = 4;

struct KnownId {
  uint16_t vendorId, productId;
  SpaceMouseLayout layout;
};

constexpr KnownId kKnownIds[] = {
    {kLogitechVendorId, 0xc603, SpaceMouseLayout::kSeparateReports},
    {kLogitechVendorId, 0xc605, SpaceMouseLayout::kSeparateReports},
    {kLogitechVendorId, 0xc606, SpaceMouseLayout::kSeparateReports},
    {kLogitechVendorId, 0xc621, SpaceMouseLayout::kSeparateReports},
    {kLogitechVendorId, 0xc623, SpaceMouseLayout::kSeparateReports},
    {kLogitechVendorId, 0xc625, SpaceMouseLayout::kSeparateReports},
    {kLogitechVendorId, 0xc626, SpaceMouseLayout::kSeparateReports},
    {kLogitechVendorId, 0xc627, SpaceMouseLayout::kSeparateReports},
    {kLogitechVendorId, 0xc628, SpaceMouseLayout::kSeparateReports},
    {kLogitechVendorId, 0xc629, SpaceMouseLayout::kSeparateReports},
    {kLogitechVendorId, 0xc62b, SpaceMouseLayout::kSeparateReports},
    {kLogitechVendorId, 0xc640, SpaceMouseLayout::kSeparateReports},
    {k3DconnexionVendorId, 0xc62e, SpaceMouseLayout::kCombinedReport},
    {k3DconnexionVendorId, 0xc62f, SpaceMouseLayout::kCombinedReport},
    {k3DconnexionVendorId, 0xc631, SpaceMouseLayout::kCombinedReport},
    {k3DconnexionVendorId, 0xc632, SpaceMouseLayout::kCombinedReport},
    {k3DconnexionVendorId, 0xc633, SpaceMouseLayout::kCombinedReport},
    {k3DconnexionVendorId, 0xc638, SpaceMouseLayout::kCombinedReport},
    {k3DconnexionVendorId, 0xc63a, SpaceMouseLayout::kCombinedReport},
    {k3DconnexionVendorId, 0xc652, SpaceMouseLayout::kCombinedReport},
    {k3DconnexionVendorId, 0xc635, SpaceMouseLayout::kSeparateReports},
    {k3DconnexionVendorId, 0xc636, SpaceMouseLayout::kSeparateReports},
};

const char* layoutProfileName(SpaceMouseLayout layout) {
  return layout == SpaceMouseLayout::kSeparateReports ? "spacemouse-separate"
                                                      : "spacemouse-combined";
}

}  // namespace

SpaceMouseAxisTable defaultSpaceMouseAxes() {
  return {{{AxisTarget::kTx, 1},
           {AxisTarget::kTz, 1},
           {AxisTarget::kTy, -1},
           {AxisTarget::kRx, 1},
           {AxisTarget::kRz, 1},
           {AxisTarget::kRy, -1}}};
}

std::optional<SpaceMouseLayout> documentedLayout(uint16_t vendorId, uint16_t productId) {
  for (const KnownId& id : kKnownIds)
    if (id.vendorId == vendorId && id.productId == productId) return id.layout;
  return std::nullopt;
}

bool isSpaceMouse(uint16_t vendorId, uint16_t productId) {
  return documentedLayout(vendorId, productId).has_value();
}

HidProfile spaceMouseProfile(SpaceMouseLayout layout, const SpaceMouseOptions& options) {
  HidProfile profile;
  profile.name = layoutProfileName(layout);
  profile.usagePage = 0x01;
  profile.usage = 0x08;
  for (size_t i = 0; i < kAxisCount; ++i) {
    HidAxisField axis;
    const bool rotation = i >= 3;
    axis.reportId = layout == SpaceMouseLayout::kCombinedReport || !rotation ? kTranslationReport
                                                                             : kRotationReport;
    axis.byteOffset = 1 + 2 * (layout == SpaceMouseLayout::kCombinedReport ? i : i % 3);
    axis.size = 2;
    axis.isSigned = true;
    axis.scale = options.axes[i].sign / options.fullScale;
    axis.deadZone = options.deadZone;
    axis.target = options.axes[i].target;
    profile.axes.push_back(axis);
  }
  for (size_t byte = 0; byte < kButtonBytes; ++byte)
    for (int bit = 0; bit < 8; ++bit)
      profile.buttons.push_back({kButtonReport, 1 + byte, bit, static_cast<int>(8 * byte) + bit});
  return profile;
}

std::optional<HidProfile> profileFor(uint16_t vendorId, uint16_t productId,
                                     const SpaceMouseOptions& options) {
  const std::optional<SpaceMouseLayout> layout = documentedLayout(vendorId, productId);
  if (!layout) return std::nullopt;
  HidProfile profile = spaceMouseProfile(*layout, options);
  profile.vendorId = vendorId;
  profile.productId = productId;
  return profile;
}

std::array<uint8_t, 2> spaceMouseLedReport(bool on) {
  return {kLedReport, static_cast<uint8_t>(on ? 1 : 0)};
}

SpaceMouseDecoder::SpaceMouseDecoder(const SpaceMouseOptions& options,
                                     std::optional<SpaceMouseLayout> expected)
    : separate_(spaceMouseProfile(SpaceMouseLayout::kSeparateReports, options)),
      combined_(spaceMouseProfile(SpaceMouseLayout::kCombinedReport, options)),
      layout_(expected) {}

std::string SpaceMouseDecoder::profileName() const {
  return layout_ ? layoutProfileName(*layout_) : "spacemouse";
}

std::vector<uint8_t> SpaceMouseDecoder::ledReport(bool on) const {
  const std::array<uint8_t, 2> report = spaceMouseLedReport(on);
  return {report.begin(), report.end()};
}

ReportOutcome SpaceMouseDecoder::decodeReport(std::span<const uint8_t> report,
                                              HidInputState& state) {
  if (report.empty()) return ReportOutcome::kTruncated;
  const size_t length = report.size();
  switch (report[0]) {
    case kTranslationReport: {
      if (length != kSeparateLength && length != kCombinedLength)
        return length < kCombinedLength ? ReportOutcome::kTruncated : ReportOutcome::kOverLong;
      layout_ = length == kSeparateLength ? SpaceMouseLayout::kSeparateReports
                                          : SpaceMouseLayout::kCombinedReport;
      return applyProfileReport(length == kSeparateLength ? separate_ : combined_, report, state);
    }
    case kRotationReport:
      if (length != kSeparateLength)
        return length < kSeparateLength ? ReportOutcome::kTruncated : ReportOutcome::kOverLong;
      layout_ = SpaceMouseLayout::kSeparateReports;
      return applyProfileReport(separate_, report, state);
    case kButtonReport:
      if (length < kShortestButtonReport) return ReportOutcome::kTruncated;
      if (length > kLongestButtonReport) return ReportOutcome::kOverLong;
      return applyProfileReport(separate_, report, state);
    case kBatteryReport:
      if (length < 2) return ReportOutcome::kTruncated;
      state.batteryPercent = std::min<int>(report[1], 100);
      return ReportOutcome::kDecoded;
    default:
      return ReportOutcome::kUnknownId;
  }
}

}  // namespace sculpt::haptics
