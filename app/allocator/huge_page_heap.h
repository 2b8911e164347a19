// glibc's malloc set for transparent huge pages and a heap that is not handed back and faulted
// in again (docs/memory.md): block10's build and first steps then take 2,000 page faults, not
// 105,000.
#pragma once

#include <chrono>

namespace sculpt::app {

// Call first in main(). Unless the heap is already so set, or SCULPT_SYSTEM_HEAP is set, or the
// build uses a sanitizer, re-executes the program once with GLIBC_TUNABLES set for it (glibc
// reads its tunables only at start); the re-executed program restores the variable as it was,
// so that programs it runs do not inherit it. Returns when the program runs as it will: the
// time returned is when the first of the two main()s began.
std::chrono::steady_clock::time_point useHugePageHeap(char** argv);

// Whether this process' malloc runs with those tunables.
bool heapUsesHugePages();

// Whether a sanitizer's allocator replaces malloc in this build (nothing to tune then).
bool sanitizerAllocator();

}  // namespace sculpt::app
