#include "sculpt/termination_signals.h"

#include <signal.h>

#include <atomic>

namespace sculpt::app {
namespace {

// A lock-free atomic, not a volatile sig_atomic_t: the signal may arrive on a simulation thread
// while the UI thread reads it.
std::atomic<int> noted{0};
static_assert(std::atomic<int>::is_always_lock_free);

void setAction(void (*action)(int)) {
  struct sigaction act {};
  act.sa_handler = action;
  sigemptyset(&act.sa_mask);
  act.sa_flags = SA_RESTART;  // reads and writes elsewhere go on; the loop checks each frame
  sigaction(SIGTERM, &act, nullptr);
  sigaction(SIGINT, &act, nullptr);
}

void noteTermination(int signal) {
  noted.store(signal);
  setAction(SIG_DFL);  // sigaction is async-signal-safe
}

}  // namespace

void installTerminationHandlers() {
  noted.store(0);
  setAction(noteTermination);
}

void restoreDefaultTermination() {
  setAction(SIG_DFL);
  noted.store(0);
}

int terminationSignal() { return noted.load(); }

}  // namespace sculpt::app
