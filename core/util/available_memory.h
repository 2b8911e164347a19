#pragma once
// How much memory a large allocation may count on: the figure that refinement and the finite
// elements are checked against before they allocate, so that work which cannot fit is refused
// with a sentence instead of ending in std::bad_alloc or the kernel's out-of-memory killer.

#include <cstdint>
#include <string>

namespace sculpt {

/// The share of the kernel's MemAvailable that one command may plan to use: the rest is left to
/// the page cache, the other programs and the estimate's own error.
inline constexpr double kUsableMemoryFraction = 0.8;

/// The memory one command may use, in bytes. SCULPT_MEMORY_LIMIT_MB (a positive integer, in
/// MiB) replaces the measured figure, for tests and for sharing a machine; otherwise it is
/// kUsableMemoryFraction of MemAvailable in /proc/meminfo, or of sysconf's available physical
/// pages where that file cannot be read. UINT64_MAX when neither is known.
uint64_t availableMemoryBytes();

/// "this machine has 2.1 GB available", or "SCULPT_MEMORY_LIMIT_MB allows 1.0 GB" when the
/// variable sets the figure: the end of a refusal.
std::string availableMemoryPhrase(uint64_t bytes);

/// "2.1 GB", "350 MB": bytes in decimal units with two or three significant digits.
std::string memoryText(uint64_t bytes);

/// "1,230,000": an integer with thousands separators.
std::string groupedNumber(uint64_t value);

}  // namespace sculpt
