#pragma once
// Small helpers of the animation writers' tests: a file's bytes, a directory's file names, a
// progress reporter that cancels, and numbers read by hand from the formats' bytes.

#include <bit>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <string>

#include "util/progress.h"

namespace sculpt::test {

inline std::string fileBytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// Every entry's name, hidden temporary files included.
inline std::set<std::string> fileNames(const std::filesystem::path& directory) {
  std::set<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(directory))
    names.insert(entry.path().filename().string());
  return names;
}

/// A reporter whose callback lets `frames` reports through and cancels at the next.
inline ProgressReporter cancelAfter(int frames) {
  return ProgressReporter(
      [calls = 0, frames](double, std::string_view) mutable { return ++calls <= frames; });
}

inline uint32_t littleEndian32(const std::string& bytes, size_t at) {
  uint32_t bits = 0;
  for (size_t i = 4; i-- > 0;) bits = (bits << 8) | static_cast<uint8_t>(bytes.at(at + i));
  return bits;
}

inline uint64_t readBigEndianBits(const std::string& bytes, size_t at, size_t size) {
  uint64_t bits = 0;
  for (size_t i = 0; i < size; ++i) bits = (bits << 8) | static_cast<uint8_t>(bytes.at(at + i));
  return bits;
}

inline uint32_t bigEndian32(const std::string& bytes, size_t at) {
  return static_cast<uint32_t>(readBigEndianBits(bytes, at, 4));
}

inline float bigEndianFloat(const std::string& bytes, size_t at) {
  return std::bit_cast<float>(bigEndian32(bytes, at));
}

inline double bigEndianDouble(const std::string& bytes, size_t at) {
  return std::bit_cast<double>(readBigEndianBits(bytes, at, 8));
}

}  // namespace sculpt::test
