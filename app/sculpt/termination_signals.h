#pragma once
// SIGTERM, SIGINT and SIGHUP (logout, `kill`, Ctrl+C in the terminal, the terminal closed) ask the
// window to close. The handler only notes the signal, the one thing a handler may safely do; the
// frame loop sees it, writes the recovery file of unsaved work and quits without the
// unsaved-changes prompt. The handler puts the signals back to their default action, so that a
// second one ends the process at once (a save that hangs cannot hold the program). A signal the
// program was started with ignored (`nohup`, a background job) stays ignored.

namespace sculpt::app {

/// Installs the handler for SIGTERM, SIGINT and SIGHUP (those not ignored at the time).
void installTerminationHandlers();
/// The handled signals back to their default action, and any noted signal forgotten.
void restoreDefaultTermination();
/// The signal noted since installTerminationHandlers(); 0 when none came.
int terminationSignal();
/// "SIGTERM", "SIGINT" or "SIGHUP" for those signals; "signal" otherwise.
const char* terminationSignalName(int signal);

}  // namespace sculpt::app
