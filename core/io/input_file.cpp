#include "io/input_file.h"

#include <sys/stat.h>

#include <cerrno>
#include <system_error>

#include "io/atomic_file.h"
#include "io/file_error.h"
#include "util/short_number.h"

namespace sculpt {
namespace {

const char* fileTypeName(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISFIFO(mode)) return "a FIFO (named pipe)";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "something other than a file";
}

// "5 GiB (5368709120 bytes)": the short figure to read, the exact one to check.
std::string describeSize(uint64_t bytes) {
  const double value = static_cast<double>(bytes);
  std::string figure;
  if (bytes >= kGiB) {
    figure = shortNumber(value / static_cast<double>(kGiB)) + " GiB";
  } else if (bytes >= (uint64_t{1} << 20)) {
    figure = shortNumber(value / static_cast<double>(uint64_t{1} << 20)) + " MiB";
  } else {
    return std::to_string(bytes) + " bytes";
  }
  return figure + " (" + std::to_string(bytes) + " bytes)";
}

[[noreturn]] void refuseSize(const std::filesystem::path& path, uint64_t size,
                             const InputFormat& format) {
  throw FileError(path.string() + ": " + describeSize(size) + " is more than the " +
                  describeSize(format.maxBytes) + " that " + format.noun + " may have");
}

}  // namespace

uint64_t checkInputFile(const std::filesystem::path& path, const InputFormat& format) {
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0) {
    throw FileError(path.string() + ": cannot open (" + std::generic_category().message(errno) +
                    ")");
  }
  if (!S_ISREG(info.st_mode)) {
    throw FileError(path.string() + ": is " + fileTypeName(info.st_mode) + ", not a regular file");
  }
  const auto size = static_cast<uint64_t>(info.st_size);
  if (size > format.maxBytes) refuseSize(path, size, format);
  return size;
}

std::string readInputFile(const std::filesystem::path& path, const InputFormat& format) {
  checkInputFile(path, format);
  std::string bytes = readFile(path);
  // The file may have grown between the check and the read.
  if (bytes.size() > format.maxBytes) refuseSize(path, bytes.size(), format);
  return bytes;
}

}  // namespace sculpt
