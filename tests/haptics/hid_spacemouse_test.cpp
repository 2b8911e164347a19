// The SpaceMouse decoder against a genuine SpaceNavigator report and against reports composed
// here, byte by byte, from the two documented layouts; the expected axes come from the
// documented axis table and normalisation written out in this file.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <initializer_list>
#include <random>
#include <regex>
#include <string>
#include <vector>

#include "haptics/hid/spacemouse.h"

namespace sculpt::haptics {
namespace {

using Bytes = std::vector<uint8_t>;

void appendInt16(Bytes& bytes, int value) {
  const auto bits = static_cast<uint16_t>(static_cast<int16_t>(value));
  bytes.push_back(static_cast<uint8_t>(bits & 0xFF));
  bytes.push_back(static_cast<uint8_t>(bits >> 8));
}

Bytes report(uint8_t id, std::initializer_list<int> values) {
  Bytes bytes{id};
  for (int v : values) appendInt16(bytes, v);
  return bytes;
}

// The documented normalisation at the defaults: counts / 350, clamped, 0.03 dead zone taken out.
double expectedAxis(int counts) {
  const double v = std::clamp(counts / 350.0, -1.0, 1.0);
  if (std::abs(v) <= 0.03) return 0.0;
  return (v > 0 ? 1 : -1) * (std::abs(v) - 0.03) / 0.97;
}

TEST(SpaceMouseDecoder, GenuineSpaceNavigatorReport) {
  SpaceMouseDecoder decoder;
  const Bytes genuine{0x01, 0x76, 0x00, 0x00, 0x00, 0xFA, 0xFF};
  ASSERT_EQ(decoder.decode(genuine, 0.5), ReportOutcome::kDecoded);
  const HidInputState& s = decoder.state();
  ASSERT_EQ(s.rawCount, 6u);
  EXPECT_EQ(s.raw[0], 118);  // X
  EXPECT_EQ(s.raw[1], 0);    // Y
  EXPECT_EQ(s.raw[2], -6);   // Z
  // tx = X: (118/350 - 0.03) / 0.97; ty = -Z = 6 counts, inside the dead zone; tz = Y = 0.
  EXPECT_NEAR(s.translation[0], 0.3166421206, 1e-9);
  EXPECT_EQ(s.translation[1], 0.0);
  EXPECT_EQ(s.translation[2], 0.0);
  EXPECT_EQ(s.rotation, (std::array<double, 3>{0, 0, 0}));
  EXPECT_EQ(s.time, 0.5);
  EXPECT_EQ(s.counts.decoded, 1u);
  EXPECT_EQ(decoder.layout(), SpaceMouseLayout::kSeparateReports);
  EXPECT_EQ(decoder.profileName(), "spacemouse-separate");
}

TEST(SpaceMouseDecoder, NormalisationAtKnownCounts) {
  // Hand-computed: 350 counts is full scale, 10 counts (0.0286) is inside the 0.03 dead zone,
  // 11 counts is (11/350 - 0.03) / 0.97 = 0.0014727..., beyond full scale clamps.
  const struct {
    int counts;
    double tx;
  } cases[] = {{0, 0.0},       {10, 0.0},    {-10, 0.0},         {11, 0.00147275405},
               {350, 1.0},     {-350, -1.0}, {175, 0.48453608},  {32767, 1.0},
               {-32768, -1.0}, {700, 1.0},   {-118, -0.31664212}};
  for (const auto& c : cases) {
    SCOPED_TRACE(c.counts);
    SpaceMouseDecoder decoder;
    ASSERT_EQ(decoder.decode(report(1, {c.counts, 0, 0}), 0), ReportOutcome::kDecoded);
    EXPECT_NEAR(decoder.state().translation[0], c.tx, 1e-8);
  }
}

struct AxisCase {
  std::array<int, 6> counts;  // X, Y, Z, RX, RY, RZ as the device sends them
};

class SpaceMouseLayouts : public ::testing::TestWithParam<SpaceMouseLayout> {};

TEST_P(SpaceMouseLayouts, AxesFromBuiltReportsFollowTheDefaultTable) {
  const AxisCase cases[] = {
      {{0, 0, 0, 0, 0, 0}},
      {{118, 0, -6, 0, 0, 0}},
      {{1, 2, 3, 4, 5, 6}},
      {{-32768, 32767, -1, 1, 350, -350}},
      {{200, -200, 100, -100, 50, -50}},
      {{-340, 341, -342, 343, -344, 345}},
  };
  for (const AxisCase& c : cases) {
    const auto& v = c.counts;
    SCOPED_TRACE(::testing::PrintToString(v));
    SpaceMouseDecoder decoder;
    if (GetParam() == SpaceMouseLayout::kSeparateReports) {
      ASSERT_EQ(decoder.decode(report(1, {v[0], v[1], v[2]}), 0), ReportOutcome::kDecoded);
      ASSERT_EQ(decoder.decode(report(2, {v[3], v[4], v[5]}), 0), ReportOutcome::kDecoded);
    } else {
      ASSERT_EQ(decoder.decode(report(1, {v[0], v[1], v[2], v[3], v[4], v[5]}), 0),
                ReportOutcome::kDecoded);
    }
    EXPECT_EQ(decoder.layout(), GetParam());
    const HidInputState& s = decoder.state();
    ASSERT_EQ(s.rawCount, 6u);
    for (size_t i = 0; i < 6; ++i) EXPECT_EQ(s.raw[i], v[i]) << "raw " << i;
    // tx = X, ty = -Z, tz = Y, rx = RX, ry = -RZ, rz = RY.
    EXPECT_DOUBLE_EQ(s.translation[0], expectedAxis(v[0]));
    EXPECT_DOUBLE_EQ(s.translation[1], expectedAxis(-v[2]));
    EXPECT_DOUBLE_EQ(s.translation[2], expectedAxis(v[1]));
    EXPECT_DOUBLE_EQ(s.rotation[0], expectedAxis(v[3]));
    EXPECT_DOUBLE_EQ(s.rotation[1], expectedAxis(-v[5]));
    EXPECT_DOUBLE_EQ(s.rotation[2], expectedAxis(v[4]));
    for (double a : s.translation) EXPECT_LE(std::abs(a), 1.0);
    for (double a : s.rotation) EXPECT_LE(std::abs(a), 1.0);
  }
}

INSTANTIATE_TEST_SUITE_P(BothLayouts, SpaceMouseLayouts,
                         ::testing::Values(SpaceMouseLayout::kSeparateReports,
                                           SpaceMouseLayout::kCombinedReport));

TEST(SpaceMouseDecoder, LayoutIsChosenByTheLengthOfReportOne) {
  // A 256f device documented as combined still decodes a 7-byte report 1 as translation only.
  SpaceMouseDecoder decoder({}, documentedLayout(0x256f, 0xc62e));
  EXPECT_EQ(decoder.profileName(), "spacemouse-combined");
  ASSERT_EQ(decoder.decode(report(1, {350, 0, 0}), 0), ReportOutcome::kDecoded);
  EXPECT_EQ(decoder.layout(), SpaceMouseLayout::kSeparateReports);
  EXPECT_EQ(decoder.state().translation[0], 1.0);
  ASSERT_EQ(decoder.decode(report(1, {0, 0, 0, 350, 0, 0}), 0), ReportOutcome::kDecoded);
  EXPECT_EQ(decoder.layout(), SpaceMouseLayout::kCombinedReport);
  EXPECT_EQ(decoder.state().translation[0], 0.0);
  EXPECT_EQ(decoder.state().rotation[0], 1.0);
}

TEST(SpaceMouseDecoder, ButtonMasksFromOneToFourBytes) {
  const struct {
    Bytes bytes;
    uint32_t mask;
  } cases[] = {
      {{0x03, 0x00}, 0x0},
      {{0x03, 0x01}, 0x1},
      {{0x03, 0x02, 0x00}, 0x2},
      {{0x03, 0x03, 0x00}, 0x3},
      {{0x03, 0x00, 0x01}, 0x100},
      {{0x03, 0x81, 0x00, 0x40}, 0x400081},
      {{0x03, 0x01, 0x00, 0x00, 0x80}, 0x80000001},
      {{0x03, 0xFF, 0xFF, 0xFF, 0xFF}, 0xFFFFFFFF},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(::testing::PrintToString(c.bytes));
    SpaceMouseDecoder decoder;
    ASSERT_EQ(decoder.decode(c.bytes, 0), ReportOutcome::kDecoded);
    EXPECT_EQ(decoder.state().buttons, c.mask);
  }
  // A shorter report after a longer one: the bytes it does not carry read as released.
  SpaceMouseDecoder decoder;
  ASSERT_EQ(decoder.decode(Bytes{0x03, 0x01, 0x00, 0x00, 0x80}, 0), ReportOutcome::kDecoded);
  ASSERT_EQ(decoder.decode(Bytes{0x03, 0x02}, 0), ReportOutcome::kDecoded);
  EXPECT_EQ(decoder.state().buttons, 0x2u);
}

TEST(SpaceMouseDecoder, ButtonsAndAxesAreKeptAcrossReports) {
  SpaceMouseDecoder decoder;
  ASSERT_EQ(decoder.decode(Bytes{0x03, 0x01, 0x00}, 0), ReportOutcome::kDecoded);
  ASSERT_EQ(decoder.decode(report(1, {350, 0, 0}), 0), ReportOutcome::kDecoded);
  ASSERT_EQ(decoder.decode(report(2, {0, 0, -350}), 0), ReportOutcome::kDecoded);
  EXPECT_EQ(decoder.state().buttons, 0x1u);
  EXPECT_EQ(decoder.state().translation[0], 1.0);
  EXPECT_EQ(decoder.state().rotation[1], 1.0);  // ry = -RZ
}

TEST(SpaceMouseDecoder, BatteryPercent) {
  const struct {
    Bytes bytes;
    int percent;
  } cases[] = {{{0x17, 0x00}, 0},
               {{0x17, 0x2A}, 42},
               {{0x17, 0x64}, 100},
               {{0x17, 0xFF}, 100},
               {{0x17, 0x32, 0x00, 0x00}, 50}};
  for (const auto& c : cases) {
    SpaceMouseDecoder decoder;
    EXPECT_EQ(decoder.state().batteryPercent, -1);
    ASSERT_EQ(decoder.decode(c.bytes, 0), ReportOutcome::kDecoded);
    EXPECT_EQ(decoder.state().batteryPercent, c.percent);
  }
}

TEST(SpaceMouseDecoder, LedOutputReport) {
  EXPECT_EQ(spaceMouseLedReport(true), (std::array<uint8_t, 2>{0x04, 0x01}));
  EXPECT_EQ(spaceMouseLedReport(false), (std::array<uint8_t, 2>{0x04, 0x00}));
  const SpaceMouseDecoder decoder;
  EXPECT_EQ(decoder.ledReport(true), (Bytes{0x04, 0x01}));
  EXPECT_EQ(decoder.ledReport(false), (Bytes{0x04, 0x00}));
}

TEST(SpaceMouseDecoder, TruncatedOverLongAndUnknownReportsAreIgnoredAndCounted) {
  const struct {
    Bytes bytes;
    ReportOutcome outcome;
  } cases[] = {
      {{}, ReportOutcome::kTruncated},
      {{0x01}, ReportOutcome::kTruncated},
      {{0x01, 0x76, 0x00, 0x00, 0x00, 0xFA}, ReportOutcome::kTruncated},
      {{0x01, 1, 2, 3, 4, 5, 6, 7, 8}, ReportOutcome::kTruncated},  // 9 bytes: neither layout
      {Bytes(14, 0x01), ReportOutcome::kOverLong},                  // over 13
      {{0x02, 1, 2, 3, 4}, ReportOutcome::kTruncated},
      {Bytes(13, 0x02), ReportOutcome::kOverLong},
      {{0x03}, ReportOutcome::kTruncated},
      {{0x03, 1, 2, 3, 4, 5}, ReportOutcome::kOverLong},
      {{0x17}, ReportOutcome::kTruncated},
      {{0x00, 1, 2, 3, 4, 5, 6}, ReportOutcome::kUnknownId},
      {{0x05, 0x00}, ReportOutcome::kUnknownId},
      {{0x04, 0x01}, ReportOutcome::kUnknownId},  // the LED report is output, not input
      {{0xFF, 0xFF, 0xFF}, ReportOutcome::kUnknownId},
  };
  SpaceMouseDecoder decoder;
  ASSERT_EQ(decoder.decode(report(1, {118, 0, -6}), 1.0), ReportOutcome::kDecoded);
  ASSERT_EQ(decoder.decode(Bytes{0x03, 0x01, 0x00}, 1.0), ReportOutcome::kDecoded);
  const HidInputState before = decoder.state();
  HidReportCounts expected = before.counts;
  for (const auto& c : cases) {
    SCOPED_TRACE(::testing::PrintToString(c.bytes));
    EXPECT_EQ(decoder.decode(c.bytes, 2.0), c.outcome);
    if (c.outcome == ReportOutcome::kTruncated) ++expected.truncated;
    if (c.outcome == ReportOutcome::kOverLong) ++expected.overLong;
    if (c.outcome == ReportOutcome::kUnknownId) ++expected.unknownId;
  }
  const HidInputState& after = decoder.state();
  EXPECT_EQ(after.counts.decoded, 2u);
  EXPECT_EQ(after.counts.truncated, expected.truncated);
  EXPECT_EQ(after.counts.overLong, expected.overLong);
  EXPECT_EQ(after.counts.unknownId, expected.unknownId);
  EXPECT_EQ(after.counts.ignored(), std::size(cases));
  // Nothing of an ignored report reached the state.
  EXPECT_EQ(after.raw, before.raw);
  EXPECT_EQ(after.translation, before.translation);
  EXPECT_EQ(after.buttons, before.buttons);
  EXPECT_EQ(after.time, 1.0);
}

TEST(SpaceMouseDecoder, RandomReportsNeverEscapeTheRange) {
  std::mt19937 random(7);
  SpaceMouseDecoder decoder;
  const int n = 20000;
  for (int i = 0; i < n; ++i) {
    Bytes bytes(std::uniform_int_distribution<size_t>(0, 20)(random));
    for (uint8_t& b : bytes) b = static_cast<uint8_t>(random());
    if (!bytes.empty() && i % 2 == 0) bytes[0] = static_cast<uint8_t>(1 + random() % 3);
    decoder.decode(bytes, i);
    const HidInputState& s = decoder.state();
    for (double a : s.translation) ASSERT_LE(std::abs(a), 1.0);
    for (double a : s.rotation) ASSERT_LE(std::abs(a), 1.0);
  }
  EXPECT_EQ(decoder.state().counts.decoded + decoder.state().counts.ignored(), uint64_t(n));
  EXPECT_GT(decoder.state().counts.decoded, 0u);
}

TEST(SpaceMouseDecoder, FullScaleDeadZoneAndAxisTableAreOptions) {
  SpaceMouseOptions options;
  options.fullScale = 100;
  options.deadZone = 0;
  for (size_t i = 0; i < kAxisCount; ++i) options.axes[i] = {static_cast<AxisTarget>(i), 1};
  options.axes[2].sign = -1;
  SpaceMouseDecoder decoder(options);
  ASSERT_EQ(decoder.decode(report(1, {25, -50, 75}), 0), ReportOutcome::kDecoded);
  EXPECT_DOUBLE_EQ(decoder.state().translation[0], 0.25);
  EXPECT_DOUBLE_EQ(decoder.state().translation[1], -0.5);
  EXPECT_DOUBLE_EQ(decoder.state().translation[2], -0.75);
}

TEST(SpaceMouseIds, KnownIdsAndTheirDocumentedLayouts) {
  for (uint16_t pid :
       std::initializer_list<uint16_t>{0xc603, 0xc605, 0xc606, 0xc621, 0xc623, 0xc625, 0xc626,
                                       0xc627, 0xc628, 0xc629, 0xc62b, 0xc640}) {
    EXPECT_EQ(documentedLayout(0x046d, pid), SpaceMouseLayout::kSeparateReports) << pid;
  }
  for (uint16_t pid : std::initializer_list<uint16_t>{0xc62e, 0xc62f, 0xc631, 0xc632, 0xc633,
                                                      0xc638, 0xc63a, 0xc652})
    EXPECT_EQ(documentedLayout(0x256f, pid), SpaceMouseLayout::kCombinedReport) << pid;
  for (uint16_t pid : std::initializer_list<uint16_t>{0xc635, 0xc636})
    EXPECT_EQ(documentedLayout(0x256f, pid), SpaceMouseLayout::kSeparateReports) << pid;
  // Left out on purpose (sources disagree), other vendors, a Logitech mouse.
  EXPECT_FALSE(isSpaceMouse(0x256f, 0xc641));
  EXPECT_FALSE(isSpaceMouse(0x256f, 0xc62c));
  EXPECT_FALSE(isSpaceMouse(0x256f, 0xc626));
  EXPECT_FALSE(isSpaceMouse(0x046d, 0xc62e));
  EXPECT_FALSE(isSpaceMouse(0x046d, 0xc077));
  EXPECT_TRUE(isSpaceMouse(0x046d, 0xc626));

  const std::optional<HidProfile> profile = profileFor(0x046d, 0xc626);
  ASSERT_TRUE(profile);
  EXPECT_EQ(profile->vendorId, 0x046d);
  EXPECT_EQ(profile->productId, 0xc626);
  EXPECT_EQ(profile->name, "spacemouse-separate");
  EXPECT_EQ(profile->usagePage, 0x01);
  EXPECT_EQ(profile->usage, 0x08);
  EXPECT_EQ(profile->axes.size(), 6u);
  EXPECT_EQ(profile->buttons.size(), 32u);
  EXPECT_FALSE(profileFor(0x1234, 0x5678));
}

TEST(SpaceMouseIds, BuiltInProfilesDescribeTheDocumentedBytes) {
  const HidProfile separate = spaceMouseProfile(SpaceMouseLayout::kSeparateReports);
  const HidProfile combined = spaceMouseProfile(SpaceMouseLayout::kCombinedReport);
  const size_t separateOffsets[] = {1, 3, 5, 1, 3, 5};
  const uint8_t separateIds[] = {1, 1, 1, 2, 2, 2};
  for (size_t i = 0; i < 6; ++i) {
    EXPECT_EQ(separate.axes[i].reportId, separateIds[i]);
    EXPECT_EQ(separate.axes[i].byteOffset, separateOffsets[i]);
    EXPECT_EQ(combined.axes[i].reportId, 1);
    EXPECT_EQ(combined.axes[i].byteOffset, 1 + 2 * i);
    EXPECT_EQ(separate.axes[i].size, 2u);
    EXPECT_TRUE(separate.axes[i].isSigned);
  }
}

TEST(SpaceMouseIds, TheExampleUdevRulesCoverExactlyTheKnownIds) {
  const std::string name = "70-sculpt-spacemouse.rules";
  EXPECT_LT(name, "73-seat-late.rules");  // udev reads rules files in name order
  std::ifstream in(SCULPT_SOURCE_DIR "/haptics/udev/" + name);
  ASSERT_TRUE(in);
  const std::regex rule(R"re(SUBSYSTEM=="hidraw", ATTRS\{idVendor\}=="([0-9a-f]{4})", )re"
                        R"re(ATTRS\{idProduct\}=="([0-9a-f]{4})", TAG\+="uaccess")re");
  int rules = 0;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::smatch match;
    ASSERT_TRUE(std::regex_match(line, match, rule)) << line;
    const auto vid = static_cast<uint16_t>(std::stoi(match[1].str(), nullptr, 16));
    const auto pid = static_cast<uint16_t>(std::stoi(match[2].str(), nullptr, 16));
    EXPECT_TRUE(isSpaceMouse(vid, pid)) << line;
    ++rules;
  }
  EXPECT_EQ(rules, 22);  // 12 with vendor 046d, 10 with vendor 256f
}

}  // namespace
}  // namespace sculpt::haptics
