// User HID profiles: parsing (every error names its field), the profile-driven decoder, the
// shipped example profiles, and force output reports.

#include "haptics/hid/hid_profile.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "haptics/hid/hid_decoder.h"
#include "haptics/hid/spacemouse.h"
#include "io/file_error.h"

namespace sculpt::haptics {
namespace {

using Bytes = std::vector<uint8_t>;
const std::string kProfiles = SCULPT_SOURCE_DIR "/assets/hid_profiles/";

// A profile with one axis given by `axis` (JSON object text) and nothing else.
std::string withAxis(const std::string& axis) {
  return R"({"name": "t", "vendor_id": "1234", "product_id": "abcd", "axes": [)" + axis + "]}";
}

// A profile with one axis and the force output `force` (JSON object text).
std::string withForce(const std::string& force) {
  return R"({"name": "t", "vendor_id": "1234", "product_id": "abcd",
             "axes": [{"report_id": 1, "byte_offset": 1, "target": "tx"}], "force_output": )" +
         force + "}";
}

TEST(HidProfile, ParsesEveryField) {
  const HidProfile p = parseHidProfile(R"({
    "name": "Pad", "comment": "free text", "vendor_id": "0x12aB", "product_id": "00ff",
    "usage_page": "01", "usage": 4,
    "axes": [
      {"report_id": 2, "byte_offset": 1, "size": 1, "signed": false, "scale": -0.5,
       "dead_zone": 0, "target": "rz"},
      {"report_id": 2, "byte_offset": 2, "target": "tx"}
    ],
    "buttons": [{"report_id": 2, "byte_offset": 4, "bit": 7, "button": 31}],
    "force_output": {"report_id": 9, "byte_offset": 2, "size": 4, "signed": true,
                     "scale": 1000, "axes": ["fz", "fx"], "max_force": 2.5}
  })",
                                       "pad.json");
  EXPECT_EQ(p.name, "Pad");
  EXPECT_EQ(p.vendorId, 0x12ab);
  EXPECT_EQ(p.productId, 0x00ff);
  EXPECT_EQ(p.usagePage, 0x01);
  EXPECT_EQ(p.usage, 0x04);
  ASSERT_EQ(p.axes.size(), 2u);
  EXPECT_EQ(p.axes[0].reportId, 2);
  EXPECT_EQ(p.axes[0].byteOffset, 1u);
  EXPECT_EQ(p.axes[0].size, 1u);
  EXPECT_FALSE(p.axes[0].isSigned);
  EXPECT_EQ(p.axes[0].scale, -0.5);
  EXPECT_EQ(p.axes[0].deadZone, 0.0);
  EXPECT_EQ(p.axes[0].target, AxisTarget::kRz);
  // Defaults: 2 bytes, signed, 1/350, dead zone 0.03.
  EXPECT_EQ(p.axes[1].size, 2u);
  EXPECT_TRUE(p.axes[1].isSigned);
  EXPECT_DOUBLE_EQ(p.axes[1].scale, 1.0 / 350);
  EXPECT_DOUBLE_EQ(p.axes[1].deadZone, 0.03);
  ASSERT_EQ(p.buttons.size(), 1u);
  EXPECT_EQ(p.buttons[0].byteOffset, 4u);
  EXPECT_EQ(p.buttons[0].bit, 7);
  EXPECT_EQ(p.buttons[0].button, 31);
  ASSERT_TRUE(p.forceOutput);
  EXPECT_EQ(p.forceOutput->reportId, 9);
  EXPECT_EQ(p.forceOutput->byteOffset, 2u);
  EXPECT_EQ(p.forceOutput->size, 4u);
  EXPECT_EQ(p.forceOutput->countsPerNewton, 1000.0);
  EXPECT_EQ(p.forceOutput->axes, (std::vector<ForceAxis>{ForceAxis::kFz, ForceAxis::kFx}));
  EXPECT_EQ(p.forceOutput->maxForce, 2.5);
}

