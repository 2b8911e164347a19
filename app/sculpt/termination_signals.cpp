#include "sculpt/termination_signals.h"

#include <signal.h>

#include <atomic>
#include <iterator>

namespace sculpt::app {
namespace {

constexpr int kSignals[] = {SIGTERM, SIGINT, SIGHUP};

// A lock-free atomic, not a volatile sig_atomic_t: the signal may arrive on a simulation thread
// while the UI thread reads it.
std::atomic<int> noted{0};
static_assert(std::atomic<int>::is_always_lock_free);
// The signals the handler was installed for (bit k: kSignals[k]); written before it is installed.
std::atomic<unsigned> handled{0};
static_assert(std::atomic<unsigned>::is_always_lock_free);

void setAction(int signal, void (*action)(int)) {
  struct sigaction act {};
  act.sa_handler = action;
  sigemptyset(&act.sa_mask);
  act.sa_flags = SA_RESTART;  // reads and writes elsewhere go on; the loop checks each frame
  sigaction(signal, &act, nullptr);
}

void setHandledActions(void (*action)(int)) {
  const unsigned mask = handled.load();
  for (unsigned k = 0; k < std::size(kSignals); ++k)
    if (mask & (1u << k)) setAction(kSignals[k], action);
}

void noteTermination(int signal) {
  noted.store(signal);
  setHandledActions(SIG_DFL);  // sigaction is async-signal-safe
}

bool ignored(int signal) {
  struct sigaction current {};
  return sigaction(signal, nullptr, &current) == 0 && current.sa_handler == SIG_IGN;
}

}  // namespace

void installTerminationHandlers() {
  noted.store(0);
  unsigned mask = 0;
  for (unsigned k = 0; k < std::size(kSignals); ++k)
    if (!ignored(kSignals[k])) mask |= 1u << k;
  handled.store(mask);
  setHandledActions(noteTermination);
}

void restoreDefaultTermination() {
  setHandledActions(SIG_DFL);
  handled.store(0);
  noted.store(0);
}

int terminationSignal() { return noted.load(); }

const char* terminationSignalName(int signal) {
  switch (signal) {
    case SIGTERM: return "SIGTERM";
    case SIGINT: return "SIGINT";
    case SIGHUP: return "SIGHUP";
    default: return "signal";
  }
}

}  // namespace sculpt::app
