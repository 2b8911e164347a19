#pragma once
// The Display panel's state saved with a project, as its tool settings ("display.field", ...;
// docs/file-formats.md lists the keys), like the tools' state (tool_state.h): a view setting,
// never an undo entry.

#include "project/project.h"
#include "sculpt/display_settings.h"

namespace sculpt::app {

/// Writes every field of `display` under a "display." key of `settings`.
void storeDisplayState(const DisplaySettings& display, ToolSettings& settings);

/// The display state of `settings`: keys missing or of the wrong kind, and unknown names, keep
/// the defaults; out-of-range numbers are clamped (a non-finite one keeps the default).
DisplaySettings loadDisplayState(const ToolSettings& settings);

/// A project's display with the command line's switches on top: each field that `commandLine`
/// sets away from its default (--field youngs, --clip x, --wireframe ...) wins over `saved`.
DisplaySettings withCommandLineDisplay(DisplaySettings saved, const DisplaySettings& commandLine);

}  // namespace sculpt::app
