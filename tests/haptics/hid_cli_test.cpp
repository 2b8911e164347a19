// sculpt-cli devices end to end: the committed SpaceNavigator recording decoded line by line
// (normalised and raw), a recording written here, a user profile, and bad input (exit 2, one
// error line naming the file).

#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "haptics/hid/hid_recording.h"
#include "support/cli_fixture.h"

namespace sculpt::haptics {
namespace {

using test::CliResult;
using test::quote;

const std::string kFixture = SCULPT_SOURCE_DIR "/tests/data/hid/spacenavigator.txt";
const std::string kProfiles = SCULPT_SOURCE_DIR "/assets/hid_profiles/";

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

class DevicesCliTest : public test::CliFixture {
 protected:
  DevicesCliTest() : CliFixture("sculpt_devices_cli_test_") {}
  void SetUp() override {
    CliFixture::SetUp();
    ASSERT_TRUE(std::filesystem::exists(test::kCli)) << test::kCli << " is not built";
  }
};

// The fixture's reports, decoded by hand with the default table (tx = X, ty = -Z, tz = Y,
// rx = RX, ry = -RZ, rz = RY) and normalisation ((|c|/350 - 0.03) / 0.97, clamped):
// X = 118 -> 0.3166; Z = -6 -> inside the dead zone; RY = 300 -> 0.8527; X = -32768 -> -1;
// Y = 32767 -> 1; Z = -100 -> ty = 0.2636. Reports 6 (cut to 4 bytes) and 7 (ID 5) are ignored.
const std::vector<std::string> kNormalised = {
    "t=0.000000 tx=0.3166 ty=0.0000 tz=0.0000 rx=0.0000 ry=0.0000 rz=0.0000 buttons=0x0",
    "t=0.008000 tx=0.3166 ty=0.0000 tz=0.0000 rx=0.0000 ry=0.0000 rz=0.8527 buttons=0x0",
    "t=0.016000 tx=0.3166 ty=0.0000 tz=0.0000 rx=0.0000 ry=0.0000 rz=0.8527 buttons=0x1",
    "t=0.024000 tx=-1.0000 ty=0.2636 tz=1.0000 rx=0.0000 ry=0.0000 rz=0.8527 buttons=0x1",
    "t=0.032000 tx=-1.0000 ty=0.2636 tz=1.0000 rx=0.0000 ry=0.0000 rz=0.8527 buttons=0x3",
    "t=0.056000 tx=-1.0000 ty=0.2636 tz=1.0000 rx=0.0000 ry=0.0000 rz=0.8527 buttons=0x0",
    "reports=8 decoded=6 ignored=2",
};

TEST_F(DevicesCliTest, ReplaysTheSpaceNavigatorRecording) {
  const CliResult result = run("devices --replay " + quote(kFixture));
  EXPECT_FALSE(result.signaled);
  ASSERT_EQ(result.exitCode, 0) << result.err;
  EXPECT_EQ(lines(result.out), kNormalised);
  // The ignored reports are named on stderr.
  EXPECT_NE(result.err.find("report 6"), std::string::npos) << result.err;
  EXPECT_NE(result.err.find("truncated"), std::string::npos) << result.err;
  EXPECT_NE(result.err.find("unknown report ID"), std::string::npos) << result.err;
}

TEST_F(DevicesCliTest, RawPrintsTheDevicesOwnCountsInReportOrder) {
  const CliResult result = run("devices --replay " + quote(kFixture) + " --raw");
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const std::vector<std::string> expected = {
      "t=0.000000 raw=118,0,-6,0,0,0 buttons=0x0",
      "t=0.008000 raw=118,0,-6,0,300,0 buttons=0x0",
      "t=0.016000 raw=118,0,-6,0,300,0 buttons=0x1",
      "t=0.024000 raw=-32768,32767,-100,0,300,0 buttons=0x1",
      "t=0.032000 raw=-32768,32767,-100,0,300,0 buttons=0x3",
      "t=0.056000 raw=-32768,32767,-100,0,300,0 buttons=0x0",
      "reports=8 decoded=6 ignored=2",
  };
  EXPECT_EQ(lines(result.out), expected);
}

TEST_F(DevicesCliTest, AShippedProfileDecodesTheRecordingAsTheBuiltInOne) {
  const CliResult result = run("devices --replay " + quote(kFixture) + " --profile " +
                               quote(kProfiles + "spacenavigator.json"));
  ASSERT_EQ(result.exitCode, 0) << result.err;
  EXPECT_EQ(lines(result.out), kNormalised);
}

TEST_F(DevicesCliTest, ARecordingWrittenHereOfANewerDevice) {
  // A combined-layout device (256f:c62e): one 13-byte report with all six axes, a battery report.
  HidRecording recording;
  recording.name = "test";
  recording.bus = 3;
  recording.vendorId = 0x256f;
  recording.productId = 0xc62e;
  recording.events = {
      {0.5, {0x01, 0x5E, 0x01, 0, 0, 0, 0, 0, 0, 0xA2, 0xFE, 0, 0}},  // X = 350, RY = -350
      {0.75, {0x17, 0x2A}},                                           // battery 42 %
  };
  writeHidRecording(path("rec.txt"), recording);
  const CliResult result = run("devices --replay " + quote(path("rec.txt")));
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const std::vector<std::string> expected = {
      "t=0.500000 tx=1.0000 ty=0.0000 tz=0.0000 rx=0.0000 ry=0.0000 rz=-1.0000 buttons=0x0",
      "t=0.750000 tx=1.0000 ty=0.0000 tz=0.0000 rx=0.0000 ry=0.0000 rz=-1.0000 buttons=0x0 "
      "battery=42",
      "reports=2 decoded=2 ignored=0",
  };
  EXPECT_EQ(lines(result.out), expected);
}

TEST_F(DevicesCliTest, BadInputIsOneErrorLineNamingTheFile) {
  test::writeText(path("bad.txt"), "N: x\nI: 3 046d c626\nE: 0.000000 7 01 02\n");
  expectBadInput("devices --replay " + quote(path("bad.txt")), path("bad.txt") + ": line 3");
  test::writeText(path("other.txt"), "I: 3 1234 5678\nE: 0.000000 1 01\n");
  expectBadInput("devices --replay " + quote(path("other.txt")), "no profile for device 1234:5678");
  expectBadInput("devices --replay " + quote(path("missing.txt")), path("missing.txt"));
  test::writeText(path("p.json"), R"({"name": "p", "vendor_id": "xyz"})");
  expectBadInput("devices --replay " + quote(kFixture) + " --profile " + quote(path("p.json")),
                 path("p.json") + ": vendor_id:");
  expectBadInput("devices --raw", "--raw is for --replay");
  expectBadInput("devices somefile", "devices takes no file");
  expectBadInput("devices --bogus", "unknown option '--bogus'");
}

TEST_F(DevicesCliTest, ListsDevicesAndEndsWithTheirCount) {
  const CliResult result = run("devices");
  EXPECT_FALSE(result.signaled);
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const std::vector<std::string> out = lines(result.out);
  ASSERT_FALSE(out.empty());
  EXPECT_EQ(out.back(), "devices=" + std::to_string(out.size() - 1));
  const CliResult help = run("devices --help");
  EXPECT_EQ(help.exitCode, 0);
  EXPECT_NE(help.out.find("devices --replay FILE"), std::string::npos);
}

}  // namespace
}  // namespace sculpt::haptics
