#pragma once
// The files a sequence export wrote: removed again unless the export completes (keep()), so a
// cancelled or failed sequence leaves none of its frames behind.

#include <filesystem>
#include <system_error>
#include <vector>

namespace sculpt {

class WrittenFiles {
 public:
  WrittenFiles() = default;
  WrittenFiles(const WrittenFiles&) = delete;
  WrittenFiles& operator=(const WrittenFiles&) = delete;
  ~WrittenFiles() {
    if (kept_) return;
    for (const std::filesystem::path& path : files_) {
      std::error_code ignored;
      std::filesystem::remove(path, ignored);
    }
  }
  void add(const std::filesystem::path& path) { files_.push_back(path); }
  std::vector<std::filesystem::path> keep() {
    kept_ = true;
    return files_;
  }

 private:
  std::vector<std::filesystem::path> files_;
  bool kept_ = false;
};

}  // namespace sculpt
