#pragma once
// A path's extension in lower case ("Take.GLB" -> ".glb"): file formats are chosen by it.

#include <cctype>
#include <filesystem>
#include <string>

namespace sculpt {

inline std::string lowerExtension(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return extension;
}

}  // namespace sculpt
