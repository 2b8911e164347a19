// main() of the window tests: on the programs' heap (docs/memory.md), as `sculpt` runs, so that
// the tests that time the window's frames measure what the window does, not page faults it does
// not take.

#include <gtest/gtest.h>

#include "allocator/huge_page_heap.h"

int main(int argc, char** argv) {
  sculpt::app::useHugePageHeap(argv);
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
