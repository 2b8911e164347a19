#include "haptics/mock/device_script.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <initializer_list>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

#include "haptics/servo/haptic_tool.h"
#include "io/file_error.h"
#include "io/input_file.h"
#include "io/json_fields.h"

namespace sculpt::haptics {
namespace {

using nlohmann::json;

/// The pieces of a message, appended in order.
template <typename... Parts>
std::string cat(const Parts&... parts) {
  std::string text;
  ((text += parts), ...);
  return text;
}

template <typename... Parts>
[[noreturn]] void fail(const Parts&... parts) {
  throw std::runtime_error(cat(parts...));
}

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

std::string quoted(const std::string& name) { return cat("\"", name, "\""); }

/// Rejects fields outside `known` (a misspelt "clutch" would otherwise be ignored silently).
void onlyKnownFields(const json& object, const std::string& where,
                     std::initializer_list<const char*> known) {
  if (const std::optional<std::string> unknown = unknownJsonField(object, known))
    fail(where.empty() ? std::string() : cat(where, ": "), "unknown field ", quoted(*unknown),
         " (expected ", jsonFieldList(known), ")");
}

const json& required(const json& object, const char* key, const std::string& path,
                     const std::string& what) {
  const auto it = object.find(key);
  if (it == object.end()) fail("missing field ", quoted(path), " (", what, ")");
  return *it;
}

double finiteNumber(const json& value, const std::string& path, const std::string& what) {
  if (!value.is_number()) fail(quoted(path), " must be ", what, ", got ", value.dump());
  const double x = value.get<double>();
  if (!std::isfinite(x)) fail(quoted(path), " must be ", what, ", got ", number(x));
  return x;
}

/// A finite number in [low, high] (or (low, high] when lowOpen; high may be infinite), with
/// `unit` for the message.
double numberIn(const json& object, const char* key, const std::string& path, double low,
                double high, bool lowOpen, const char* unit) {
  const std::string what =
      cat("a finite number in ", lowOpen ? "(" : "[", number(low), ", ",
          std::isfinite(high) ? cat(number(high), "]") : std::string("inf)"), " ", unit);
  const double x = finiteNumber(required(object, key, path, what), path, what);
  if (x < low || (lowOpen && x == low) || x > high)
    fail(quoted(path), " must be ", what, ", got ", number(x));
  return x;
}

/// A string field's value, or the JSON text of what stands there instead (for the message).
std::string choice(const json& value) {
  return value.is_string() ? value.get<std::string>() : value.dump();
}
std::string shown(const json& value) {
  return value.is_string() ? quoted(value.get<std::string>()) : value.dump();
}

PhantomModel parseModel(const json& script) {
  const json& value = required(script, "model", "model", "\"touch\" or \"omni\"");
  const std::string name = choice(value);
  if (name == "touch") return PhantomModel::kTouch;
  if (name == "omni") return PhantomModel::kOmni;
  fail("\"model\" must be \"touch\" or \"omni\", got ", shown(value));
}

ScriptMode parseMode(const json& script) {
  const json& value = required(script, "mode", "mode", "\"trajectory\" or \"hand\"");
  const std::string name = choice(value);
  if (name == "trajectory") return ScriptMode::kTrajectory;
  if (name == "hand") return ScriptMode::kHand;
  fail("\"mode\" must be \"trajectory\" or \"hand\", got ", shown(value));
}

HandDynamics parseHand(const json& hand) {
  if (!hand.is_object()) fail("\"hand\" must be an object with stiffness, damping and mass");
  onlyKnownFields(hand, "hand", {"stiffness", "damping", "mass"});
  constexpr double kInf = INFINITY;
  HandDynamics h;
  h.stiffness = numberIn(hand, "stiffness", "hand.stiffness", 0.0, DeviceScript::kMaxHandStiffness,
                         true, "N/m");
  h.damping = numberIn(hand, "damping", "hand.damping", 0.0, kInf, false, "N s/m");
  h.mass = numberIn(hand, "mass", "hand.mass", DeviceScript::kMinHandMass, kInf, false, "kg");
  return h;
}

ScriptKey parseKey(const json& key, size_t index, double workspaceRadius, PhantomModel model) {
  const std::string at = cat("keys[", std::to_string(index), "]");
  if (!key.is_object()) fail(quoted(at), " must be an object with t, position and buttons");
  onlyKnownFields(key, at, {"t", "position", "buttons", "clutch"});
  ScriptKey k;
  k.t = numberIn(key, "t", cat(at, ".t"), 0.0, INFINITY, false, "s");

  const std::string positionPath = cat(at, ".position");
  const std::string positionWhat = "an array of 3 finite numbers (m)";
  const json& position = required(key, "position", positionPath, positionWhat);
  if (!position.is_array() || position.size() != 3)
    fail(quoted(positionPath), " must be ", positionWhat, ", got ", position.dump());
  for (int i = 0; i < 3; ++i)
    k.position[i] = finiteNumber(position[static_cast<size_t>(i)], positionPath, positionWhat);
  if (k.position.norm() > 2.0 * workspaceRadius)
    fail(quoted(positionPath), " is ", number(k.position.norm()),
         " m from the workspace centre, more than twice the ", phantomModelName(model),
         "'s workspace radius (", number(2.0 * workspaceRadius), " m)");

  const std::string buttonsPath = cat(at, ".buttons");
  const std::string buttonsWhat = "an integer in [0, 4294967295] (bit 0: the stylus button)";
  const json& buttons = required(key, "buttons", buttonsPath, buttonsWhat);
  const bool negative =
      buttons.is_number_integer() && !buttons.is_number_unsigned() && buttons.get<int64_t>() < 0;
  if (!buttons.is_number_integer() || negative || buttons.get<uint64_t>() > 0xffffffffu)
    fail(quoted(buttonsPath), " must be ", buttonsWhat, ", got ", buttons.dump());
  k.buttons = static_cast<uint32_t>(buttons.get<uint64_t>());

  if (const auto clutch = key.find("clutch"); clutch != key.end()) {
    if (!clutch->is_boolean())
      fail(quoted(cat(at, ".clutch")), " must be true or false, got ", clutch->dump());
    k.clutch = clutch->get<bool>();
  }
  return k;
}

}  // namespace

double phantomWorkspaceRadius(PhantomModel model) {
  return model == PhantomModel::kOmni ? 0.10 : 0.075;
}

const char* phantomModelName(PhantomModel model) {
  return model == PhantomModel::kOmni ? "omni" : "touch";
}

double DeviceScript::duration() const { return keys.empty() ? 0.0 : keys.back().t; }

ScriptSample DeviceScript::sample(double t) const {
  ScriptSample s;
  if (keys.empty()) return s;
  // The first key with a later time; the one before it holds at t.
  const auto next = std::upper_bound(keys.begin(), keys.end(), t,
                                     [](double time, const ScriptKey& k) { return time < k.t; });
  if (next == keys.begin() || !(t >= keys.front().t)) {  // before the first key (or t is NaN)
    s.position = keys.front().position;
    s.buttons = keys.front().buttons;
    s.clutch = keys.front().clutch;
    return s;
  }
  const ScriptKey& from = *(next - 1);
  s.position = from.position;
  s.buttons = from.buttons;
  s.clutch = from.clutch;
  if (next != keys.end()) {
    const double span = next->t - from.t;  // > 0: from.t <= t < next->t
    s.velocity = (next->position - from.position) / span;
    s.position = from.position + (t - from.t) / span * (next->position - from.position);
  }
  return s;
}

DeviceScript parseDeviceScript(const nlohmann::json& script) {
  if (!script.is_object()) fail("a device script must be a JSON object, got ", script.dump());
  onlyKnownFields(script, "",
                  {"format", "version", "model", "mode", "tool", "description", "hand", "keys"});
  if (const auto format = script.find("format");
      format != script.end() && *format != "sculpt-device-script")
    fail("\"format\" must be \"sculpt-device-script\", got ", format->dump());
  const json& version = required(script, "version", "version", "must be 1");
  if (!version.is_number_integer() || version.get<int64_t>() != 1)
    fail("\"version\" must be 1, got ", version.dump());

  DeviceScript result;
  if (const auto tool = script.find("tool"); tool != script.end()) {
    if (!tool->is_string() || !hapticToolNamed(tool->get<std::string>()))
      fail("\"tool\" must be \"pull\", \"probe\", \"paint\" or \"inflate\", got ", tool->dump());
    result.tool = tool->get<std::string>();
  }
  result.model = parseModel(script);
  result.mode = parseMode(script);
  if (const auto hand = script.find("hand"); hand != script.end())
    result.hand = parseHand(*hand);
  else if (result.mode == ScriptMode::kHand)
    fail("missing field \"hand\" (mode \"hand\" needs the hand's stiffness, damping and mass)");

  const json& keys = required(script, "keys", "keys", "an array of keys sorted by t");
  if (!keys.is_array() || keys.empty())
    fail("\"keys\" must be a non-empty array of keys sorted by t, got ", keys.dump());
  if (keys.size() > DeviceScript::kMaxKeys)
    fail("\"keys\" has ", std::to_string(keys.size()), " keys, more than the ",
         std::to_string(DeviceScript::kMaxKeys), " allowed");
  const double radius = phantomWorkspaceRadius(result.model);
  result.keys.reserve(keys.size());
  for (size_t i = 0; i < keys.size(); ++i) {
    result.keys.push_back(parseKey(keys[i], i, radius, result.model));
    if (i > 0 && result.keys[i].t < result.keys[i - 1].t)
      fail("\"keys[", std::to_string(i), "].t\" (", number(result.keys[i].t),
           " s) is before \"keys[", std::to_string(i - 1), "].t\" (", number(result.keys[i - 1].t),
           " s): keys must be sorted by time");
  }
  return result;
}

DeviceScript loadDeviceScript(const std::filesystem::path& path) {
  const std::string file = path.string();
  std::string text;
  try {
    text = readInputFile(path, kDeviceScriptInput);
  } catch (const FileError& e) {  // "<file>: is a FIFO ...", "<file>: cannot open (...)"
    fail(e.what(), " (the device script)");
  }
  json script;
  try {
    script = json::parse(text);
  } catch (const json::parse_error& e) {
    fail(file, ": not valid JSON (", e.what(), ")");
  }
  try {
    return parseDeviceScript(script);
  } catch (const std::runtime_error& e) {
    fail(file, ": ", e.what());
  }
}

}  // namespace sculpt::haptics
