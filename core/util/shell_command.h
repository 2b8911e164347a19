#pragma once
// Running other programs (ffmpeg, the window program, xvfb-run) through the shell: quoting an
// argument for sh, and finding a program on PATH before relying on it.

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>

namespace sculpt {

/// `text` single-quoted for sh (paths may hold spaces or quotes).
inline std::string shellQuote(const std::string& text) {
  std::string quoted = "'";
  for (const char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

/// True when an executable file named `program` is in a folder of PATH.
inline bool programOnPath(const std::string& program) {
  const char* path = std::getenv("PATH");
  if (!path) return false;
  std::stringstream folders(path);
  std::string folder;
  while (std::getline(folders, folder, ':')) {
    const std::filesystem::path candidate =
        std::filesystem::path(folder.empty() ? "." : folder) / program;
    if (::access(candidate.c_str(), X_OK) == 0 && !std::filesystem::is_directory(candidate))
      return true;
  }
  return false;
}

}  // namespace sculpt
