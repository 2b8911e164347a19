#pragma once
// The help overlay (`?` or F1, docs/design/ux.md Navigation): the mouse gestures of the current
// navigation preset and every key binding of the key map, grouped View / Simulation / Display /
// File.

#include <string>
#include <vector>

#include "sculpt/navigation.h"

namespace sculpt::app {

struct GestureHelp {
  std::string gesture;  ///< "Shift + middle drag"
  std::string effect;   ///< "Pan"
};

/// The mouse gestures of a preset, as the overlay lists them (mirrors Navigator's rules).
std::vector<GestureHelp> gestureHelp(NavigationPreset preset);

/// Draws the help window centred over the main viewport's work area while *open is true; its
/// close button or Escape (while it has focus) set *open to false. Call between ImGui::NewFrame
/// and ImGui::Render. open == nullptr draws nothing.
void drawHelpOverlay(const KeyMap& keys, NavigationPreset preset, bool* open);

}  // namespace sculpt::app
