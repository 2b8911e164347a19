#pragma once
// A file written in pieces under a temporary name beside its destination (so that the final
// rename stays on one filesystem): buffered writes, then commit() flushes it to disk and renames
// it over the destination; anything short of commit() removes it. Every failure (no space, no
// folder, no permission) throws FileError naming the destination.

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "io/file_error.h"

namespace sculpt {

[[noreturn]] inline void failErrno(const std::filesystem::path& path, const char* what, int error) {
  throw FileError(path.string() + ": " + what + " (" + std::generic_category().message(error) +
                  ")");
}

// The file being written, under a temporary name next to the destination (so that the final
// rename stays on one filesystem); removed unless committed.
class StreamFile {
 public:
  explicit StreamFile(std::filesystem::path destination) : destination_(std::move(destination)) {
    static std::atomic<unsigned> counter{0};
    for (int attempt = 0; attempt < 16 && fd_ < 0; ++attempt) {
      std::string name(".");
      name.append(destination_.filename().string()).append(".tmp.");
      name.append(std::to_string(::getpid())).append(".").append(std::to_string(counter++));
      temp_ = destination_;
      temp_.replace_filename(name);
      fd_ = ::open(temp_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
      if (fd_ < 0 && errno != EEXIST) break;
    }
    if (fd_ < 0) failErrno(destination_, "cannot create a temporary file for writing", errno);
    buffer_.reserve(kBufferSize);
  }
  StreamFile(const StreamFile&) = delete;
  StreamFile& operator=(const StreamFile&) = delete;
  ~StreamFile() {
    if (fd_ >= 0) ::close(fd_);
    if (!committed_) ::unlink(temp_.c_str());
  }

  void write(const void* data, size_t size) {
    const char* bytes = static_cast<const char*>(data);
    written_ += size;
    while (size > 0) {
      const size_t n = std::min(size, kBufferSize - buffer_.size());
      buffer_.insert(buffer_.end(), bytes, bytes + n);
      bytes += n;
      size -= n;
      if (buffer_.size() == kBufferSize) flush();
    }
  }
  template <class T>
  void write(const std::vector<T>& values) {
    write(values.data(), values.size() * sizeof(T));
  }
  void pad(size_t size, char byte) {
    const std::string padding(size, byte);
    write(padding.data(), padding.size());
  }
  uint64_t written() const { return written_; }

  /// Flushes to disk and replaces the destination.
  void commit() {
    flush();
    if (::fsync(fd_) != 0) failErrno(destination_, "cannot flush to disk", errno);
    const int result = ::close(fd_);
    fd_ = -1;
    if (result != 0) failErrno(destination_, "cannot write", errno);
    if (::rename(temp_.c_str(), destination_.c_str()) != 0) {
      failErrno(destination_, "cannot replace", errno);
    }
    committed_ = true;
    // Makes the rename durable; a failure here does not undo the write, so it is ignored.
    const auto dir = destination_.has_parent_path() ? destination_.parent_path() : ".";
    const int dirFd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (dirFd >= 0) {
      ::fsync(dirFd);
      ::close(dirFd);
    }
  }

 private:
  static constexpr size_t kBufferSize = size_t{1} << 20;

  void flush() {
    const char* data = buffer_.data();
    size_t left = buffer_.size();
    while (left > 0) {
      const ssize_t n = ::write(fd_, data, left);
      if (n < 0) {
        if (errno == EINTR) continue;
        failErrno(destination_, "cannot write", errno);
      }
      data += n;
      left -= static_cast<size_t>(n);
    }
    buffer_.clear();
  }

  std::filesystem::path destination_, temp_;
  int fd_ = -1;
  std::vector<char> buffer_;
  uint64_t written_ = 0;
  bool committed_ = false;
};

}  // namespace sculpt
