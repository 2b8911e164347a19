#include "haptics/mock/device_script.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace sculpt::haptics {
namespace {

using nlohmann::json;

json validScript() {
  return json::parse(R"({
    "version": 1, "model": "touch", "mode": "hand",
    "hand": {"stiffness": 300, "damping": 5, "mass": 0.1},
    "keys": [
      {"t": 0, "position": [0, 0, 0], "buttons": 0},
      {"t": 1, "position": [0.04, -0.02, 0.01], "buttons": 1, "clutch": true},
      {"t": 3, "position": [0.0, 0.02, 0.03], "buttons": 0}
    ]})");
}

std::string errorOf(const json& script) {
  try {
    parseDeviceScript(script);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(DeviceScript, ParsesEveryField) {
  const DeviceScript s = parseDeviceScript(validScript());
  EXPECT_EQ(s.model, PhantomModel::kTouch);
  EXPECT_EQ(s.mode, ScriptMode::kHand);
  EXPECT_EQ(s.hand.stiffness, 300.0);
  EXPECT_EQ(s.hand.damping, 5.0);
  EXPECT_EQ(s.hand.mass, 0.1);
  ASSERT_EQ(s.keys.size(), 3u);
  EXPECT_EQ(s.keys[1].position, Eigen::Vector3d(0.04, -0.02, 0.01));
  EXPECT_EQ(s.keys[1].buttons, 1u);
  EXPECT_TRUE(s.keys[1].clutch);
  EXPECT_FALSE(s.keys[0].clutch) << "clutch is optional, off by default";
  EXPECT_EQ(s.duration(), 3.0);

  json omni = validScript();
  omni["model"] = "omni";
  omni["mode"] = "trajectory";
  omni.erase("hand");
  const DeviceScript o = parseDeviceScript(omni);
  EXPECT_EQ(o.model, PhantomModel::kOmni);
  EXPECT_EQ(o.mode, ScriptMode::kTrajectory);
  EXPECT_EQ(phantomWorkspaceRadius(PhantomModel::kOmni), 0.10);
  EXPECT_EQ(phantomWorkspaceRadius(PhantomModel::kTouch), 0.075);
}

TEST(DeviceScript, InterpolatesPositionsAndHoldsButtonsAndClutch) {
  const DeviceScript s = parseDeviceScript(validScript());
  ScriptSample a = s.sample(0.25);
  EXPECT_DOUBLE_EQ(a.position.x(), 0.01);
  EXPECT_DOUBLE_EQ(a.position.y(), -0.005);
  EXPECT_DOUBLE_EQ(a.position.z(), 0.0025);
  EXPECT_EQ(a.buttons, 0u);
  EXPECT_FALSE(a.clutch);
  EXPECT_DOUBLE_EQ(a.velocity.x(), 0.04);
  EXPECT_DOUBLE_EQ(a.velocity.y(), -0.02);

  const ScriptSample atKey = s.sample(1.0);
  EXPECT_EQ(atKey.position, Eigen::Vector3d(0.04, -0.02, 0.01));
  EXPECT_EQ(atKey.buttons, 1u);
  EXPECT_TRUE(atKey.clutch);

  const ScriptSample b = s.sample(2.0);  // halfway between keys 1 and 2
  EXPECT_DOUBLE_EQ(b.position.x(), 0.02);
  EXPECT_NEAR(b.position.y(), 0.0, 1e-17);
  EXPECT_DOUBLE_EQ(b.position.z(), 0.02);
  EXPECT_EQ(b.buttons, 1u) << "held until the next key";
  EXPECT_TRUE(b.clutch);
  EXPECT_DOUBLE_EQ(b.velocity.y(), 0.02);

  const ScriptSample before = s.sample(-1.0), after = s.sample(10.0);
  EXPECT_EQ(before.position, Eigen::Vector3d::Zero());
  EXPECT_EQ(after.position, Eigen::Vector3d(0.0, 0.02, 0.03));
  EXPECT_EQ(after.velocity, Eigen::Vector3d::Zero()) << "held after the end";
  EXPECT_EQ(after.buttons, 0u);
  EXPECT_FALSE(after.clutch);
  EXPECT_EQ(s.sample(std::numeric_limits<double>::quiet_NaN()).position, Eigen::Vector3d::Zero());
}

TEST(DeviceScript, KeysAtTheSameTimeMakeAStep) {
  json j = validScript();
  j["keys"][2]["t"] = 1;  // keys 1 and 2 both at 1 s: from there on, key 2
  const DeviceScript s = parseDeviceScript(j);
  EXPECT_EQ(s.sample(1.0).position, Eigen::Vector3d(0.0, 0.02, 0.03));
  EXPECT_EQ(s.sample(1.0).buttons, 0u);
  EXPECT_DOUBLE_EQ(s.sample(0.5).position.x(), 0.02);
}

TEST(DeviceScript, ErrorsNameTheFieldAndTheKey) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  struct Case {
    std::function<void(json&)> edit;
    std::string expected;
  };
  const Case cases[] = {
      {[](json& j) { j = json::array(); }, "a device script must be a JSON object"},
      {[](json& j) { j.erase("version"); }, "missing field \"version\""},
      {[](json& j) { j["version"] = 2; }, "\"version\" must be 1, got 2"},
      {[](json& j) { j["colour"] = 1; }, "unknown field \"colour\""},
      {[](json& j) { j.erase("model"); }, "missing field \"model\""},
      {[](json& j) { j["model"] = "falcon"; },
       "\"model\" must be \"touch\" or \"omni\", got \"falcon\""},
      {[](json& j) { j["mode"] = "dance"; },
       "\"mode\" must be \"trajectory\" or \"hand\", got \"dance\""},
      {[](json& j) { j.erase("hand"); }, "missing field \"hand\""},
      {[](json& j) { j["hand"]["stiffness"] = 2500; },
       "\"hand.stiffness\" must be a finite number in (0, 2000] N/m, got 2500"},
      {[](json& j) { j["hand"]["stiffness"] = 0; }, "\"hand.stiffness\" must be"},
      {[&](json& j) { j["hand"]["damping"] = -1; }, "\"hand.damping\" must be"},
      {[](json& j) { j["hand"].erase("mass"); }, "missing field \"hand.mass\""},
      {[](json& j) { j["hand"]["mass"] = 0.001; }, "\"hand.mass\" must be"},
      {[](json& j) { j["hand"]["mass"] = "heavy"; }, "\"hand.mass\" must be a finite number"},
      {[](json& j) { j.erase("keys"); }, "missing field \"keys\""},
      {[](json& j) { j["keys"] = json::array(); }, "\"keys\" must be a non-empty array"},
      {[](json& j) { j["keys"][1] = 5; }, "\"keys[1]\" must be an object"},
      {[](json& j) { j["keys"][1].erase("t"); }, "missing field \"keys[1].t\""},
      {[](json& j) { j["keys"][1]["t"] = -0.5; },
       "\"keys[1].t\" must be a finite number in [0, inf) s, got -0.5"},
      {[&](json& j) { j["keys"][1]["t"] = nan; }, "\"keys[1].t\" must be a finite number"},
      {[](json& j) { j["keys"][2]["t"] = 0.5; },
       "\"keys[2].t\" (0.5 s) is before \"keys[1].t\" (1 s): keys must be sorted by time"},
      {[](json& j) { j["keys"][1].erase("position"); }, "missing field \"keys[1].position\""},
      {[](json& j) {
         j["keys"][1]["position"] = {0.0, 0.0};
       },
       "\"keys[1].position\" must be an array of 3 finite numbers (m)"},
      {[&](json& j) { j["keys"][1]["position"][2] = inf; },
       "\"keys[1].position\" must be an array of 3 finite numbers (m), got inf"},
      {[](json& j) {
         j["keys"][2]["position"] = {0.2, 0.0, 0.0};
       },
       "\"keys[2].position\" is 0.2 m from the workspace centre, more than twice the touch's "
       "workspace radius (0.15 m)"},
      {[](json& j) { j["keys"][0].erase("buttons"); }, "missing field \"keys[0].buttons\""},
      {[](json& j) { j["keys"][0]["buttons"] = -1; }, "\"keys[0].buttons\" must be an integer"},
      {[](json& j) { j["keys"][0]["buttons"] = 1.5; }, "\"keys[0].buttons\" must be an integer"},
      {[](json& j) { j["keys"][0]["clutch"] = "yes"; },
       "\"keys[0].clutch\" must be true or false, got \"yes\""},
      {[](json& j) { j["keys"][1]["clutsh"] = true; }, "keys[1]: unknown field \"clutsh\""},
  };
  for (const Case& c : cases) {
    json j = validScript();
    c.edit(j);
    const std::string message = errorOf(j);
    EXPECT_NE(message.find(c.expected), std::string::npos)
        << "expected \"" << c.expected << "\" in: " << message;
  }
  // 0.2 m is inside twice the Omni's radius.
  json omni = validScript();
  omni["model"] = "omni";
  omni["keys"][2]["position"] = {0.2, 0.0, 0.0};
  EXPECT_NO_THROW(parseDeviceScript(omni));
}

TEST(DeviceScript, RejectsMoreThanTheKeyLimit) {
  json j = validScript();
  // The count is checked before the keys themselves.
  j["keys"] = json::array();
  for (size_t i = 0; i <= DeviceScript::kMaxKeys; ++i) j["keys"].push_back(0);
  const std::string message = errorOf(j);
  EXPECT_NE(message.find("\"keys\" has 100001 keys, more than the 100000 allowed"),
            std::string::npos)
      << message;
}

TEST(DeviceScript, LoadsAFileAndPrefixesItsErrorsWithTheFileName) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("device_script_test_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const auto write = [&](const char* name, const std::string& text) {
    const std::filesystem::path path = dir / name;
    std::ofstream(path) << text;
    return path;
  };
  const auto errorLoading = [](const std::filesystem::path& path) -> std::string {
    try {
      loadDeviceScript(path);
    } catch (const std::runtime_error& e) {
      return e.what();
    }
    return "(no error)";
  };

  const auto good = write("good.json", validScript().dump(2));
  EXPECT_EQ(loadDeviceScript(good).keys.size(), 3u);

  const auto broken = write("broken.json", "{\"version\": 1,");
  EXPECT_EQ(errorLoading(broken).rfind(broken.string() + ": not valid JSON", 0), 0u)
      << errorLoading(broken);

  json wrong = validScript();
  wrong["model"] = "falcon";
  const auto bad = write("bad.json", wrong.dump());
  EXPECT_EQ(errorLoading(bad),
            bad.string() + ": \"model\" must be \"touch\" or \"omni\", got \"falcon\"");

  const auto missing = dir / "missing.json";
  EXPECT_EQ(errorLoading(missing),
            missing.string() + ": cannot open (No such file or directory) (the device script)");
  std::filesystem::remove_all(dir);
}

