// The device-manager thread over the scripted transport: hot-plug within two polls, one device per
// path, unplug mid-read (disconnected and zero at once), replug, ignored reports counted, every
// transport call (writes included) made from the manager thread; and HidInputDevice over it.

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <functional>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "haptics/hid/device_manager.h"
#include "haptics/hid/hid_input_device.h"
#include "haptics/hid/replay_transport.h"
#include "haptics/hid/scripted_transport.h"

namespace sculpt::haptics {
namespace {

using Bytes = std::vector<uint8_t>;
using std::chrono::milliseconds;

const Bytes kGenuine{0x01, 0x76, 0x00, 0x00, 0x00, 0xFA, 0xFF};  // X = +118, Y = 0, Z = -6
const Bytes kFullX{0x01, 0x5E, 0x01, 0x00, 0x00, 0x00, 0x00};    // X = +350
constexpr double kGenuineTx = 0.3166421206;                      // (118/350 - 0.03) / 0.97

bool waitFor(const std::function<bool()>& done, milliseconds limit = milliseconds(10000)) {
  const auto end = std::chrono::steady_clock::now() + limit;
  while (!done()) {
    if (std::chrono::steady_clock::now() > end) return false;
    std::this_thread::sleep_for(milliseconds(1));
  }
  return true;
}

DeviceManagerOptions fastOptions() {
  DeviceManagerOptions options;
  options.pollPeriod = milliseconds(20);
  options.readTimeoutMs = 2;
  return options;
}

HidDeviceInfo spaceNavigator(const std::string& path, uint16_t usage = 0x08,
                             const std::string& serial = "") {
  HidDeviceInfo device;
  device.path = path;
  device.vendorId = 0x046d;
  device.productId = 0xc626;
  device.manufacturer = "3Dconnexion";
  device.product = "SpaceNavigator";
  device.serial = serial;
  device.usagePage = 0x01;
  device.usage = usage;
  device.interfaceNumber = 0;
  return device;
}

std::optional<ManagedDevice> find(const DeviceManager& manager, const std::string& path) {
  for (const ManagedDevice& device : manager.devices())
    if (device.path == path) return device;
  return std::nullopt;
}

bool connected(const DeviceManager& manager, const std::string& path) {
  const auto device = find(manager, path);
  return device && device->connected;
}

TEST(DeviceManager, HotPlugAppearsWithinTwoPolls) {
  ScriptedTransport transport;
  DeviceManager manager(transport, fastOptions());
  ASSERT_TRUE(waitFor([&] { return manager.pollCount() >= 1; }));
  EXPECT_TRUE(manager.devices().empty());
  transport.addDevice(spaceNavigator("/dev/hidraw7"));
  const uint64_t before = manager.pollCount();
  ASSERT_TRUE(waitFor([&] { return manager.pollCount() >= before + 2; }));
  const std::vector<ManagedDevice> devices = manager.devices();
  ASSERT_EQ(devices.size(), 1u);
  EXPECT_EQ(devices[0].id, 0);
  EXPECT_TRUE(devices[0].connected);
  EXPECT_EQ(devices[0].path, "/dev/hidraw7");
  EXPECT_EQ(devices[0].model, "SpaceNavigator");
  EXPECT_EQ(devices[0].manufacturer, "3Dconnexion");
  EXPECT_EQ(devices[0].profileName, "spacemouse-separate");
  EXPECT_TRUE(devices[0].hasLed);
  EXPECT_FALSE(devices[0].hasForceOutput);
}

TEST(DeviceManager, OneDevicePerPathAndOnlyDevicesWithAProfile) {
  ScriptedTransport transport;
  transport.addDevice(spaceNavigator("/dev/hidraw1", 0x08));
  transport.addDevice(spaceNavigator("/dev/hidraw1", 0x02));  // the same path, another usage
  transport.addDevice(spaceNavigator("/dev/hidraw2", 0x02));  // a mouse-only interface
  HidDeviceInfo unknown = spaceNavigator("/dev/hidraw3");
  unknown.vendorId = 0x1234;
  transport.addDevice(unknown);
  HidDeviceInfo noUsage = spaceNavigator("/dev/hidraw4");
  noUsage.usagePage = 0;  // a transport that does not report usages
  noUsage.usage = 0;
  transport.addDevice(noUsage);
  DeviceManager manager(transport, fastOptions());
  ASSERT_TRUE(waitFor([&] { return manager.pollCount() >= 3; }));
  const std::vector<ManagedDevice> devices = manager.devices();
  ASSERT_EQ(devices.size(), 2u);
  EXPECT_TRUE(connected(manager, "/dev/hidraw1"));
  EXPECT_TRUE(connected(manager, "/dev/hidraw4"));
  EXPECT_EQ(transport.openCount("/dev/hidraw1"), 1);
  EXPECT_EQ(transport.openCount("/dev/hidraw2"), 0);
  EXPECT_EQ(transport.openCount("/dev/hidraw3"), 0);
}

TEST(DeviceManager, ReportsReachTheReader) {
  ScriptedTransport transport;
  transport.addDevice(spaceNavigator("/dev/hidraw1"));
  DeviceManager manager(transport, fastOptions());
  ASSERT_TRUE(waitFor([&] { return connected(manager, "/dev/hidraw1"); }));
  HidInputDevice device(manager, 0);
  transport.script("/dev/hidraw1", {ScriptStep::report(kGenuine), ScriptStep::timeout(),
                                    ScriptStep::report({0x03, 0x01, 0x00})});
  ASSERT_TRUE(waitFor([&] { return device.read(0).buttons == 0x1; }));
  const DeviceSample sample = device.read(1.25);
  EXPECT_TRUE(sample.connected);
  EXPECT_EQ(sample.time, 1.25);
  EXPECT_NEAR(sample.position.x(), kGenuineTx, 1e-9);
  EXPECT_EQ(sample.position.y(), 0.0);
  EXPECT_EQ(sample.position.z(), 0.0);
  EXPECT_EQ(sample.rotationRate, Eigen::Vector3d::Zero());
  EXPECT_EQ(sample.velocity, Eigen::Vector3d::Zero());
}

TEST(DeviceManager, UnplugMidReadIsDisconnectedAndZeroAtOnceAndReplugBringsItBack) {
  ScriptedTransport transport;
  const std::string path = "/dev/hidraw1";
  transport.addDevice(spaceNavigator(path));
  DeviceManager manager(transport, fastOptions());
  ASSERT_TRUE(waitFor([&] { return connected(manager, path); }));
  HidInputDevice device(manager, 0);
  transport.script(path, {ScriptStep::report(kFullX), ScriptStep::report({0x03, 0x01, 0x00})});
  ASSERT_TRUE(waitFor([&] {
    const DeviceSample s = device.read(0);
    return s.buttons == 0x1 && s.position.x() == 1.0;
  }));

  // The device goes away in the middle of reading: every sample from then on is disconnected
  // with zero axes and no buttons, the first one included.
  transport.script(path, {ScriptStep::disconnect(), ScriptStep::report(kGenuine)});
  bool sawDisconnected = false;
  ASSERT_TRUE(waitFor([&] {
    const DeviceSample s = device.read(0);
    if (!s.connected) {
      sawDisconnected = true;
      EXPECT_EQ(s.position, Eigen::Vector3d::Zero());
      EXPECT_EQ(s.rotationRate, Eigen::Vector3d::Zero());
      EXPECT_EQ(s.buttons, 0u);
    }
    return sawDisconnected;
  }));
  ASSERT_TRUE(waitFor([&] { return !connected(manager, path); }));
  EXPECT_FALSE(find(manager, path)->lastError.empty());
  // Unplugged, it is not listed and not opened again.
  const uint64_t polls = manager.pollCount();
  ASSERT_TRUE(waitFor([&] { return manager.pollCount() >= polls + 2; }));
  EXPECT_EQ(transport.openCount(path), 1);
  EXPECT_FALSE(device.read(0).connected);

  // Plugged in again: open within two polls, same id, and the script goes on where it was.
  transport.replug(path);
  const uint64_t replugged = manager.pollCount();
  ASSERT_TRUE(waitFor([&] { return manager.pollCount() >= replugged + 2; }));
  EXPECT_TRUE(connected(manager, path));
  EXPECT_EQ(transport.openCount(path), 2);
  ASSERT_EQ(manager.devices().size(), 1u);
  ASSERT_TRUE(waitFor([&] { return std::abs(device.read(0).position.x() - kGenuineTx) < 1e-9; }));
  EXPECT_TRUE(device.read(0).connected);
  EXPECT_EQ(device.read(0).buttons, 0u);  // held buttons were dropped with the unplug
}

TEST(DeviceManager, ADeviceBackUnderAnotherPathKeepsItsId) {
  ScriptedTransport transport;
  transport.addDevice(spaceNavigator("/dev/hidraw1", 0x08, "SN123"));
  DeviceManager manager(transport, fastOptions());
  ASSERT_TRUE(waitFor([&] { return connected(manager, "/dev/hidraw1"); }));
  transport.unplug("/dev/hidraw1");
  ASSERT_TRUE(waitFor([&] { return !connected(manager, "/dev/hidraw1"); }));
  transport.addDevice(spaceNavigator("/dev/hidraw5", 0x08, "SN123"));
  ASSERT_TRUE(waitFor([&] { return connected(manager, "/dev/hidraw5"); }));
  const std::vector<ManagedDevice> devices = manager.devices();
  ASSERT_EQ(devices.size(), 1u);
  EXPECT_EQ(devices[0].id, 0);
  // Another serial is another device.
  transport.addDevice(spaceNavigator("/dev/hidraw6", 0x08, "SN999"));
  ASSERT_TRUE(waitFor([&] { return connected(manager, "/dev/hidraw6"); }));
  EXPECT_EQ(find(manager, "/dev/hidraw6")->id, 1);
}

TEST(DeviceManager, GarbageAndShortReportsAreCountedAndIgnored) {
  ScriptedTransport transport;
  transport.addDevice(spaceNavigator("/dev/hidraw1"));
  DeviceManager manager(transport, fastOptions());
  ASSERT_TRUE(waitFor([&] { return connected(manager, "/dev/hidraw1"); }));
  HidInputDevice device(manager, 0);
  ScriptStep garbage = ScriptStep::garbage(30, 1);
  garbage.bytes[0] = 0xEE;
  transport.script("/dev/hidraw1", {
                                       ScriptStep::report(kGenuine),
                                       ScriptStep::report({0x01, 0x76}),     // short
                                       ScriptStep::report(Bytes(20, 0x01)),  // over-long
                                       ScriptStep::report({0x05, 0x00}),     // unknown ID
                                       garbage,                              // noise, unknown ID
                                       ScriptStep::report({0x03}),           // short
                                       ScriptStep::report({0x03, 0x02}),
                                   });
  ASSERT_TRUE(waitFor([&] {
    const HidReportCounts c = manager.devices().at(0).counts;
    return c.decoded + c.ignored() == 7;
  }));
  const HidReportCounts counts = manager.devices().at(0).counts;
  EXPECT_EQ(counts.decoded, 2u);
  EXPECT_EQ(counts.truncated, 2u);
  EXPECT_EQ(counts.overLong, 1u);
  EXPECT_EQ(counts.unknownId, 2u);
  ASSERT_TRUE(waitFor([&] { return device.read(0).buttons == 0x2; }));
  EXPECT_NEAR(device.read(0).position.x(), kGenuineTx, 1e-9);
  EXPECT_TRUE(connected(manager, "/dev/hidraw1"));
}

TEST(DeviceManager, EveryTransportCallWritesIncludedIsFromTheManagerThread) {
  ScriptedTransport transport;
  transport.addDevice(spaceNavigator("/dev/hidraw1"));
  DeviceManager manager(transport, fastOptions());
  ASSERT_TRUE(waitFor([&] { return connected(manager, "/dev/hidraw1"); }));
  EXPECT_FALSE(manager.setLed(7, true));
  EXPECT_TRUE(manager.setLed(0, true));
  EXPECT_TRUE(manager.setLed(0, false));
  ASSERT_TRUE(waitFor([&] { return transport.sentReports().size() == 2; }));
  const std::vector<SentReport> sent = transport.sentReports();
  EXPECT_EQ(sent[0].bytes, (Bytes{0x04, 0x01}));
  EXPECT_EQ(sent[1].bytes, (Bytes{0x04, 0x00}));
  for (const SentReport& report : sent) {
    EXPECT_EQ(report.kind, SentReport::Kind::kOutput);
    EXPECT_EQ(report.path, "/dev/hidraw1");
    EXPECT_EQ(report.thread, manager.threadId());
    EXPECT_NE(report.thread, std::this_thread::get_id());
  }
  EXPECT_EQ(transport.callingThreads(), std::vector<std::thread::id>{manager.threadId()});
  ASSERT_TRUE(waitFor([&] { return manager.devices().at(0).outputsSent == 2; }));
}

TEST(DeviceManager, WriteFailuresAreCountedAndTheDeviceStays) {
  ScriptedTransport transport;
  transport.addDevice(spaceNavigator("/dev/hidraw1"));
  transport.failWrites("/dev/hidraw1", 1);
  DeviceManager manager(transport, fastOptions());
  ASSERT_TRUE(waitFor([&] { return connected(manager, "/dev/hidraw1"); }));
  manager.setLed(0, true);
  manager.setLed(0, true);
  ASSERT_TRUE(waitFor([&] {
    const ManagedDevice d = manager.devices().at(0);
    return d.outputsFailed == 1 && d.outputsSent == 1;
  }));
  EXPECT_TRUE(transport.sentReports().at(0).failed);
  EXPECT_FALSE(transport.sentReports().at(1).failed);
  EXPECT_TRUE(connected(manager, "/dev/hidraw1"));
}

TEST(DeviceManager, AFailedOpenIsListedWithItsReasonAndRetried) {
  ScriptedTransport transport;
  transport.addDevice(spaceNavigator("/dev/hidraw1"));
  transport.failOpens("/dev/hidraw1", 1, "Permission denied");
  DeviceManager manager(transport, fastOptions());
  ASSERT_TRUE(waitFor([&] { return !manager.devices().empty(); }));
  const ManagedDevice first = manager.devices().at(0);
  EXPECT_FALSE(first.connected);
  EXPECT_EQ(first.lastError, "Permission denied");
  EXPECT_EQ(first.profileName, "spacemouse-separate");
  ASSERT_TRUE(waitFor([&] { return connected(manager, "/dev/hidraw1"); }));
  EXPECT_EQ(manager.devices().at(0).lastError, "");
  EXPECT_EQ(transport.openCount("/dev/hidraw1"), 1);
}

TEST(DeviceManager, ForceOutputIsSentByTheManagerThread) {
  // A test device described by a user profile with a force output (IDs made up for the test).
  DeviceManagerOptions options = fastOptions();
  options.profiles.push_back(parseHidProfile(R"({"name": "test-force", "vendor_id": "f00d",
      "product_id": "0001",
      "axes": [{"report_id": 1, "byte_offset": 1, "target": "tx"}],
      "force_output": {"report_id": 6, "byte_offset": 1, "size": 2, "scale": 100,
                       "axes": ["fx", "fy", "fz"], "max_force": 3}})",
                                             "test-force.json"));
  ScriptedTransport transport;
  HidDeviceInfo info;
  info.path = "/dev/hidraw9";
  info.vendorId = 0xf00d;
  info.productId = 0x0001;
  transport.addDevice(info);
  DeviceManager manager(transport, options);
  ASSERT_TRUE(waitFor([&] { return connected(manager, "/dev/hidraw9"); }));
  EXPECT_EQ(manager.devices().at(0).profileName, "test-force");
  EXPECT_EQ(manager.devices().at(0).model, "test-force f00d:0001");
  HidInputDevice device(manager, 0);
  EXPECT_TRUE(device.info().hasForce());
  EXPECT_EQ(device.info().maxForce, 3.0);
  device.sendForce(Eigen::Vector3d(1.0, -2.0, 0.5));
  ASSERT_TRUE(waitFor([&] { return transport.sentReports().size() == 1; }));
  // 100, -200, 50 counts, int16 little-endian after the report ID.
  const SentReport sent = transport.sentReports().at(0);
  EXPECT_EQ(sent.bytes, (Bytes{0x06, 0x64, 0x00, 0x38, 0xFF, 0x32, 0x00}));
  EXPECT_EQ(sent.thread, manager.threadId());
  // Many requests in a row: only the newest need be sent, and it is.
  for (int i = 1; i <= 50; ++i) device.sendForce(Eigen::Vector3d(0.01 * i, 0, 0));
  ASSERT_TRUE(waitFor(
      [&] { return transport.sentReports().back().bytes == Bytes{0x06, 0x32, 0x00, 0, 0, 0, 0}; }));
  EXPECT_LE(transport.sentReports().size(), 51u);
  EXPECT_EQ(transport.callingThreads(), std::vector<std::thread::id>{manager.threadId()});
}

