// The worker pool behind parallelChunks: every index exactly once, whether the helpers are
// spinning (back-to-back loops) or asleep (after a pause), from several calling threads at once,
// and nested loops inline; and exit() while a loop runs on another thread ends the program.
#include <gtest/gtest.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdlib>
#include <optional>
#include <string>
#include <thread>
#include <vector>

extern char** environ;

#include "support/child_exit.h"
#include "util/parallel_for.h"

namespace sculpt {
namespace {

// Runs one loop over n indices and checks that each was visited exactly once, and that each
// chunk index was handed out once (whichever pool thread ran it).
void expectEachIndexOnce(uint32_t n, uint32_t minParallel) {
  std::vector<std::atomic<int>> visits(n);
  std::vector<std::atomic<int>> chunkOwner(workerCount());
  for (auto& owner : chunkOwner) owner = 0;
  parallelChunks(n, minParallel, [&](uint32_t begin, uint32_t end, unsigned worker) {
    ASSERT_LT(worker, workerCount());
    chunkOwner[worker].fetch_add(1);
    for (uint32_t i = begin; i < end; ++i) visits[i].fetch_add(1);
  });
  for (uint32_t i = 0; i < n; ++i) ASSERT_EQ(visits[i].load(), 1) << "index " << i << " of " << n;
  for (auto& owner : chunkOwner) ASSERT_LE(owner.load(), 1);
}

TEST(ParallelChunks, EveryIndexOnceInBackToBackLoops) {
  for (int round = 0; round < 3000; ++round) expectEachIndexOnce(uint32_t(1 + round % 97), 1);
}

TEST(ParallelChunks, EveryIndexOnceAfterTheWorkersFellAsleep) {
  for (int round = 0; round < 20; ++round) {
    // Longer than the pool's spin, so the helpers block and have to be woken.
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
    expectEachIndexOnce(1000, 1);
  }
}

TEST(ParallelChunks, BelowTheThresholdRunsInlineAsOneChunk) {
  int calls = 0;
  parallelChunks(10, 100, [&](uint32_t begin, uint32_t end, unsigned worker) {
    ++calls;
    EXPECT_EQ(begin, 0u);
    EXPECT_EQ(end, 10u);
    EXPECT_EQ(worker, 0u);
  });
  EXPECT_EQ(calls, 1);
}

TEST(ParallelChunks, NestedLoopsRunInline) {
  std::vector<std::atomic<int>> visits(64 * 64);
  parallelChunks(64, 1, [&](uint32_t begin, uint32_t end, unsigned) {
    for (uint32_t i = begin; i < end; ++i)
      parallelChunks(64, 1, [&](uint32_t innerBegin, uint32_t innerEnd, unsigned innerWorker) {
        EXPECT_EQ(innerWorker, 0u);  // inline: one chunk on the calling thread
        for (uint32_t j = innerBegin; j < innerEnd; ++j) visits[i * 64 + j].fetch_add(1);
      });
  });
  for (auto& v : visits) ASSERT_EQ(v.load(), 1);
}

TEST(ParallelChunks, CallsFromSeveralThreadsAreSerialisedAndComplete) {
  std::atomic<int> failures{0};
  std::vector<std::thread> callers;
  for (int t = 0; t < 3; ++t)
    callers.emplace_back([&, t] {
      for (int round = 0; round < 500; ++round) {
        const uint32_t n = uint32_t(50 + 13 * t + round % 7);
        std::vector<int> visits(n, 0);
        parallelChunks(n, 1, [&](uint32_t begin, uint32_t end, unsigned) {
          for (uint32_t i = begin; i < end; ++i) ++visits[i];  // chunks are disjoint
        });
        for (int v : visits)
          if (v != 1) failures.fetch_add(1);
      }
    });
  for (auto& caller : callers) caller.join();
  EXPECT_EQ(failures.load(), 0);
}

TEST(ParallelChunks, InsideAnInlineScopeLoopsRunOnTheCallingThreadAlone) {
  const std::thread::id caller = std::this_thread::get_id();
  std::vector<std::thread::id> threads;
  {
    const InlineLoopsOnThisThread inlineLoops;
    parallelChunks(100000, 1, [&](uint32_t begin, uint32_t end, unsigned worker) {
      EXPECT_EQ(begin, 0u);
      EXPECT_EQ(end, 100000u);
      EXPECT_EQ(worker, 0u);
      threads.push_back(std::this_thread::get_id());
    });
  }
  ASSERT_EQ(threads.size(), 1u);
  EXPECT_EQ(threads[0], caller);
  // Out of the scope the loop is shared again (on a machine with more than one thread).
  std::atomic<int> chunks{0};
  parallelChunks(100000, 1, [&](uint32_t, uint32_t, unsigned) { chunks.fetch_add(1); });
  EXPECT_EQ(chunks.load(), static_cast<int>(workerCount()));
}

// exit() while another thread is inside a loop (Xlib's default handler of a lost display does
// that from the UI thread, the simulation mid-step) ends the program. The pool used to be torn
// down by exit(), joining a helper that was still running its chunk: the program hung for good.
// Run in a child process (this test binary again, with two workers).
constexpr const char* kExitChild = "SCULPT_TEST_EXIT_DURING_A_LOOP";

[[noreturn]] void exitWhileAHelperRunsAChunk() {
  std::atomic<bool> helperIn{false};
  std::thread looping([&] {
    const std::thread::id caller = std::this_thread::get_id();
    parallelChunks(2, 1, [&](uint32_t, uint32_t, unsigned) {
      if (std::this_thread::get_id() == caller) {  // leave the other chunk to the helper
        while (!helperIn) std::this_thread::yield();
        return;
      }
      helperIn = true;
      for (;;) std::this_thread::sleep_for(std::chrono::seconds(1));  // a chunk that never ends
    });
  });
  looping.detach();
  while (!helperIn) std::this_thread::yield();
  std::this_thread::sleep_for(std::chrono::milliseconds(50));  // the caller waits for the helper
  std::exit(0);
}

TEST(ParallelChunks, ExitWhileAnotherThreadIsInALoopEndsTheProgram) {
  if (std::getenv(kExitChild)) exitWhileAHelperRunsAChunk();
  std::vector<std::string> variables = {std::string(kExitChild) + "=1", "SCULPT_THREADS=2"};
  for (char** v = environ; *v; ++v) variables.emplace_back(*v);
  std::vector<char*> environment;
  for (std::string& v : variables) environment.push_back(v.data());
  environment.push_back(nullptr);
  std::string filter = std::string("--gtest_filter=") +
                       ::testing::UnitTest::GetInstance()->current_test_suite()->name() + "." +
                       ::testing::UnitTest::GetInstance()->current_test_info()->name();
  char self[] = "/proc/self/exe";
  char* argv[] = {self, filter.data(), nullptr};
  pid_t child = -1;
  ASSERT_EQ(posix_spawn(&child, self, nullptr, nullptr, argv, environment.data()), 0);
  const std::optional<int> status = test::waitForExit(child, std::chrono::seconds(10));
  ASSERT_TRUE(status.has_value()) << "the program hung in exit() for 10 s";
  ASSERT_TRUE(WIFEXITED(*status)) << "ended by signal " << WTERMSIG(*status);
  EXPECT_EQ(WEXITSTATUS(*status), 0);
}

}  // namespace
}  // namespace sculpt
