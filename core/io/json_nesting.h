#pragma once
// A guard for JSON from files: finds where brackets nest deeper than a limit (outside strings),
// so that no parser or later stage recurses on a hostile file.

#include <cstddef>
#include <string_view>

namespace sculpt {

/// The byte offset of the first '[' or '{' that opens level maxDepth + 1, or npos.
inline size_t excessiveJsonNesting(std::string_view text, int maxDepth) {
  int depth = 0;
  bool inString = false;
  for (size_t i = 0; i < text.size(); ++i) {
    const char ch = text[i];
    if (inString) {
      if (ch == '\\') {
        ++i;  // skip the escaped character
      } else if (ch == '"') {
        inString = false;
      }
    } else if (ch == '"') {
      inString = true;
    } else if (ch == '[' || ch == '{') {
      if (++depth > maxDepth) return i;
    } else if (ch == ']' || ch == '}') {
      --depth;
    }
  }
  return std::string_view::npos;
}

}  // namespace sculpt
