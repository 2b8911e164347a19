// An exception thrown inside a parallel loop (std::bad_alloc while a worker builds its block of
// stencil rows) reaches the caller instead of terminating the program, and the pool keeps
// working afterwards.

#include <gtest/gtest.h>

#include <atomic>
#include <new>
#include <stdexcept>

#include "util/parallel_for.h"

namespace sculpt {
namespace {

TEST(WorkerExceptions, ReachTheCallerFromAnyChunk) {
  if (workerCount() < 2) GTEST_SKIP() << "one worker: every chunk runs on the caller";
  for (unsigned thrower = 0; thrower < workerCount(); ++thrower) {
    SCOPED_TRACE(thrower);
    std::atomic<unsigned> finished{0};
    EXPECT_THROW(parallelChunks(1 << 16, 1,
                                [&](uint32_t, uint32_t, unsigned worker) {
                                  if (worker == thrower) throw std::bad_alloc();
                                  ++finished;
                                }),
                 std::bad_alloc);
    // The other chunks ran to their end before the caller saw the exception.
    EXPECT_EQ(finished.load(), workerCount() - 1);
  }
  // The lowest chunk's exception wins when several throw.
  try {
    parallelChunks(1 << 16, 1, [](uint32_t, uint32_t, unsigned worker) {
      throw std::runtime_error("chunk " + std::to_string(worker));
    });
    ADD_FAILURE() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "chunk 0");
  }
  std::atomic<uint64_t> sum{0};
  parallelChunks(1000, 1, [&](uint32_t begin, uint32_t end, unsigned) {
    for (uint32_t i = begin; i < end; ++i) sum += i;
  });
  EXPECT_EQ(sum.load(), 999u * 1000u / 2u);
}

TEST(WorkerExceptions, ReachTheCallerFromAnInlineLoop) {
  EXPECT_THROW(
      parallelChunks(10, 1000, [](uint32_t, uint32_t, unsigned) { throw std::bad_alloc(); }),
      std::bad_alloc);
}

}  // namespace
}  // namespace sculpt
