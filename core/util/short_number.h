#pragma once
// Numbers in messages: three significant digits ("%.3g": 1.3e-05, 250, inf).

#include <cstdio>
#include <string>

namespace sculpt {

inline std::string shortNumber(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3g", value);
  return buffer;
}

}  // namespace sculpt
