#include "util/parallel_for.h"

#include <algorithm>
#include <condition_variable>
#include <cstdlib>
#include <mutex>
#include <thread>
#include <vector>

namespace sculpt {
namespace {

// Worker threads that live for the whole program: a fork-join costs a wake-up instead of a
// thread creation (tens of microseconds), which matters for per-step loops of a millisecond.
class WorkerPool {
 public:
  explicit WorkerPool(unsigned helpers) {
    for (unsigned k = 0; k < helpers; ++k) threads_.emplace_back([this, k] { loop(k + 1); });
  }
  ~WorkerPool() {
    {
      std::lock_guard lock(mutex_);
      stopping_ = true;
      ++generation_;
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
      pending_ = count - 1;
      ++generation_;
    }
    wake_.notify_all();
    task(0);
    std::unique_lock lock(mutex_);
    done_.wait(lock, [this] { return pending_ == 0; });
    task_ = nullptr;
  }

  unsigned size() const { return static_cast<unsigned>(threads_.size()) + 1; }

 private:
  void loop(unsigned worker) {
    uint64_t seen = 0;
    for (;;) {
      const std::function<void(unsigned)>* task = nullptr;
      {
        std::unique_lock lock(mutex_);
        wake_.wait(lock, [&] { return generation_ != seen; });
        seen = generation_;
        if (stopping_) return;
        if (worker > active_) continue;
        task = task_;
      }
      (*task)(worker);
      std::lock_guard lock(mutex_);
      if (--pending_ == 0) done_.notify_one();
    }
  }

  std::vector<std::thread> threads_;
  std::mutex mutex_, runMutex_;
  std::condition_variable wake_, done_;
  const std::function<void(unsigned)>* task_ = nullptr;
  unsigned active_ = 0, pending_ = 0;
  uint64_t generation_ = 0;
  bool stopping_ = false;
};

WorkerPool& pool() {
  static WorkerPool instance(workerCount() - 1);
  return instance;
}

// True on the pool's own threads: a nested parallel loop then runs inline instead of waiting
// for workers that are busy running its parent.
thread_local bool insideParallelLoop = false;

}  // namespace

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
  pool().run(workers, [&](unsigned k) {
    const bool outer = insideParallelLoop;
    insideParallelLoop = true;
    body(chunkBegin(k), chunkBegin(k + 1), k);
    insideParallelLoop = outer;
  });
}

}  // namespace sculpt
