#pragma once
// The window's panels (Dear ImGui 1.86, no docking), placed from the main viewport's work area:
// the main menu bar, the left tool panel, the right panel (scene, material, simulation, display),
// the bottom strip (play/pause/step/reset and the status), the build progress with Cancel and the
// toasts. The 3D view is the rectangle left between them.

#include <imgui.h>

#include "sculpt/app_model.h"

namespace sculpt::app {

struct ViewRect {
  ImVec2 min, max;  ///< ImGui coordinates (logical pixels, y down)
};

/// Draws every panel for this frame and returns the 3D view's rectangle. With
/// model.showPanels false only the menu bar is drawn and the view fills the rest.
ViewRect drawPanels(AppModel& model);

/// The progress of a build (stage, bar, Cancel) centred in the view; nothing when none runs.
void drawBuildProgress(AppModel& model, ViewRect view);
/// Short messages in the top right corner of the view, dropped when they expire.
void drawToasts(AppModel& model, ViewRect view);

}  // namespace sculpt::app
