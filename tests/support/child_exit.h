#pragma once
// Waiting for a child process with a deadline, so that a child that hangs fails its test
// instead of holding the suite until ctest's timeout.

#include <signal.h>
#include <sys/wait.h>

#include <chrono>
#include <optional>
#include <thread>

namespace sculpt::test {

/// The wait status of `pid` once it ends within `limit`; nullopt, and the child killed and
/// reaped, if it does not.
inline std::optional<int> waitForExit(pid_t pid, std::chrono::milliseconds limit) {
  const auto deadline = std::chrono::steady_clock::now() + limit;
  int status = 0;
  while (std::chrono::steady_clock::now() < deadline) {
    if (::waitpid(pid, &status, WNOHANG) == pid) return status;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  ::kill(pid, SIGKILL);
  ::waitpid(pid, &status, 0);
  return std::nullopt;
}

}  // namespace sculpt::test
