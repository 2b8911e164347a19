#pragma once
// Xlib's handler of a lost connection, as installed now, for tests that call it as Xlib would.
// Apart from the test so that Xlib's macros (Success, None, Bool) stay out of gtest and Eigen.

namespace sculpt::testing {

/// True when a handler other than Xlib's default is installed.
bool xlibIoHandlerInstalled();
/// Calls the installed handler as Xlib does when the connection is lost (it should not return).
void callXlibIoHandler();

}  // namespace sculpt::testing
