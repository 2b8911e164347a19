#include "util/parallel_for.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdlib>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace sculpt {
namespace {

// Worker threads that live for the whole program: a fork-join costs a wake-up instead of a
// thread creation (tens of microseconds), which matters for per-step loops of a millisecond.
// Both sides spin for a short while before they block: a simulation step runs several loops
// back to back with short serial parts between them, and on a virtual machine a futex wake-up
// of a sleeping thread costs tens of microseconds. The spin is bounded in time, so an idle
// pool sleeps. With more workers than hardware threads (SCULPT_THREADS) nobody spins: a
// spinning thread would take the core from one with work.
//
// A loop's chunks are claimed, not assigned: the caller and the helpers take the next
// unclaimed one until none is left, and the caller waits only for chunks that were claimed.
// When another thread holds a core (a factor made on a worker, the window's drawing), a helper
// that has not been scheduled yet costs nothing: the caller runs its chunk. The chunks and the
// index each is called with do not change, so neither do the results.
class WorkerPool {
 public:
  explicit WorkerPool(unsigned helpers)
      : spin_(helpers + 1 <= std::max(1u, std::thread::hardware_concurrency())) {
    for (unsigned k = 0; k < helpers; ++k) threads_.emplace_back([this] { loop(); });
  }

  // Runs task(k) once for every k in [0, count) on the caller and the helpers; returns when all
  // have ended. Calls from several threads at once are serialised.
  void run(unsigned count, const std::function<void(unsigned)>& task) {
    std::lock_guard serial(runMutex_);
    uint32_t job;
    {
      std::lock_guard lock(mutex_);
      task_ = &task;
      ended_.store(0, std::memory_order_relaxed);
      job = ++job_;
      claims_.store(pack(job, 0, count), std::memory_order_release);
    }
    wake_.notify_all();
    runClaimedChunks(job);
    const auto allEnded = [&] { return ended_.load(std::memory_order_acquire) == count; };
    if (spinUntil(allEnded)) return;
    std::unique_lock lock(mutex_);
    done_.wait(lock, allEnded);
  }

  unsigned size() const { return static_cast<unsigned>(threads_.size()) + 1; }

 private:
  // One word holds the job, its next unclaimed chunk and its chunk count, so that a helper
  // that wakes late cannot claim a chunk of a job that has ended.
  static uint64_t pack(uint32_t job, uint32_t next, uint32_t count) {
    return uint64_t(job) << 32 | uint64_t(next) << 16 | count;
  }
  static uint32_t jobOf(uint64_t word) { return uint32_t(word >> 32); }
  static uint32_t nextOf(uint64_t word) { return uint32_t(word >> 16) & 0xffffu; }
  static uint32_t countOf(uint64_t word) { return uint32_t(word) & 0xffffu; }

  // Claims and runs chunks of `job` until none is left.
  void runClaimedChunks(uint32_t job) {
    for (;;) {
      uint64_t word = claims_.load(std::memory_order_acquire);
      do {
        if (jobOf(word) != job || nextOf(word) >= countOf(word)) return;
      } while (!claims_.compare_exchange_weak(word, word + (uint64_t(1) << 16),
                                              std::memory_order_acq_rel,
                                              std::memory_order_acquire));
      // The task stays valid while a claimed chunk has not ended: run() waits for it.
      (*task_)(nextOf(word));
      if (ended_.fetch_add(1, std::memory_order_acq_rel) + 1 == countOf(word)) {
        std::lock_guard lock(mutex_);
        done_.notify_one();
      }
    }
  }

  // Polls `ready` for up to kSpin; true as soon as it holds.
  template <class Ready>
  bool spinUntil(const Ready& ready) const {
    if (!spin_) return false;
    constexpr auto kSpin = std::chrono::microseconds(200);
    const auto deadline = std::chrono::steady_clock::now() + kSpin;
    for (;;) {
      for (int k = 0; k < 64; ++k) {
        if (ready()) return true;
        pause();
      }
      if (std::chrono::steady_clock::now() >= deadline) return false;
    }
  }
  static void pause() {
#if defined(__x86_64__) || defined(__i386__)
    __builtin_ia32_pause();
#endif
  }

  void loop() {
    uint32_t seen = 0;
    for (;;) {
      const auto newJob = [&] {
        return jobOf(claims_.load(std::memory_order_acquire)) != seen;
      };
      spinUntil(newJob);
      {
        std::unique_lock lock(mutex_);
        wake_.wait(lock, newJob);
        seen = jobOf(claims_.load(std::memory_order_relaxed));
      }
      runClaimedChunks(seen);
    }
  }

  const bool spin_;
  std::vector<std::thread> threads_;
  std::mutex mutex_, runMutex_;
  std::condition_variable wake_, done_;
  const std::function<void(unsigned)>* task_ = nullptr;  // written under mutex_ before a job
  uint32_t job_ = 0;                                     // guarded by mutex_
  // The job, its next chunk and its chunk count; a job is published under mutex_.
  std::atomic<uint64_t> claims_{0};
  std::atomic<unsigned> ended_{0};  // chunks of the current job that have ended
};

// Never destroyed, and its helpers never joined: exit() runs static destructors while other
// threads may still be inside a loop (a library that ends the program on a fatal error, such as
// Xlib's default handler when the display goes away, calls exit() with the simulation mid-step),
// and a pool torn down under them left them waiting forever for chunks nobody would run: the
// program hung instead of ending. The helpers end with the process.
WorkerPool& pool() {
  static WorkerPool* const instance = new WorkerPool(workerCount() - 1);
  return *instance;
}

// True on the pool's own threads: a nested parallel loop then runs inline instead of waiting
// for workers that are busy running its parent. Also set by InlineLoopsOnThisThread.
thread_local bool insideParallelLoop = false;

}  // namespace

InlineLoopsOnThisThread::InlineLoopsOnThisThread() : previous_(insideParallelLoop) {
  insideParallelLoop = true;
}

InlineLoopsOnThisThread::~InlineLoopsOnThisThread() { insideParallelLoop = previous_; }

unsigned workerCount() {
  static const unsigned count = [] {
    // SCULPT_THREADS overrides the hardware count (benchmarks, reproducible runs).
    if (const char* text = std::getenv("SCULPT_THREADS")) {
      const long n = std::strtol(text, nullptr, 10);
      if (n >= 1 && n <= 256) return static_cast<unsigned>(n);
    }
    return std::max(1u, std::thread::hardware_concurrency());
  }();
  return count;
}

void parallelChunks(uint32_t n, uint32_t minParallel,
                    const std::function<void(uint32_t, uint32_t, unsigned)>& body) {
  const unsigned workers =
      (n < minParallel || insideParallelLoop) ? 1u : std::min<unsigned>(workerCount(), n);
  if (workers <= 1) {
    body(0, n, 0);
    return;
  }
  auto chunkBegin = [&](unsigned k) { return static_cast<uint32_t>(uint64_t(n) * k / workers); };
  // An exception escaping a pool thread would terminate the program, and one leaving the
  // caller's chunk early would return while the workers still use `body`: every chunk catches
  // its own, and the first (by chunk) is rethrown on the caller once all chunks are done.
  std::vector<std::exception_ptr> failures(workers);
  pool().run(workers, [&](unsigned k) {
    const bool outer = insideParallelLoop;
    insideParallelLoop = true;
    try {
      body(chunkBegin(k), chunkBegin(k + 1), k);
    } catch (...) {
      failures[k] = std::current_exception();
    }
    insideParallelLoop = outer;
  });
  for (const std::exception_ptr& failure : failures)
    if (failure) std::rethrow_exception(failure);
}

}  // namespace sculpt