TEST(HidProfile, ErrorsNameTheFieldInOneSentence) {
  const std::string base = R"("name": "t", "vendor_id": "1234", "product_id": "abcd")";
  const struct {
    std::string json;
    std::string message;
  } cases[] = {
      {"[1, 2]", "p.json: a profile must be a JSON object"},
      {"{", "p.json: not valid JSON"},
      {R"({"vendor_id": "1234", "product_id": "abcd", "axes": []})", "p.json: name: is required"},
      {R"({"name": "t", "vendor_id": "zz12", "product_id": "abcd", "axes": []})",
       "p.json: vendor_id: 'zz12' is not 1 to 4 hexadecimal digits"},
      {R"({"name": "t", "vendor_id": "12345", "product_id": "abcd", "axes": []})",
       "p.json: vendor_id: '12345' is not 1 to 4 hexadecimal digits"},
      {R"({"name": "t", "vendor_id": "1234", "product_id": true, "axes": []})",
       "p.json: product_id: must be a hexadecimal string"},
      {"{" + base + R"(, "axis": []})", "p.json: axis: unknown field"},
      {"{" + base + R"(, "axes": []})", "p.json: axes: a profile needs at least one axis"},
      {"{" + base + R"(, "axes": {}})", "p.json: axes: must be an array"},
      {"{" + base + R"(, "usage_page": "1", "axes": []})", "p.json: usage: is required"},
      {withAxis(R"({"report_id": 1, "byte_offset": 1, "target": "tq"})"),
       "p.json: axes[0].target: unknown target 'tq' (expected tx, ty, tz, rx, ry, rz)"},
      {withAxis(R"({"report_id": 1, "byte_offset": 1})"), "p.json: axes[0].target: is required"},
      {withAxis(R"({"report_id": 1, "byte_offset": 1, "size": 3, "target": "tx"})"),
       "p.json: axes[0].size: 3 is not 1, 2 or 4 bytes"},
      {withAxis(R"({"report_id": 1, "byte_offset": 63, "size": 2, "target": "tx"})"),
       "p.json: axes[0].byte_offset: 63 plus 2 bytes runs past the 64-byte report"},
      {withAxis(R"({"report_id": 1, "byte_offset": 0, "target": "tx"})"),
       "p.json: axes[0].byte_offset: must be at least 1: byte 0 is the report ID"},
      {withAxis(R"({"report_id": 256, "byte_offset": 1, "target": "tx"})"),
       "p.json: axes[0].report_id: 256 is not from 0 to 255"},
      {withAxis(R"({"report_id": 1, "byte_offset": 1.5, "target": "tx"})"),
       "p.json: axes[0].byte_offset: must be a whole number"},
      {withAxis(R"({"report_id": 1, "byte_offset": 1, "scale": 0, "target": "tx"})"),
       "p.json: axes[0].scale: must not be 0"},
      {withAxis(R"({"report_id": 1, "byte_offset": 1, "dead_zone": 1, "target": "tx"})"),
       "p.json: axes[0].dead_zone: must be at least 0 and less than 1"},
      {withAxis(R"({"report_id": 1, "byte_offset": 1, "signed": 1, "target": "tx"})"),
       "p.json: axes[0].signed: must be true or false"},
      {withAxis(R"({"report_id": 1, "byte_offset": 1, "target": "tx"},
                   {"report_id": 1, "byte_offset": 3, "target": "tx"})"),
       "p.json: axes[1].target: tx is already the target of another axis"},
      {withAxis(R"({"report_id": 0, "byte_offset": 0, "target": "tx"},
                   {"report_id": 1, "byte_offset": 3, "target": "ty"})"),
       "p.json: axes: report_id 0 (a device without numbered reports) cannot be mixed"},
      {"{" + base + R"(, "axes": [], "buttons": [{"report_id": 3, "byte_offset": 1, "bit": 8,
                     "button": 0}]})",
       "p.json: buttons[0].bit: 8 is not from 0 to 7"},
      {"{" + base + R"(, "axes": [], "buttons": [{"report_id": 3, "byte_offset": 1, "bit": 0,
                     "button": 32}]})",
       "p.json: buttons[0].button: 32 is not from 0 to 31"},
      {"{" + base + R"(, "axes": [], "buttons": [{"report_id": 3, "byte_offset": 1, "bit": 0,
          "button": 1}, {"report_id": 3, "byte_offset": 1, "bit": 1, "button": 1}]})",
       "p.json: buttons[1].button: 1 is listed twice"},
      {withForce(R"({"report_id": 5, "byte_offset": 1,
                 "axes": ["fx"]})"),
       "p.json: force_output.scale: is required"},
      {withForce(R"({"report_id": 5, "byte_offset": 1,
                 "scale": 10, "axes": ["fw"]})"),
       "p.json: force_output.axes[0]: unknown target 'fw' (expected fx, fy, fz)"},
      {withForce(R"({"report_id": 5, "byte_offset": 60,
                 "size": 2, "scale": 10, "axes": ["fx", "fy", "fz"]})"),
       "p.json: force_output.byte_offset: 60 plus 6 bytes runs past the 64-byte report"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.json);
    try {
      parseHidProfile(c.json, "p.json");
      ADD_FAILURE() << "parsed";
    } catch (const FileError& error) {
      const std::string what = error.what();
      EXPECT_EQ(what.rfind(c.message, 0), 0u) << what;
      EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    }
  }
}

