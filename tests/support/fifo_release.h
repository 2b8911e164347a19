#pragma once
// For tests that hand a FIFO to a reader that must refuse it: a reader that opens it instead
// blocks until a writer comes, so the test would hang rather than fail. runReleasingFifo gives
// the reader a few seconds, then keeps opening the FIFO for writing and closing it, which lets
// each blocked open return and each read see the end of the file, until the reader is done.

#include <fcntl.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <functional>
#include <future>

namespace sculpt::test {

/// Runs `body`; returns false when it had to be released from `fifo` (it blocked on it).
inline bool runReleasingFifo(const std::filesystem::path& fifo, const std::function<void()>& body,
                             std::chrono::seconds patience = std::chrono::seconds(5)) {
  std::future<void> done = std::async(std::launch::async, body);
  if (done.wait_for(patience) == std::future_status::ready) {
    done.get();
    return true;
  }
  do {
    const int fd = ::open(fifo.c_str(), O_WRONLY | O_NONBLOCK);
    if (fd >= 0) ::close(fd);
  } while (done.wait_for(std::chrono::milliseconds(100)) != std::future_status::ready);
  done.get();
  return false;
}

}  // namespace sculpt::test