TEST(DeviceScript, TheShippedScriptsLoadWithTheirToolsAndAForeignFormatIsRefused) {
  const std::filesystem::path assets = std::filesystem::path(SCULPT_SOURCE_DIR) / "assets";
  const DeviceScript pull = loadDeviceScript(assets / "device_pull.json");
  EXPECT_EQ(pull.tool, "pull");
  EXPECT_EQ(pull.mode, ScriptMode::kHand);
  EXPECT_NEAR(pull.duration(), 3.6, 1e-12);
  EXPECT_EQ(pull.sample(1.0).buttons, 1u) << "the button is held while pulling";
  const DeviceScript probe = loadDeviceScript(assets / "device_probe.json");
  EXPECT_EQ(probe.tool, "probe");
  for (const ScriptKey& key : probe.keys) EXPECT_EQ(key.buttons, 0u) << "probed with the button up";
  nlohmann::json bad = {{"format", "sculpt-session"},
                        {"version", 1},
                        {"model", "touch"},
                        {"mode", "trajectory"},
                        {"keys", {{{"t", 0}, {"position", {0, 0, 0}}, {"buttons", 0}}}}};
  EXPECT_THROW(parseDeviceScript(bad), std::runtime_error);
  bad["format"] = "sculpt-device-script";
  EXPECT_NO_THROW(parseDeviceScript(bad));
  bad["tool"] = "hammer";
  EXPECT_THROW(parseDeviceScript(bad), std::runtime_error);
}

}  // namespace
}  // namespace sculpt::haptics
