#pragma once
// Text drawn over the 3D view (a spring's force, a measurement) on a dark rounded backdrop, so
// that it reads on the light model as on the dark background, in the colour of what it labels.

#include <imgui.h>

namespace sculpt::app {

/// Draws `text` with its box's left edge at `anchor.x` + the gap, its middle at `anchor.y` (to
/// the right of a dot at `anchor` of radius `clearance`, never over it). Returns the box.
ImVec4 drawOverlayLabel(ImDrawList* draw, ImVec2 anchor, float clearance, ImU32 colour,
                        const char* text);

}  // namespace sculpt::app
