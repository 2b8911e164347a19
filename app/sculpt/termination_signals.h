#pragma once
// SIGTERM and SIGINT (logout, `kill`, Ctrl+C in the terminal) ask the window to close. The handler
// only notes the signal, the one thing a handler may safely do; the frame loop sees it, writes
// the recovery file of unsaved work and quits without the unsaved-changes prompt. The handler
// puts both signals back to their default action, so that a second one ends the process at once
// (a save that hangs cannot hold the program).

namespace sculpt::app {

/// Installs the handler for SIGTERM and SIGINT.
void installTerminationHandlers();
/// Both back to their default action, and any noted signal forgotten.
void restoreDefaultTermination();
/// The signal noted since installTerminationHandlers(); 0 when none came.
int terminationSignal();

}  // namespace sculpt::app
