#include "sculpt/display_loss.h"

#include <X11/Xlib.h>
#include <unistd.h>

#include <atomic>
#include <csignal>
#include <cstdio>
#include <exception>

namespace sculpt::app {
namespace {

std::atomic<void (*)(void*)> keepWorkFunction{nullptr};
std::atomic<void*> keepWorkContext{nullptr};
std::atomic<bool> lost{false};

int displayLost(Display*) {
  // A second X call failing while the work is kept (none should) ends the process at once.
  if (lost.exchange(true)) ::_exit(kDisplayLostExitStatus);
  // The session may be ending with the display (a logout): a message to a reader that is gone
  // must not end the program before the work is kept.
  std::signal(SIGPIPE, SIG_IGN);
  std::fprintf(stderr, "sculpt: the connection to the display was lost; closing\n");
  std::fflush(stderr);
  if (void (*keep)(void*) = keepWorkFunction.load()) {
    try {
      keep(keepWorkContext.load());
    } catch (const std::exception& error) {
      std::fprintf(stderr, "sculpt: the unsaved work could not be kept: %s\n", error.what());
    } catch (...) {
      std::fprintf(stderr, "sculpt: the unsaved work could not be kept\n");
    }
  }
  std::fflush(stdout);
  std::fflush(stderr);
  ::_exit(kDisplayLostExitStatus);
}

}  // namespace

void onDisplayLoss(void (*keepWork)(void* context), void* context) {
  keepWorkContext.store(context);
  keepWorkFunction.store(keepWork);
  XSetIOErrorHandler(displayLost);
}

}  // namespace sculpt::app
