#pragma once
// Number formatting shared by the text writers (JSON, VTK, OBJ). std::to_chars is locale-free and
// far faster than streams for meshes with millions of numbers.

#include <charconv>
#include <cstdint>
#include <string>

namespace sculpt {

inline void appendNumber(std::string& out, uint32_t value) {
  char buffer[16];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  out.append(buffer, result.ptr);
}

inline void appendNumber(std::string& out, uint64_t value) {
  char buffer[24];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  out.append(buffer, result.ptr);
}

/// 17 significant digits (like "%.17g"): every finite double reads back bit for bit.
inline void appendNumber(std::string& out, double value) {
  char buffer[40];
  const auto result =
      std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::general, 17);
  out.append(buffer, result.ptr);
}

}  // namespace sculpt
