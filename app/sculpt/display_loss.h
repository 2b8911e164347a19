#pragma once
// Losing the display (the X server ends, a forwarded session drops, a test's Xvfb is killed) is
// noticed inside whatever X call the UI thread makes next. Xlib's default handler then calls
// exit(), which runs static destructors while the simulation and builder threads still use
// them: the program could hang instead of ending, and unsaved work was lost. This handler keeps
// the unsaved work first, says what happened and ends the process at once (no destructors).

namespace sculpt::app {

/// The exit status after a lost display (Xlib's default handler used the same).
constexpr int kDisplayLostExitStatus = 1;

/// Installs the handler. `keepWork(context)` runs on the UI thread, inside the X call that found
/// the connection gone, between two frames' updates of the document; it must not call GLFW or
/// GL. Pass nullptr to keep no work (the handler still ends the process).
void onDisplayLoss(void (*keepWork)(void* context), void* context);

}  // namespace sculpt::app
