#include "util/available_memory.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>

namespace sculpt {
namespace {

constexpr uint64_t kMiB = uint64_t(1) << 20;

// MemAvailable in bytes, 0 when the line is missing (kernels before 3.14, other systems).
uint64_t procMemAvailable() {
  std::ifstream meminfo("/proc/meminfo");
  std::string line;
  while (std::getline(meminfo, line)) {
    if (line.rfind("MemAvailable:", 0) != 0) continue;
    std::istringstream fields(line.substr(13));
    uint64_t kib = 0;
    if (fields >> kib) return kib * 1024;
  }
  return 0;
}

uint64_t sysconfAvailable() {
  const long pages = sysconf(_SC_AVPHYS_PAGES);
  const long pageSize = sysconf(_SC_PAGESIZE);
  if (pages <= 0 || pageSize <= 0) return 0;
  return uint64_t(pages) * uint64_t(pageSize);
}

// SCULPT_MEMORY_LIMIT_MB in bytes, 0 when unset or not a positive integer.
uint64_t limitFromEnvironment() {
  const char* text = std::getenv("SCULPT_MEMORY_LIMIT_MB");
  if (!text) return 0;
  char* end = nullptr;
  const unsigned long long mib = std::strtoull(text, &end, 10);
  if (end == text || *end != '\0' || mib == 0 || mib >= std::numeric_limits<uint64_t>::max() / kMiB)
    return 0;
  return mib * kMiB;
}

}  // namespace

uint64_t availableMemoryBytes() {
  if (const uint64_t limit = limitFromEnvironment()) return limit;
  uint64_t measured = procMemAvailable();
  if (measured == 0) measured = sysconfAvailable();
  if (measured == 0) return std::numeric_limits<uint64_t>::max();
  return static_cast<uint64_t>(double(measured) * kUsableMemoryFraction);
}

std::string availableMemoryPhrase(uint64_t bytes) {
  if (limitFromEnvironment() == bytes) return "SCULPT_MEMORY_LIMIT_MB allows " + memoryText(bytes);
  return "this machine has " + memoryText(bytes) + " available";
}

std::string memoryText(uint64_t bytes) {
  const double value = double(bytes);
  const char* unit = "kB";
  double scaled = value / 1e3;
  if (value >= 1e12) {
    unit = "TB";
    scaled = value / 1e12;
  } else if (value >= 1e9) {
    unit = "GB";
    scaled = value / 1e9;
  } else if (value >= 1e6) {
    unit = "MB";
    scaled = value / 1e6;
  }
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, scaled < 10 ? "%.1f %s" : "%.0f %s", scaled, unit);
  return buffer;
}

std::string groupedNumber(uint64_t value) {
  std::string digits = std::to_string(value);
  for (int i = int(digits.size()) - 3; i > 0; i -= 3) digits.insert(size_t(i), ",");
  return digits;
}

}  // namespace sculpt
