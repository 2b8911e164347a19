#include "allocator/program_allocator.h"

#include <sys/resource.h>

#include <cstdio>
#include <fstream>
#include <sstream>

#include "allocator/huge_page_heap.h"

namespace sculpt::app {
namespace {

// The kernel's count of this process' anonymous memory in huge pages, in MB (0 if unreadable).
double anonymousHugePagesMb() {
  std::ifstream rollup("/proc/self/smaps_rollup");
  for (std::string line; std::getline(rollup, line);) {
    if (line.rfind("AnonHugePages:", 0) != 0) continue;
    std::istringstream fields(line.substr(14));
    double kb = 0;
    fields >> kb;
    return kb / 1024.0;
  }
  return 0;
}

double peakResidentMb() {
  rusage usage{};
  if (getrusage(RUSAGE_SELF, &usage) != 0) return 0;
  return static_cast<double>(usage.ru_maxrss) / 1024.0;  // Linux gives kilobytes
}

}  // namespace

AllocatorReport allocatorReport() {
  AllocatorReport report;
  report.name = sanitizerAllocator() ? "sanitizer" : "glibc";
  report.hugePageHeap = heapUsesHugePages();
  report.hugePagesMb = anonymousHugePagesMb();
  report.peakRssMb = peakResidentMb();
  return report;
}

std::string allocatorLine() {
  const AllocatorReport report = allocatorReport();
  char text[160];
  std::snprintf(text, sizeof text,
                "allocator=%s huge_page_heap=%d huge_pages_mb=%.0f peak_rss_mb=%.0f",
                report.name.c_str(), report.hugePageHeap ? 1 : 0, report.hugePagesMb,
                report.peakRssMb);
  return text;
}

}  // namespace sculpt::app