TEST(HidProfile, ShippedProfilesLoad) {
  const HidProfile spaceNavigator = loadHidProfile(kProfiles + "spacenavigator.json");
  EXPECT_EQ(spaceNavigator.vendorId, 0x046d);
  EXPECT_EQ(spaceNavigator.productId, 0xc626);
  EXPECT_EQ(spaceNavigator.axes.size(), 6u);
  const HidProfile joystick = loadHidProfile(kProfiles + "example-joystick.json");
  EXPECT_EQ(joystick.axes.size(), 3u);
  EXPECT_EQ(joystick.buttons.size(), 4u);
  EXPECT_THROW(loadHidProfile(kProfiles + "missing.json"), FileError);
}

TEST(HidProfile, ShippedSpaceNavigatorProfileDecodesAsTheBuiltInOne) {
  ProfileDecoder user(loadHidProfile(kProfiles + "spacenavigator.json"));
  SpaceMouseDecoder builtIn;
  const Bytes reports[] = {{0x01, 0x76, 0x00, 0x00, 0x00, 0xFA, 0xFF},
                           {0x02, 0x10, 0x01, 0x2C, 0x01, 0x00, 0x80},
                           {0x03, 0x02, 0x00},
                           {0x01, 0x00, 0x80, 0xFF, 0x7F, 0x9C, 0xFF}};
  for (const Bytes& report : reports) {
    ASSERT_EQ(user.decode(report, 0), ReportOutcome::kDecoded);
    ASSERT_EQ(builtIn.decode(report, 0), ReportOutcome::kDecoded);
    EXPECT_EQ(user.state().raw, builtIn.state().raw);
    EXPECT_EQ(user.state().translation, builtIn.state().translation);
    EXPECT_EQ(user.state().rotation, builtIn.state().rotation);
    EXPECT_EQ(user.state().buttons, builtIn.state().buttons);
  }
}

TEST(ProfileDecoder, FieldSizesSignsAndButtons) {
  ProfileDecoder decoder(parseHidProfile(R"({"name": "g", "vendor_id": "1", "product_id": "2",
    "axes": [
      {"report_id": 7, "byte_offset": 1, "size": 1, "signed": false, "scale": 0.01,
       "dead_zone": 0, "target": "tx"},
      {"report_id": 7, "byte_offset": 2, "size": 1, "signed": true, "scale": 0.01,
       "dead_zone": 0, "target": "ty"},
      {"report_id": 7, "byte_offset": 3, "size": 4, "signed": true, "scale": 1e-9,
       "dead_zone": 0, "target": "rz"},
      {"report_id": 8, "byte_offset": 1, "size": 2, "signed": false, "scale": -1e-4,
       "dead_zone": 0.1, "target": "rx"}],
    "buttons": [{"report_id": 7, "byte_offset": 7, "bit": 0, "button": 0},
                {"report_id": 7, "byte_offset": 8, "bit": 7, "button": 5}]})",
                                         "g.json"));
  // 0x50 = 80 unsigned; 0xF6 = -10 signed; 0xC4653600 = -1000000000 as int32.
  const Bytes report7{7, 0x50, 0xF6, 0x00, 0x36, 0x65, 0xC4, 0x01, 0x80};
  ASSERT_EQ(decoder.decode(report7, 0), ReportOutcome::kDecoded);
  const HidInputState& s = decoder.state();
  EXPECT_EQ(s.raw[0], 80);
  EXPECT_EQ(s.raw[1], -10);
  EXPECT_EQ(s.raw[2], -1000000000);
  EXPECT_DOUBLE_EQ(s.translation[0], 0.8);
  EXPECT_DOUBLE_EQ(s.translation[1], -0.1);
  EXPECT_DOUBLE_EQ(s.rotation[2], -1.0);
  EXPECT_EQ(s.buttons, 0x21u);
  // 0xFFFF unsigned = 65535 counts * -1e-4 = -6.55, clamped to -1.
  ASSERT_EQ(decoder.decode(Bytes{8, 0xFF, 0xFF}, 0), ReportOutcome::kDecoded);
  EXPECT_EQ(decoder.state().raw[3], 65535);
  EXPECT_EQ(decoder.state().rotation[0], -1.0);
  // 0x0800 = 2048 counts = -0.2048, dead zone 0.1: -(0.2048 - 0.1) / 0.9.
  ASSERT_EQ(decoder.decode(Bytes{8, 0x00, 0x08}, 0), ReportOutcome::kDecoded);
  EXPECT_NEAR(decoder.state().rotation[0], -0.1048 / 0.9, 1e-12);

  // The button byte 8 may be missing (reads released); the axis bytes may not.
  ASSERT_EQ(decoder.decode(Bytes{7, 0, 0, 0, 0, 0, 0, 0x01}, 0), ReportOutcome::kDecoded);
  EXPECT_EQ(decoder.state().buttons, 0x1u);
  EXPECT_EQ(decoder.decode(Bytes{7, 0, 0, 0, 0, 0, 0}, 0), ReportOutcome::kTruncated);
  EXPECT_EQ(decoder.decode(Bytes{8, 0}, 0), ReportOutcome::kTruncated);
  EXPECT_EQ(decoder.decode(Bytes{9, 0, 0}, 0), ReportOutcome::kUnknownId);
  EXPECT_EQ(decoder.decode(Bytes{}, 0), ReportOutcome::kTruncated);
  // Longer reports are fine for a user profile: bytes past its fields are not looked at.
  EXPECT_EQ(decoder.decode(Bytes(40, 8), 0), ReportOutcome::kDecoded);
  EXPECT_EQ(decoder.state().counts.decoded, 5u);
  EXPECT_EQ(decoder.state().counts.ignored(), 4u);
}

