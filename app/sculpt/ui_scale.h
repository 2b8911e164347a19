#pragma once
// HiDPI (docs/design/ux.md, Feedback): one UI scale from the monitor's content scale
// (glfwGetWindowContentScale) or the user's saved override, applied by loading the font at the
// scaled size and scaling the style's sizes (sharper than ImGui's FontGlobalScale).

namespace sculpt::app {

/// The UI scale: userOverride when it is positive, else the larger content scale rounded to a
/// multiple of 0.25; either way clamped to [1, 3]. Content scales that are not positive and
/// finite (some platforms report 0) count as 1. Throws std::invalid_argument for a negative or
/// non-finite override.
float uiScale(float contentScaleX, float contentScaleY, float userOverride = 0.0f);

/// Rebuilds ImGui's font atlas with the default font at 13 * scale pixels and resets the style to
/// StyleColorsDark scaled by `scale`. With the OpenGL 3 backend initialised it also re-uploads the
/// font texture (needs the GL context current). Call between frames (not between NewFrame and
/// Render). Throws std::invalid_argument for a scale outside [0.5, 4] and std::logic_error without
/// an ImGui context.
void applyUiScale(float scale);

}  // namespace sculpt::app
