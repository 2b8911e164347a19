#include "allocator/huge_page_heap.h"

#include <unistd.h>

#include <cstdlib>
#include <string>
#include <string_view>

namespace sculpt::app {
namespace {

// glibc 2.35+: madvise huge pages for the heap and mmapped blocks; blocks below 256 MB from the
// heap (reused, not mapped afresh each time); the heap's top kept up to 1 GB instead of trimmed;
// the heap grown 64 MB at a time; one heap for every thread, so that what one thread frees the
// next reuses (docs/memory.md). Older glibc ignores tunables it does not know.
constexpr const char* kTunables =
    "glibc.malloc.hugetlb=1:glibc.malloc.mmap_threshold=268435456:"
    "glibc.malloc.trim_threshold=1073741824:glibc.malloc.top_pad=67108864:"
    "glibc.malloc.arena_max=1";
// Set for the re-executed program: "<first main's steady clock in ns>;<GLIBC_TUNABLES as it
// was, or nothing>;<1 if it was set>".
constexpr const char* kHandOver = "SCULPT_HUGE_PAGE_HEAP";

#if defined(SCULPT_SANITIZED)
constexpr bool kSanitized = true;
#else
constexpr bool kSanitized = false;
#endif
constexpr std::string_view kHugePages = "glibc.malloc.hugetlb=";

bool tuned = false;

// Whether tunables set glibc.malloc.hugetlb to anything but 0 (the last setting counts).
bool asksForHugePages(const char* tunables) {
  if (!tunables) return false;
  const std::string_view text = tunables;
  const size_t at = text.rfind(kHugePages);
  return at != std::string_view::npos && at + kHugePages.size() < text.size() &&
         text[at + kHugePages.size()] != '0';
}

void restore(const char* name, const std::string& value, bool wasSet) {
  if (wasSet)
    ::setenv(name, value.c_str(), 1);
  else
    ::unsetenv(name);
}

}  // namespace

std::chrono::steady_clock::time_point useHugePageHeap(char** argv) {
  using Clock = std::chrono::steady_clock;
  const Clock::time_point now = Clock::now();
  const char* handOver = std::getenv(kHandOver);
  if (handOver) {  // the re-executed program
    const std::string text = handOver;
    ::unsetenv(kHandOver);
    const size_t first = text.find(';'), last = text.rfind(';');
    if (first == std::string::npos || last == first) return now;
    tuned = asksForHugePages(std::getenv("GLIBC_TUNABLES"));
    restore("GLIBC_TUNABLES", text.substr(first + 1, last - first - 1),
            text.substr(last + 1) == "1");
    const long long ns = std::strtoll(text.substr(0, first).c_str(), nullptr, 10);
    const Clock::time_point began{std::chrono::nanoseconds(ns)};
    return began <= now ? began : now;
  }
  if (kSanitized) return now;  // a sanitizer's allocator replaces malloc: nothing to tune
  const char* given = std::getenv("GLIBC_TUNABLES");
  const std::string original = given ? given : "";
  if (original.find(kHugePages) != std::string::npos) {  // the user's own choice
    tuned = asksForHugePages(given);
    return now;
  }
  if (std::getenv("SCULPT_SYSTEM_HEAP") || !argv || !argv[0]) return now;
  const long long ns =
      std::chrono::duration_cast<std::chrono::nanoseconds>(now.time_since_epoch()).count();
  const std::string handOverText = std::to_string(ns) + ";" + original + ";" + (given ? "1" : "0");
  ::setenv(kHandOver, handOverText.c_str(), 1);
  // The user's tunables after ours, so that theirs win where both name one.
  const std::string tunables =
      original.empty() ? std::string(kTunables) : std::string(kTunables) + ":" + original;
  ::setenv("GLIBC_TUNABLES", tunables.c_str(), 1);
  ::execv("/proc/self/exe", argv);
  // Not re-executed (no /proc, say): run on as we are.
  ::unsetenv(kHandOver);
  restore("GLIBC_TUNABLES", original, given != nullptr);
  return now;
}

bool heapUsesHugePages() { return tuned; }

bool sanitizerAllocator() { return kSanitized; }

}  // namespace sculpt::app