TEST(ProfileDecoder, UnnumberedReportsStartAtByteZero) {
  ProfileDecoder decoder(parseHidProfile(R"({"name": "u", "vendor_id": "1", "product_id": "2",
    "axes": [{"report_id": 0, "byte_offset": 0, "size": 1, "scale": 0.01, "dead_zone": 0,
              "target": "tz"}],
    "buttons": [{"report_id": 0, "byte_offset": 1, "bit": 2, "button": 3}]})",
                                         "u.json"));
  ASSERT_EQ(decoder.decode(Bytes{0x32, 0x04}, 0), ReportOutcome::kDecoded);
  EXPECT_DOUBLE_EQ(decoder.state().translation[2], 0.5);
  EXPECT_EQ(decoder.state().buttons, 0x8u);
  EXPECT_EQ(decoder.decode(Bytes{0x32}, 0), ReportOutcome::kTruncated);
}

TEST(NormaliseAxis, ClampAndDeadZone) {
  EXPECT_EQ(normaliseAxis(0, 0.01, 0.1), 0.0);
  EXPECT_EQ(normaliseAxis(10, 0.01, 0.1), 0.0);  // exactly at the dead zone
  EXPECT_NEAR(normaliseAxis(55, 0.01, 0.1), 0.5, 1e-12);
  EXPECT_NEAR(normaliseAxis(-55, 0.01, 0.1), -0.5, 1e-12);
  EXPECT_EQ(normaliseAxis(1000, 0.01, 0.1), 1.0);
  EXPECT_EQ(normaliseAxis(-1000, 0.01, 0.1), -1.0);
  EXPECT_EQ(normaliseAxis(std::numeric_limits<int64_t>::max(), 1.0, 0.0), 1.0);
  EXPECT_NEAR(normaliseAxis(30, -0.01, 0.0), -0.3, 1e-12);
}

TEST(ForceReport, CountsRoundedClampedLittleEndian) {
  HidForceOutput output;
  output.reportId = 5;
  output.byteOffset = 2;
  output.size = 2;
  output.isSigned = true;
  output.countsPerNewton = 100;
  output.axes = {ForceAxis::kFx, ForceAxis::kFy, ForceAxis::kFz};
  // 1.5 N = 150 = 0x0096; -2 N = -200 = 0xFF38; 1000 N clamps to 32767 = 0x7FFF.
  EXPECT_EQ(buildForceReport(output, Eigen::Vector3d(1.5, -2.0, 1000.0)),
            (Bytes{5, 0, 0x96, 0x00, 0x38, 0xFF, 0xFF, 0x7F}));
  EXPECT_EQ(buildForceReport(output, Eigen::Vector3d(-1e9, std::nan(""), 0.004)),
            (Bytes{5, 0, 0x00, 0x80, 0x00, 0x00, 0x00, 0x00}));
  output.size = 1;
  output.isSigned = false;
  output.axes = {ForceAxis::kFz};
  EXPECT_EQ(buildForceReport(output, Eigen::Vector3d(0, 0, -1)), (Bytes{5, 0, 0x00}));
  EXPECT_EQ(buildForceReport(output, Eigen::Vector3d(0, 0, 9)), (Bytes{5, 0, 0xFF}));
  output.size = 4;
  output.isSigned = true;
  output.byteOffset = 1;
  EXPECT_EQ(buildForceReport(output, Eigen::Vector3d(0, 0, -0.01)),
            (Bytes{5, 0xFF, 0xFF, 0xFF, 0xFF}));
}

}  // namespace
}  // namespace sculpt::haptics
