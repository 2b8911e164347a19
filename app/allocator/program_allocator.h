// The allocator our programs run on and what it gave them, for benchmark lines and tests.
// docs/memory.md says why sculpt-cli uses jemalloc with transparent huge pages and the window not.
#pragma once

#include <string>

namespace sculpt::app {

struct AllocatorReport {
  std::string name;        // "jemalloc" or "system" (glibc's malloc, or a sanitizer's)
  std::string hugePages;   // jemalloc's "thp" option; "none" for the system allocator
  double hugePagesMb = 0;  // anonymous memory of this process in transparent huge pages now
  double peakRssMb = 0;    // the process' peak resident set so far
};

AllocatorReport allocatorReport();

// "allocator=jemalloc thp=always huge_pages_mb=212 peak_rss_mb=301": one line of key=value.
std::string allocatorLine();

}  // namespace sculpt::app
