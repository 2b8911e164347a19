#pragma once
// Shared pieces of the libFuzzer targets (docs/fuzzing.md): the input as text, a per-process
// temporary file for readers that only take a path, and the check that a refusal is a clear
// one. A failed check aborts, so libFuzzer records the input as a crash.

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <string>
#include <string_view>

namespace sculpt::fuzz {

inline std::string_view text(const uint8_t* data, size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

/// Aborts with `what` on stderr: a broken contract is a finding like a crash.
[[noreturn]] inline void fail(std::string_view what) {
  std::fprintf(stderr, "fuzz contract broken: %.*s\n", static_cast<int>(what.size()), what.data());
  std::abort();
}

/// A refusal must say why in one message that starts with the source name the reader was given
/// (every reader documents "<source>: ..."), so the user learns which file is bad.
inline void expectClearMessage(const std::exception& error, std::string_view source) {
  const std::string_view message = error.what();
  if (message.empty()) fail("empty error message");
  if (message.substr(0, source.size()) != source) {
    fail("error message does not start with the source name: " + std::string(message));
  }
}

/// A file of this process in a private directory under /tmp, rewritten for every input. The
/// directory keeps relative references in an input (glTF buffer URIs) away from other files,
/// and lets two fuzzers run side by side. Removed when the process exits normally.
class ScratchFile {
 public:
  explicit ScratchFile(const std::string& name) {
    char pattern[] = "/tmp/sculpt-fuzz-XXXXXX";
    if (::mkdtemp(pattern) == nullptr) fail("mkdtemp failed");
    directory_ = pattern;
    path_ = directory_ / name;
  }
  ~ScratchFile() {
    std::error_code ignored;
    std::filesystem::remove_all(directory_, ignored);
  }
  ScratchFile(const ScratchFile&) = delete;
  ScratchFile& operator=(const ScratchFile&) = delete;

  /// Replaces the file's contents with `bytes` and returns its path.
  const std::filesystem::path& write(std::string_view bytes) const {
    std::FILE* file = std::fopen(path_.c_str(), "wb");
    if (file == nullptr) fail("cannot create the scratch file");
    const bool written = std::fwrite(bytes.data(), 1, bytes.size(), file) == bytes.size();
    if (std::fclose(file) != 0 || !written) fail("cannot write the scratch file");
    return path_;
  }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path directory_;
  std::filesystem::path path_;
};

}  // namespace sculpt::fuzz
