// What the program's allocator gave it, for benchmark lines and tests (docs/memory.md).
#pragma once

#include <string>

namespace sculpt::app {

struct AllocatorReport {
  std::string name;            // "glibc", or "sanitizer" where a sanitizer's replaces it
  bool hugePageHeap = false;   // glibc's malloc set for huge pages (allocator/huge_page_heap.h)
  double hugePagesMb = 0;      // anonymous memory of this process in transparent huge pages now
  double peakRssMb = 0;        // the process' peak resident set so far
};

AllocatorReport allocatorReport();

// "allocator=glibc huge_page_heap=1 huge_pages_mb=212 peak_rss_mb=301": one line of key=value.
std::string allocatorLine();

}  // namespace sculpt::app
