// main() of the Google Benchmark programs: on the programs' own heap (docs/memory.md), so that
// a benchmark measures what sculpt and sculpt-cli do, not page faults they do not take.

#include <benchmark/benchmark.h>

#include "allocator/huge_page_heap.h"

int main(int argc, char** argv) {
  sculpt::app::useHugePageHeap(argv);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
