#pragma once
// A minimal fork-join loop over index ranges on all hardware threads. Chunks are contiguous so
// that each worker can write its own output block without synchronisation.

#include <cstdint>
#include <functional>

namespace sculpt {

/// Number of worker threads used by parallelFor (hardware threads, at least 1).
unsigned workerCount();

/// Calls body(begin, end, worker) for disjoint contiguous chunks covering [0, n), one chunk per
/// worker thread, `worker` being the chunk's index: per-worker buffers may be indexed by it. The
/// chunks depend on n and workerCount() only; which thread runs which is not fixed (a thread
/// that is free takes the next one). Runs inline when n < minParallel.
/// An exception thrown by body (std::bad_alloc, say) is rethrown here once every chunk has
/// ended; when several chunks throw, the lowest chunk's exception wins.
void parallelChunks(uint32_t n, uint32_t minParallel,
                    const std::function<void(uint32_t begin, uint32_t end, unsigned worker)>& body);

/// While alive, parallelChunks called on this thread run inline on it. For background work (an
/// export) that must neither take every core nor hold the shared pool, which serialises loops
/// and would make the interactive threads' loops wait for it.
class InlineLoopsOnThisThread {
 public:
  InlineLoopsOnThisThread();
  ~InlineLoopsOnThisThread();
  InlineLoopsOnThisThread(const InlineLoopsOnThisThread&) = delete;
  InlineLoopsOnThisThread& operator=(const InlineLoopsOnThisThread&) = delete;

 private:
  bool previous_;
};

}  // namespace sculpt
