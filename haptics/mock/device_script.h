#pragma once
// What the mock PHANTOM does, as a JSON script, so that tests and demos can drive the whole
// haptic path without hardware:
//
//   { "version": 1, "model": "touch" | "omni", "mode": "trajectory" | "hand",
//     "hand": { "stiffness": N/m, "damping": N s/m, "mass": kg },      (needed in hand mode)
//     "keys": [ { "t": s, "position": [x, y, z], "buttons": int, "clutch": bool }, ... ] }
//
// Positions are device metres in the device frame (x right, y up, z towards the user, origin at
// the workspace centre). Keys are sorted by time; the position is interpolated linearly between
// keys, buttons (bit 0: the stylus button) and the optional clutch are held from a key to the
// next, and everything is held before the first key and after the last. In "trajectory" mode the
// device goes exactly where the script says; in "hand" mode the script is where a hand pulls the
// stylus (haptics/mock/mock_phantom.h).

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <nlohmann/json_fwd.hpp>

namespace sculpt::haptics {

enum class PhantomModel { kTouch, kOmni };

/// The radius of the largest sphere inside the model's workspace (m): Touch 0.075, Omni 0.10.
double phantomWorkspaceRadius(PhantomModel model);
/// "touch" or "omni".
const char* phantomModelName(PhantomModel model);

enum class ScriptMode { kTrajectory, kHand };

/// The hand holding the stylus: a mass pulled by a spring and a damper towards where the hand
/// means to be.
struct HandDynamics {
  double stiffness = 300.0;  ///< N/m, (0, 2000]
  double damping = 5.0;      ///< N s/m, >= 0, on the velocity relative to the hand's target
  double mass = 0.1;         ///< kg, hand and moving parts together, >= 0.01
};

struct ScriptKey {
  double t = 0.0;  ///< s, >= 0
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  uint32_t buttons = 0;
  bool clutch = false;
};

/// The script at one time.
struct ScriptSample {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();  ///< m/s, the slope between the keys
  uint32_t buttons = 0;
  bool clutch = false;
};

struct DeviceScript {
  static constexpr size_t kMaxKeys = 100000;
  static constexpr double kMaxHandStiffness = 2000.0;  // N/m
  static constexpr double kMinHandMass = 0.01;         // kg

  PhantomModel model = PhantomModel::kTouch;
  /// The tool the stylus drives ("pull", "probe", "paint", "inflate"); empty: the caller's.
  std::string tool;
  ScriptMode mode = ScriptMode::kTrajectory;
  HandDynamics hand;
  std::vector<ScriptKey> keys;  ///< sorted by t

  /// The time of the last key (s; 0 without keys).
  double duration() const;
  ScriptSample sample(double t) const;
};

/// Checks and reads a script; throws std::runtime_error with one sentence naming the field (and
/// the key's index) that is wrong.
DeviceScript parseDeviceScript(const nlohmann::json& json);
/// The same from a file; the message starts with "<file>: ".
DeviceScript loadDeviceScript(const std::filesystem::path& path);

}  // namespace sculpt::haptics