TEST(HidInputDevice, ASpaceMouseIsARateControllerWithoutForce) {
  ScriptedTransport transport;
  transport.addDevice(spaceNavigator("/dev/hidraw1"));
  DeviceManager manager(transport, fastOptions());
  ASSERT_TRUE(waitFor([&] { return connected(manager, "/dev/hidraw1"); }));
  HidInputDevice device(manager, 0);
  EXPECT_EQ(device.info().model, "SpaceNavigator");
  EXPECT_EQ(device.info().manufacturer, "3Dconnexion");
  EXPECT_EQ(device.info().capabilities,
            uint32_t{kSensesPosition | kSensesRotation | kSensesButtons | kRateControl});
  EXPECT_EQ(device.info().maxForce, 0.0);
  EXPECT_FALSE(device.info().hasForce());
  EXPECT_TRUE(device.info().rateControl());
  device.sendForce(Eigen::Vector3d(1, 2, 3));
  const uint64_t polls = manager.pollCount();
  ASSERT_TRUE(waitFor([&] { return manager.pollCount() >= polls + 2; }));
  EXPECT_TRUE(transport.sentReports().empty());
  EXPECT_THROW(HidInputDevice(manager, 5), std::invalid_argument);
}

TEST(HidInputDevice, ReadsDisconnectedOnceTheManagerIsGone) {
  ScriptedTransport transport;
  transport.addDevice(spaceNavigator("/dev/hidraw1"));
  std::unique_ptr<HidInputDevice> device;
  {
    DeviceManager manager(transport, fastOptions());
    ASSERT_TRUE(waitFor([&] { return connected(manager, "/dev/hidraw1"); }));
    device = std::make_unique<HidInputDevice>(manager, 0);
    transport.pushReport("/dev/hidraw1", kFullX);
    ASSERT_TRUE(waitFor([&] { return device->read(0).position.x() == 1.0; }));
  }
  const DeviceSample sample = device->read(0);
  EXPECT_FALSE(sample.connected);
  EXPECT_EQ(sample.position, Eigen::Vector3d::Zero());
}

TEST(DeviceManager, PlaysARecordingThroughTheReplayTransport) {
  ReplayTransport transport(SCULPT_SOURCE_DIR "/tests/data/hid/spacenavigator.txt");
  DeviceManager manager(transport, fastOptions());
  ASSERT_TRUE(waitFor([&] {
    const std::vector<ManagedDevice> devices = manager.devices();
    return devices.size() == 1 && !devices[0].connected &&
           devices[0].counts.decoded + devices[0].counts.ignored() == 8;
  }));
  const ManagedDevice device = manager.devices().at(0);
  EXPECT_EQ(device.counts.decoded, 6u);
  EXPECT_EQ(device.counts.truncated, 1u);
  EXPECT_EQ(device.counts.unknownId, 1u);
  EXPECT_EQ(device.model, "3Dconnexion SpaceNavigator");
  // Played out, the recording is gone: the manager does not open it again.
  const uint64_t polls = manager.pollCount();
  ASSERT_TRUE(waitFor([&] { return manager.pollCount() >= polls + 2; }));
  EXPECT_FALSE(manager.devices().at(0).connected);
}

}  // namespace
}  // namespace sculpt::haptics
