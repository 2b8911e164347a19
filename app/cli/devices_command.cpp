// sculpt-cli devices [--profile P.json]...: the HID devices hidapi finds and the profile each
// would be decoded with. sculpt-cli devices --replay FILE [--profile P.json] [--raw]: a
// hid-recorder recording decoded report by report, as the device manager decodes a device.

#include <cstdio>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "cli/cli_args.h"
#include "cli/cli_common.h"
#include "cli/commands.h"
#include "haptics/hid/device_manager.h"
#include "haptics/hid/hid_profile.h"
#include "haptics/hid/hid_recording.h"
#include "haptics/hid/hidapi_transport.h"
#include "haptics/hid/spacemouse.h"

namespace sculpt::cli {

const char* const kDevicesUsage =
    "  devices [--profile P.json]...\n"
    "      Lists the HID devices hidapi finds, one per line:\n"
    "      '<vid>:<pid> path=<path> usage=<page>/<usage> profile=<name|none> model=\"<name>\"',\n"
    "      then devices=<n> (0 is normal without devices or read access). A device has a\n"
    "      profile when it is a known SpaceMouse on its multi-axis interface or matches a\n"
    "      --profile file (docs/hid-devices.md, also for the udev rules that give access).\n"
    "  devices --replay FILE [--profile P.json] [--raw]\n"
    "      Decodes a hid-recorder recording as the device manager would, one line per decoded\n"
    "      report: 't=<s> tx=.. ty=.. tz=.. rx=.. ry=.. rz=.. buttons=0x..' (axes normalised to\n"
    "      [-1, 1], dead zone applied; ' battery=<%>' once the device has said), or with --raw\n"
    "      't=<s> raw=<the device's counts in report order> buttons=0x..'. Reports that do not\n"
    "      fit the profile are ignored, the first few named on stderr. Last line:\n"
    "      reports=<n> decoded=<n> ignored=<n>. The profile is the built-in SpaceMouse one\n"
    "      for a known ID on the recording's I: line unless --profile gives one; no profile, a\n"
    "      malformed recording or profile: one error line naming the file (exit 2).\n";

namespace {

using haptics::HidDeviceInfo;
using haptics::HidInputState;
using haptics::HidProfile;
using haptics::HidRecording;
using haptics::HidReportDecoder;
using haptics::ReportOutcome;

constexpr int kMaxIgnoredNotes = 10;

std::string idText(uint16_t vendorId, uint16_t productId) {
  char text[16];
  std::snprintf(text, sizeof text, "%04x:%04x", vendorId, productId);
  return text;
}

const char* outcomeName(ReportOutcome outcome) {
  switch (outcome) {
    case ReportOutcome::kDecoded:
      return "decoded";
    case ReportOutcome::kTruncated:
      return "truncated";
    case ReportOutcome::kOverLong:
      return "over-long";
    case ReportOutcome::kUnknownId:
      return "unknown report ID";
  }
  return "?";
}

std::vector<HidProfile> loadProfiles(const CliArgs& args) {
  std::vector<HidProfile> profiles;
  for (const std::string& file : args.values("profile"))
    profiles.push_back(haptics::loadHidProfile(file));
  return profiles;
}

int listDevices(const CliArgs& args) {
  const std::vector<HidProfile> profiles = loadProfiles(args);
  haptics::HidapiTransport transport;
  const std::vector<HidDeviceInfo> devices = transport.enumerate();
  for (const HidDeviceInfo& device : devices) {
    const auto match = haptics::matchProfile(device, profiles);
    char usage[32];
    std::snprintf(usage, sizeof usage, "0x%02x/0x%02x", device.usagePage, device.usage);
    std::cout << idText(device.vendorId, device.productId) << " path=" << device.path
              << " usage=" << usage << " profile=" << (match ? match->profileName : "none")
              << " model=\"" << device.product << "\"\n";
  }
  std::cout << "devices=" << devices.size() << '\n';
  return kExitSuccess;
}

void printState(double time, const HidInputState& state, bool raw) {
  char line[256];
  std::snprintf(line, sizeof line, "t=%.6f", time);
  std::string text = line;
  if (raw) {
    text += " raw=";
    for (size_t i = 0; i < state.rawCount; ++i) {
      if (i > 0) text += ',';
      text += std::to_string(state.raw[i]);
    }
  } else {
    const auto& t = state.translation;
    const auto& r = state.rotation;
    std::snprintf(line, sizeof line, " tx=%.4f ty=%.4f tz=%.4f rx=%.4f ry=%.4f rz=%.4f", t[0], t[1],
                  t[2], r[0], r[1], r[2]);
    text += line;
  }
  std::snprintf(line, sizeof line, " buttons=0x%x", state.buttons);
  text += line;
  if (state.batteryPercent >= 0) text += " battery=" + std::to_string(state.batteryPercent);
  std::cout << text << '\n';
}

int replayDevice(const CliArgs& args, const std::string& file) {
  const HidRecording recording = haptics::loadHidRecording(file);
  std::unique_ptr<HidReportDecoder> decoder;
  if (args.has("profile")) {
    if (args.values("profile").size() > 1) throw UsageError("--replay decodes with one --profile");
    decoder = std::make_unique<haptics::ProfileDecoder>(
        haptics::loadHidProfile(args.requiredValue("profile")));
  } else if (const auto layout =
                 haptics::documentedLayout(recording.vendorId, recording.productId)) {
    decoder = std::make_unique<haptics::SpaceMouseDecoder>(haptics::SpaceMouseOptions{}, layout);
  } else {
    return printError(file + ": no profile for device " +
                      idText(recording.vendorId, recording.productId) +
                      " (not a known SpaceMouse; give one with --profile P.json)");
  }
  decoder->connect();
  const bool raw = args.has("raw");
  int notes = 0;
  for (size_t i = 0; i < recording.events.size(); ++i) {
    const haptics::HidRecordedEvent& event = recording.events[i];
    const ReportOutcome outcome = decoder->decode(event.bytes, event.time);
    if (outcome == ReportOutcome::kDecoded) {
      printState(event.time, decoder->state(), raw);
    } else if (notes++ < kMaxIgnoredNotes) {
      char where[96];
      std::snprintf(where, sizeof where, "report %zu (t=%.6f, %zu bytes, ID %d)", i + 1, event.time,
                    event.bytes.size(), int{event.bytes[0]});
      std::cerr << "devices: " << where << " ignored: " << outcomeName(outcome) << '\n';
    }
  }
  const haptics::HidReportCounts& counts = decoder->state().counts;
  if (counts.ignored() > 0)
    std::cerr << "devices: ignored " << counts.truncated << " truncated, " << counts.overLong
              << " over-long, " << counts.unknownId << " with an unknown report ID\n";
  std::cout << "reports=" << recording.events.size() << " decoded=" << counts.decoded
            << " ignored=" << counts.ignored() << '\n';
  return kExitSuccess;
}

int devicesCommand(const CliArgs& args, std::string& file) {
  if (args.has("help")) {
    std::cout << "usage:\n" << kDevicesUsage;
    return kExitSuccess;
  }
  if (!args.positional().empty())
    throw UsageError("devices takes no file; use --replay FILE for a recording (see --help)");
  if (!args.has("replay")) {
    if (args.has("raw")) throw UsageError("--raw is for --replay");
    return listDevices(args);
  }
  file = args.requiredValue("replay");
  return replayDevice(args, file);
}

}  // namespace

int runDevicesCommand(const std::vector<std::string>& args) {
  std::string file;
  return runGuarded(file, [&] {
    const std::vector<OptionSpec> specs = {
        {"replay", true}, {"profile", true}, {"raw", false}, {"help", false}};
    return devicesCommand(CliArgs::parse(args, specs), file);
  });
}

}  // namespace sculpt::cli
