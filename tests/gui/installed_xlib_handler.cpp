#include "gui/installed_xlib_handler.h"

#include <X11/Xlib.h>

namespace sculpt::testing {
namespace {

XIOErrorHandler installedHandler() {
  const XIOErrorHandler installed = XSetIOErrorHandler(nullptr);  // nullptr: Xlib's default
  XSetIOErrorHandler(installed);
  return installed;
}

}  // namespace

bool xlibIoHandlerInstalled() {
  const XIOErrorHandler installed = installedHandler();
  XSetIOErrorHandler(nullptr);
  const XIOErrorHandler xlibDefault = XSetIOErrorHandler(installed);  // the default set above
  return installed != xlibDefault;
}

void callXlibIoHandler() { installedHandler()(nullptr); }

}  // namespace sculpt::testing
