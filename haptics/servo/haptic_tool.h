#pragma once
// The tools a stylus drives, and the names users give them (device scripts, --tool).

#include <optional>
#include <string_view>

namespace sculpt::haptics {

enum class HapticTool { None, Pull, Probe, Inflate };

struct NamedHapticTool {
  HapticTool tool = HapticTool::None;
  bool paint = false;  ///< a probe that paints while the button is held ("paint")
};

/// "pull", "probe", "paint" or "inflate"; nullopt for anything else.
inline std::optional<NamedHapticTool> hapticToolNamed(std::string_view name) {
  if (name == "pull") return NamedHapticTool{HapticTool::Pull, false};
  if (name == "probe") return NamedHapticTool{HapticTool::Probe, false};
  if (name == "paint") return NamedHapticTool{HapticTool::Probe, true};
  if (name == "inflate") return NamedHapticTool{HapticTool::Inflate, false};
  return std::nullopt;
}

}  // namespace sculpt::haptics
