#include "anim/frame_pattern.h"

#include <stdexcept>

namespace sculpt {
namespace {

bool isSeparator(char c) { return c == '_' || c == '-' || c == '.'; }

// The pattern the user probably meant: the name without its '#', then _#### before the extension.
std::string examplePattern(const std::filesystem::path& path) {
  std::string stem;
  for (const char c : path.stem().string())
    if (c != '#') stem += c;
  while (!stem.empty() && isSeparator(stem.back())) stem.pop_back();
  if (stem.empty()) stem = "frame";
  std::string extension;
  for (const char c : path.extension().string())
    if (c != '#') extension += c;
  return stem + "_####" + extension;
}

}  // namespace

std::optional<FramePattern> parseFramePattern(const std::filesystem::path& pattern) {
  const std::string name = pattern.filename().string();
  const size_t begin = name.find('#');
  if (begin == std::string::npos) return std::nullopt;
  size_t end = begin;
  while (end < name.size() && name[end] == '#') ++end;
  if (name.find('#', end) != std::string::npos) return std::nullopt;
  FramePattern result;
  result.directory = pattern.parent_path();
  result.prefix = name.substr(0, begin);
  result.suffix = name.substr(end);
  result.width = static_cast<uint32_t>(end - begin);
  return result;
}

FramePattern framePatternOrThrow(const std::filesystem::path& pattern) {
  if (std::optional<FramePattern> parsed = parseFramePattern(pattern)) return *parsed;
  throw std::invalid_argument("'" + pattern.string() +
                              "' is not a sequence pattern: put #### where the frame number "
                              "goes, e.g. " +
                              examplePattern(pattern));
}

bool isFramePattern(const std::filesystem::path& pattern) {
  return parseFramePattern(pattern).has_value();
}

std::filesystem::path framePath(const FramePattern& pattern, uint32_t frameNumber) {
  std::string number = std::to_string(frameNumber);
  if (number.size() < pattern.width) number.insert(0, pattern.width - number.size(), '0');
  return pattern.directory / (pattern.prefix + number + pattern.suffix);
}

std::filesystem::path collectionPath(const FramePattern& pattern, std::string_view extension) {
  std::string prefix = pattern.prefix;
  if (!prefix.empty() && isSeparator(prefix.back())) prefix.pop_back();
  // A run at the very start (####.vtk) leaves no name to build on.
  if (prefix.empty()) prefix = "frames";
  std::filesystem::path name(prefix + pattern.suffix);
  name.replace_extension(std::filesystem::path(std::string(extension)));
  return pattern.directory / name;
}

}  // namespace sculpt
