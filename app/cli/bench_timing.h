#pragma once
// Timing helpers of the bench subcommands.

#include <algorithm>
#include <chrono>
#include <vector>

namespace sculpt::cli {

using BenchClock = std::chrono::steady_clock;

inline double millisecondsSince(BenchClock::time_point start) {
  return std::chrono::duration<double, std::milli>(BenchClock::now() - start).count();
}

/// The median of the samples (mean of the middle two for an even count).
inline double median(std::vector<double> samples) {
  std::sort(samples.begin(), samples.end());
  const size_t n = samples.size();
  return n % 2 == 1 ? samples[n / 2] : 0.5 * (samples[n / 2 - 1] + samples[n / 2]);
}

}  // namespace sculpt::cli
