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
#include <stdexcept>
#include <string>

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

/// The FileError message of `read()` ("no error" when it succeeds, "not a FileError: ..." for
/// another exception); with `fifo`, a read blocked on it is released and the result says so.
template <class FileErrorType>
std::string fileErrorMessage(const std::function<void()>& read,
                             const std::filesystem::path& fifo = {}) {
  std::string message = "no error";
  const auto body = [&] {
    try {
      read();
    } catch (const FileErrorType& error) {
      message = error.what();
    } catch (const std::exception& error) {
      message = std::string("not a FileError: ") + error.what();
    }
  };
  if (fifo.empty()) {
    body();
  } else if (!runReleasingFifo(fifo, body)) {
    message = "blocked on the FIFO (then: " + message + ")";
  }
  return message;
}

}  // namespace sculpt::test
