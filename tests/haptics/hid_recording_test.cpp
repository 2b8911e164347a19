// hid-recorder text files: the committed fixture, write/parse round trips, malformed and hostile
// files (each a one-line error with its line number, never a crash), the report descriptor's
// top-level usage, and the replay transport that plays a recording as a device.

#include "haptics/hid/hid_recording.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "haptics/hid/replay_transport.h"
#include "io/file_error.h"

namespace sculpt::haptics {
namespace {

using Bytes = std::vector<uint8_t>;
const std::string kFixture = SCULPT_SOURCE_DIR "/tests/data/hid/spacenavigator.txt";

TEST(HidRecording, ReadsTheCommittedFixture) {
  const HidRecording r = loadHidRecording(kFixture);
  EXPECT_EQ(r.name, "3Dconnexion SpaceNavigator");
  EXPECT_EQ(r.bus, 3);
  EXPECT_EQ(r.vendorId, 0x046d);
  EXPECT_EQ(r.productId, 0xc626);
  EXPECT_TRUE(r.descriptor.empty());
  ASSERT_EQ(r.events.size(), 8u);
  EXPECT_EQ(r.events[0].bytes, (Bytes{0x01, 0x76, 0x00, 0x00, 0x00, 0xFA, 0xFF}));
  EXPECT_EQ(r.events[0].time, 0.0);
  EXPECT_DOUBLE_EQ(r.events[1].time, 0.008);
  EXPECT_EQ(r.events[7].bytes, (Bytes{0x03, 0x00, 0x00}));
}

TEST(HidRecording, WriteAndParseRoundTrip) {
  std::mt19937 random(11);
  for (int trial = 0; trial < 20; ++trial) {
    HidRecording r;
    r.name = "Device " + std::to_string(trial) + " with  two spaces";
    r.bus = static_cast<uint16_t>(random() % 0x20);
    r.vendorId = static_cast<uint16_t>(random());
    r.productId = static_cast<uint16_t>(random());
    r.descriptor.resize(random() % 50);
    for (uint8_t& b : r.descriptor) b = static_cast<uint8_t>(random());
    double time = 0;
    for (int e = 0; e < 30; ++e) {
      time += static_cast<double>(random() % 100000) * 1e-6;
      Bytes bytes(1 + random() % 64);
      for (uint8_t& b : bytes) b = static_cast<uint8_t>(random());
      r.events.push_back({time, bytes});
    }
    const HidRecording back = parseHidRecording(formatHidRecording(r), "round trip");
    EXPECT_EQ(back.name, r.name);
    EXPECT_EQ(back.bus, r.bus);
    EXPECT_EQ(back.vendorId, r.vendorId);
    EXPECT_EQ(back.productId, r.productId);
    EXPECT_EQ(back.descriptor, r.descriptor);
    ASSERT_EQ(back.events.size(), r.events.size());
    for (size_t i = 0; i < r.events.size(); ++i) {
      EXPECT_NEAR(back.events[i].time, r.events[i].time, 1e-9);
      EXPECT_EQ(back.events[i].bytes, r.events[i].bytes);
    }
  }
}

TEST(HidRecording, ReadsWhatHidRecorderWrites) {
  // Comments, D: 0, P:, CRLF line ends and upper-case hex are all accepted.
  const HidRecording r = parseHidRecording(
      "# recorded by hid-recorder\r\nD: 0\r\nR: 4 05 01 09 08\r\nN: Some Device\r\n"
      "P: usb-0000:00:14.0-2/input0\r\nI: 3 256F C62E\r\n# ReportID: 1\r\n"
      "E: 000001.250000 3 01 AB cd\r\n",
      "rec.txt");
  EXPECT_EQ(r.name, "Some Device");
  EXPECT_EQ(r.vendorId, 0x256f);
  EXPECT_EQ(r.productId, 0xc62e);
  EXPECT_EQ(r.descriptor, (Bytes{0x05, 0x01, 0x09, 0x08}));
  ASSERT_EQ(r.events.size(), 1u);
  EXPECT_EQ(r.events[0].time, 1.25);
  EXPECT_EQ(r.events[0].bytes, (Bytes{0x01, 0xAB, 0xCD}));
}

TEST(HidRecording, MalformedLinesAreOneLineErrorsWithTheLineNumber) {
  const std::string head = "N: d\nI: 3 046d c626\n";
  const struct {
    std::string text;
    std::string message;
  } cases[] = {
      {head + "X: 1\n", "f.txt: line 3: unknown line 'X:'"},
      {head + "E: 0.000000 3 01 02\n", "f.txt: line 3: E: size 3 disagrees with the 2 bytes given"},
      {head + "E: 0.000000 1 01 02\n", "f.txt: line 3: E: size 1 disagrees with the 2 bytes given"},
      {head + "E: 0.000000 99999999999999999999999 01\n",
       "f.txt: line 3: E: size '99999999999999999999999' is not a number"},
      {head + "E: 0.000000 100000 01\n",
       "f.txt: line 3: E: size 100000 is over the limit of 16384"},
      {head + "E: 0.000000 0\n", "f.txt: line 3: E: a report has at least one byte"},
      {head + "E: 0.000000 2 01 zz\n", "f.txt: line 3: E: byte 'zz' is not two hex digits"},
      {head + "E: 0.000000 2 01 123\n", "f.txt: line 3: E: byte '123' is not two hex digits"},
      {head + "E: soon 1 01\n", "f.txt: line 3: E: time 'soon' is not <seconds>.<micros>"},
      {head + "E: -1.0 1 01\n", "f.txt: line 3: E: time '-1.0' is not <seconds>.<micros>"},
      {head + "E: 1.5 1 01\nE: 1.0 1 01\n", "f.txt: line 4: E: time 1.0 is before the previous"},
      {head + "E: 1.5\n", "f.txt: line 3: E: needs a time, a size and the report bytes"},
      {head + "R: 3 05 01\n", "f.txt: line 3: R: size 3 disagrees with the 2 bytes given"},
      {head + "R: 5000\n", "f.txt: line 3: R: size 5000 is over the limit of 4096"},
      {head + "R: 0\nR: 0\n", "f.txt: line 4: a second R: line"},
      {head + "I: 3 046d c626\n", "f.txt: line 3: a second I: line"},
      {head + "N: again\n", "f.txt: line 3: a second N: line"},
      {head + "D: 1\n", "f.txt: line 3: only single-device recordings (D: 0) are supported"},
      {"I: 3 046d\n", "f.txt: line 1: I: needs a bus, a vendor ID and a product ID in hex"},
      {"I: 3 046d 1c626\n", "f.txt: line 1: I: values must be hexadecimal numbers up to ffff"},
      {"N: only a name\n", "f.txt: no I: line"},
      {"", "f.txt: no I: line"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.text);
    try {
      parseHidRecording(c.text, "f.txt");
      ADD_FAILURE() << "parsed";
    } catch (const FileError& error) {
      const std::string what = error.what();
      EXPECT_EQ(what.rfind(c.message, 0), 0u) << what;
      EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    }
  }
}

TEST(HidRecording, HostileTextIsRejectedOrReadNeverACrash) {
  const std::string fixture = formatHidRecording(loadHidRecording(kFixture));
  std::mt19937 random(5);
  int rejected = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    std::string text = fixture;
    const int edits = 1 + static_cast<int>(random() % 6);
    for (int k = 0; k < edits; ++k) {
      const size_t at = random() % text.size();
      switch (random() % 3) {
        case 0:
          text[at] = static_cast<char>(random());
          break;
        case 1:
          text.erase(at, 1 + random() % 4);
          break;
        default:
          text.insert(at, std::string(1 + random() % 3, static_cast<char>(random())));
      }
      if (text.empty()) text = "x";
    }
    try {
      const HidRecording r = parseHidRecording(text, "fuzz");
      for (const HidRecordedEvent& e : r.events) ASSERT_FALSE(e.bytes.empty());
    } catch (const FileError&) {
      ++rejected;
    }
  }
  EXPECT_GT(rejected, 500);
}

TEST(HidRecording, MissingFileNamesIt) {
  try {
    loadHidRecording("/nonexistent/rec.txt");
    ADD_FAILURE();
  } catch (const FileError& error) {
    EXPECT_NE(std::string(error.what()).find("/nonexistent/rec.txt"), std::string::npos);
  }
}

TEST(HidRecording, TopLevelUsageOfADescriptor) {
  // Usage Page (Generic Desktop) 05 01, Usage (Multi-axis Controller) 09 08, Collection
  // (Application) A1 01: how multi-axis controllers open their descriptor.
  EXPECT_EQ(topLevelUsage({0x05, 0x01, 0x09, 0x08, 0xA1, 0x01, 0xA1, 0x00, 0x85, 0x01}).page, 1);
  EXPECT_EQ(topLevelUsage({0x05, 0x01, 0x09, 0x08, 0xA1, 0x01}).usage, 8);
  // Two-byte usage page (06 lo hi), then Usage (Mouse) 09 02.
  const HidUsage vendor = topLevelUsage({0x06, 0x00, 0xFF, 0x09, 0x02, 0xA1, 0x01});
  EXPECT_EQ(vendor.page, 0xFF00);
  EXPECT_EQ(vendor.usage, 2);
  // An extended (4-byte) usage carries its page in the high half.
  const HidUsage extended = topLevelUsage({0x0B, 0x04, 0x00, 0x01, 0x00, 0xA1, 0x01});
  EXPECT_EQ(extended.page, 1);
  EXPECT_EQ(extended.usage, 4);
  EXPECT_EQ(topLevelUsage({}).page, 0);
  EXPECT_EQ(topLevelUsage({0x05}).page, 0);                    // cut inside an item
  EXPECT_EQ(topLevelUsage({0x05, 0x01, 0x09, 0x08}).page, 0);  // no collection
}

TEST(ReplayTransport, PlaysTheRecordingThenUnplugs) {
  ReplayTransport transport(kFixture);
  const std::vector<HidDeviceInfo> listed = transport.enumerate();
  ASSERT_EQ(listed.size(), 1u);
  EXPECT_EQ(listed[0].path, "replay:" + kFixture);
  EXPECT_EQ(listed[0].vendorId, 0x046d);
  EXPECT_EQ(listed[0].productId, 0xc626);
  EXPECT_EQ(listed[0].product, "3Dconnexion SpaceNavigator");
  EXPECT_EQ(listed[0].usagePage, 0);  // the fixture has no descriptor to tell

  std::string error;
  EXPECT_EQ(transport.open("replay:other", &error), nullptr);
  EXPECT_NE(error.find("no such recorded device"), std::string::npos);
  const std::unique_ptr<HidConnection> connection = transport.open(listed[0].path, &error);
  ASSERT_NE(connection, nullptr);
  const HidRecording recording = loadHidRecording(kFixture);
  uint8_t buffer[64];
  for (const HidRecordedEvent& event : recording.events) {
    const int n = connection->read(buffer, sizeof buffer, 0);
    ASSERT_EQ(n, static_cast<int>(event.bytes.size()));
    EXPECT_EQ(Bytes(buffer, buffer + n), event.bytes);
  }
  EXPECT_EQ(connection->read(buffer, sizeof buffer, 0), -1);
  EXPECT_FALSE(connection->lastError().empty());
  EXPECT_TRUE(transport.enumerate().empty());
  EXPECT_EQ(connection->write(buffer, 2), -1);
}

TEST(ReplayTransport, CutsReportsToTheBufferAsHidrawDoes) {
  ReplayTransport transport(kFixture);
  const auto connection = transport.open(transport.path(), nullptr);
  uint8_t buffer[3];
  EXPECT_EQ(connection->read(buffer, sizeof buffer, 0), 3);
  EXPECT_EQ(Bytes(buffer, buffer + 3), (Bytes{0x01, 0x76, 0x00}));
}

TEST(ReplayTransport, HonoursTimestampsWhenAsked) {
  HidRecording r;
  r.vendorId = 0x046d;
  r.productId = 0xc626;
  r.descriptor = {0x05, 0x01, 0x09, 0x08, 0xA1, 0x01, 0xC0};
  r.events = {{10.0, {0x03, 0x00}}, {10.06, {0x03, 0x01}}};
  ReplayTransport transport(r, "timed.txt", {.honourTimestamps = true});
  EXPECT_EQ(transport.enumerate().at(0).usage, 8);
  const auto connection = transport.open("replay:timed.txt", nullptr);
  uint8_t buffer[8];
  const auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(connection->read(buffer, sizeof buffer, 0), 2);  // the first is due at once
  EXPECT_EQ(connection->read(buffer, sizeof buffer, 1), 0);  // the second is 60 ms away
  EXPECT_EQ(connection->read(buffer, sizeof buffer, -1), 2);
  EXPECT_EQ(buffer[1], 0x01);
  EXPECT_GE(std::chrono::steady_clock::now() - start, std::chrono::milliseconds(55));
}

}  // namespace
}  // namespace sculpt::haptics
