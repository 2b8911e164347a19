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
  const XIOErrorHandler installed = XSetIOErrorHandler(nullptr);
  const XIOErrorHandler xlibDefault = XSetIOErrorHandler(nullptr);  // the one set just now
  XSetIOErrorHandler(installed);
  return installed != xlibDefault;
}

void callXlibIoHandler() { installedHandler()(nullptr); }

}  // namespace sculpt::testing
