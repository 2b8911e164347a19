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
class WorkerPool {
 public:
  explicit WorkerPool(unsigned helpers)
      : spin_(helpers + 1 <= std::max(1u, std::thread::hardware_concurrency())) {
    for (unsigned k = 0; k < helpers; ++k) threads_.emplace_back([this, k] { loop(k + 1); });
  }
  ~WorkerPool() {
    {
      std::lock_guard lock(mutex_);
      stopping_ = true;
      generation_.fetch_add(1, std::memory_order_release);
    }
    wake_.notify_all();
    for (auto& t : threads_) t.join();
  }

  // Runs task(worker) on workers 1..count-1 of the pool and 0 on the caller; returns when all
  // are done. Calls from several threads at once are serialised.
  void run(unsigned count, const std::function<void(unsigned)>& task) {
    std::lock_guard serial(runMutex_);
    {
      std::lock_guard lock(mutex_);
      task_ = &task;
      active_ = count - 1;
      pending_.store(count - 1, std::memory_order_relaxed);
      generation_.fetch_add(1, std::memory_order_release);
    }
    wake_.notify_all();
    task(0);
    if (spinUntil([this] { return pending_.load(std::memory_order_acquire) == 0; })) return;
    std::unique_lock lock(mutex_);
    done_.wait(lock, [this] { return pending_.load(std::memory_order_acquire) == 0; });
  }

  unsigned size() const { return static_cast<unsigned>(threads_.size()) + 1; }

 private:
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

  void loop(unsigned worker) {
    uint64_t seen = 0;
    for (;;) {
      spinUntil([&] { return generation_.load(std::memory_order_acquire) != seen; });
      const std::function<void(unsigned)>* task = nullptr;
      {
        // The generation, the task and the worker count are read together under the lock
        // that publishes them.
        std::unique_lock lock(mutex_);
        wake_.wait(lock, [&] { return generation_.load(std::memory_order_relaxed) != seen; });
        seen = generation_.load(std::memory_order_relaxed);
        if (stopping_) return;
        if (worker > active_) continue;
        task = task_;
      }
      (*task)(worker);
      if (pending_.fetch_sub(1, std::memory_order_acq_rel) == 1) {
        std::lock_guard lock(mutex_);
        done_.notify_one();
      }
    }
  }

  const bool spin_;
  std::vector<std::thread> threads_;
  std::mutex mutex_, runMutex_;
  std::condition_variable wake_, done_;
  const std::function<void(unsigned)>* task_ = nullptr;  // guarded by mutex_
  unsigned active_ = 0;                                  // guarded by mutex_
  bool stopping_ = false;                                // guarded by mutex_
  std::atomic<unsigned> pending_{0};
  std::atomic<uint64_t> generation_{0};  // written under mutex_, polled without it
};

WorkerPool& pool() {
  static WorkerPool instance(workerCount() - 1);
  return instance;
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
