// The re-executed program's side of useHugePageHeap: it takes the first main()'s start time
// from the hand-over, restores GLIBC_TUNABLES as the user had it (or removes it), and reports
// the heap as tuned only where the tunables it ran with ask for huge pages. (The re-execution
// itself is what BenchFemCliTest.BenchFemReportsItsHeapAndItsHugePages sees from outside.)

#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <string>

#include "allocator/huge_page_heap.h"

namespace sculpt::test {
namespace {

constexpr const char* kHandOver = "SCULPT_HUGE_PAGE_HEAP";

std::string environment(const char* name) {
  const char* value = std::getenv(name);
  return value ? value : "<unset>";
}

// Runs the re-executed program's start with `tunables` as the exec gave them.
std::chrono::steady_clock::time_point startAfterExec(const std::string& handOver,
                                                     const char* tunables) {
  ::setenv(kHandOver, handOver.c_str(), 1);
  if (tunables)
    ::setenv("GLIBC_TUNABLES", tunables, 1);
  else
    ::unsetenv("GLIBC_TUNABLES");
  return app::useHugePageHeap(nullptr);
}

class HugePageHeapTest : public ::testing::Test {
 protected:
  ~HugePageHeapTest() override {
    ::unsetenv(kHandOver);
    ::unsetenv("GLIBC_TUNABLES");
  }
};

TEST_F(HugePageHeapTest, TheReExecutedProgramRestoresTheUsersTunablesAndKeepsTheFirstStart) {
  const auto before = std::chrono::steady_clock::now();
  const long long ns = std::chrono::duration_cast<std::chrono::nanoseconds>(
                           before.time_since_epoch() - std::chrono::milliseconds(20))
                           .count();
  const auto began = startAfterExec(
      std::to_string(ns) + ";glibc.malloc.check=0;1",
      "glibc.malloc.hugetlb=1:glibc.malloc.mmap_threshold=268435456:glibc.malloc.check=0");
  EXPECT_EQ(environment("GLIBC_TUNABLES"), "glibc.malloc.check=0");
  EXPECT_EQ(environment(kHandOver), "<unset>");
  EXPECT_TRUE(app::heapUsesHugePages());
  EXPECT_EQ(std::chrono::duration_cast<std::chrono::nanoseconds>(began.time_since_epoch()).count(),
            ns);
}

TEST_F(HugePageHeapTest, AVariableTheUserDidNotSetIsRemoved) {
  startAfterExec("1;;0", "glibc.malloc.hugetlb=1");
  EXPECT_EQ(environment("GLIBC_TUNABLES"), "<unset>");
  EXPECT_TRUE(app::heapUsesHugePages());
}

TEST_F(HugePageHeapTest, AHandOverWithoutTheTunablesClaimsNothing) {
  startAfterExec("1;;0", nullptr);
  EXPECT_FALSE(app::heapUsesHugePages());
  startAfterExec("1;glibc.malloc.hugetlb=0;1", "glibc.malloc.hugetlb=0");
  EXPECT_FALSE(app::heapUsesHugePages());
  EXPECT_EQ(environment("GLIBC_TUNABLES"), "glibc.malloc.hugetlb=0");
  // A start time from the future (a garbled hand-over) is not believed.
  const auto now = std::chrono::steady_clock::now();
  const auto began = startAfterExec("9223372036854775807;;0", "glibc.malloc.hugetlb=1");
  EXPECT_GE(began, now);
}

}  // namespace
}  // namespace sculpt::test
