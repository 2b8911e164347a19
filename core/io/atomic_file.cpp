#include "io/atomic_file.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <system_error>

#include "io/file_error.h"

namespace sculpt {
namespace {

std::string errnoText(int error) { return std::generic_category().message(error); }

[[noreturn]] void fail(const std::filesystem::path& path, std::string_view what, int error) {
  throw FileError(path.string() + ": " + std::string(what) + " (" + errnoText(error) + ")");
}

// Closes the descriptor and removes the temporary file unless the write was committed.
class TemporaryFile {
 public:
  TemporaryFile(int fd, std::filesystem::path path) : fd_(fd), path_(std::move(path)) {}
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;
  ~TemporaryFile() {
    if (fd_ >= 0) ::close(fd_);
    if (!committed_) ::unlink(path_.c_str());
  }
  int fd() const { return fd_; }
  const std::filesystem::path& path() const { return path_; }
  /// Closes the descriptor, reporting the error a delayed write may only show here.
  int close() {
    const int result = ::close(fd_);
    fd_ = -1;
    return result;
  }
  void commit() { committed_ = true; }

 private:
  int fd_;
  std::filesystem::path path_;
  bool committed_ = false;
};

// ".<name>.tmp.": hidden, and with the writer's process id after it (temporaryNameFor).
std::string temporaryPrefixFor(const std::filesystem::path& path) {
  // Built with append(): GCC 12 warns falsely about `"." + std::string` (stringop-overflow).
  std::string prefix(".");
  prefix.append(path.filename().string()).append(".tmp.");
  return prefix;
}

// A name no other writer in this or another process uses at the same time.
std::filesystem::path temporaryNameFor(const std::filesystem::path& path) {
  static std::atomic<unsigned> counter{0};
  std::string name = temporaryPrefixFor(path);
  name.append(std::to_string(::getpid())).append(".").append(std::to_string(counter++));
  std::filesystem::path result = path;
  result.replace_filename(name);
  return result;
}

}  // namespace

void writeFileAtomically(const std::filesystem::path& path, std::string_view contents) {
  if (path.filename().empty()) throw FileError(path.string() + ": not a file name");
  // Create the temporary file next to the destination so that rename() stays on one filesystem.
  int fd = -1;
  std::filesystem::path tempPath;
  for (int attempt = 0; attempt < 16 && fd < 0; ++attempt) {
    tempPath = temporaryNameFor(path);
    fd = ::open(tempPath.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0 && errno != EEXIST) fail(path, "cannot create a temporary file for writing", errno);
  }
  if (fd < 0) fail(path, "cannot create a temporary file for writing", errno);
  TemporaryFile temp(fd, tempPath);

  // Write everything, retrying short writes and interruptions.
  const char* data = contents.data();
  size_t left = contents.size();
  while (left > 0) {
    const ssize_t n = ::write(temp.fd(), data, left);
    if (n < 0) {
      if (errno == EINTR) continue;
      fail(path, "cannot write", errno);
    }
    data += n;
    left -= static_cast<size_t>(n);
  }
  if (::fsync(temp.fd()) != 0) fail(path, "cannot flush to disk", errno);
  if (temp.close() != 0) fail(path, "cannot write", errno);
  if (::rename(temp.path().c_str(), path.c_str()) != 0) fail(path, "cannot replace", errno);
  temp.commit();

  // Make the rename itself durable; a failure here does not undo the write, so it is ignored.
  const std::filesystem::path dir = path.has_parent_path() ? path.parent_path() : ".";
  const int dirFd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dirFd >= 0) {
    ::fsync(dirFd);
    ::close(dirFd);
  }
}

size_t removeStaleTemporaries(const std::filesystem::path& path) {
  if (path.filename().empty()) return 0;
  const std::string prefix = temporaryPrefixFor(path);
  const std::filesystem::path dir = path.has_parent_path() ? path.parent_path() : ".";
  std::error_code error;
  std::filesystem::directory_iterator it(dir, error), end;
  size_t removed = 0;
  for (; !error && it != end; it.increment(error)) {
    const std::string name = it->path().filename().string();
    if (name.compare(0, prefix.size(), prefix) != 0) continue;
    // "<pid>.<counter>" after the prefix; anything else is not one of ours.
    const size_t dot = name.find('.', prefix.size());
    const std::string pidText = name.substr(prefix.size(), dot - prefix.size());
    if (dot == std::string::npos || pidText.empty() || pidText.size() > 9 ||
        pidText.find_first_not_of("0123456789") != std::string::npos ||
        name.find_first_not_of("0123456789", dot + 1) != std::string::npos)
      continue;
    const pid_t pid = static_cast<pid_t>(std::stol(pidText));
    // kill(pid, 0) probes without sending: success or EPERM means the writer still runs.
    if (pid == ::getpid() || ::kill(pid, 0) == 0 || errno == EPERM) continue;
    std::error_code ignored;
    if (std::filesystem::remove(it->path(), ignored)) ++removed;
  }
  return removed;
}

std::string readFile(const std::filesystem::path& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) fail(path, "cannot open", errno);
  struct stat info {};
  if (::fstat(fd, &info) == 0 && S_ISDIR(info.st_mode)) {
    ::close(fd);
    throw FileError(path.string() + ": cannot open (is a directory)");
  }
  // Read in chunks: pipes and special files report no size.
  std::string contents;
  if (info.st_size > 0) contents.reserve(static_cast<size_t>(info.st_size));
  char buffer[1 << 16];
  for (;;) {
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n == 0) break;
    if (n < 0) {
      if (errno == EINTR) continue;
      const int error = errno;
      ::close(fd);
      fail(path, "cannot read", error);
    }
    contents.append(buffer, static_cast<size_t>(n));
  }
  ::close(fd);
  return contents;
}

}  // namespace sculpt
