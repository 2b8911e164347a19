#include "util/parallel_for.h"

#include <algorithm>
#include <thread>
#include <vector>

namespace sculpt {

unsigned workerCount() { return std::max(1u, std::thread::hardware_concurrency()); }

void parallelChunks(uint32_t n, uint32_t minParallel,
                    const std::function<void(uint32_t, uint32_t, unsigned)>& body) {
  const unsigned workers = n < minParallel ? 1u : std::min<unsigned>(workerCount(), n);
  if (workers <= 1) {
    body(0, n, 0);
    return;
  }
  std::vector<std::thread> threads;
  threads.reserve(workers - 1);
  auto chunkBegin = [&](unsigned k) { return static_cast<uint32_t>(uint64_t(n) * k / workers); };
  for (unsigned k = 1; k < workers; ++k)
    threads.emplace_back([&, k] { body(chunkBegin(k), chunkBegin(k + 1), k); });
  body(chunkBegin(0), chunkBegin(1), 0);
  for (auto& t : threads) t.join();
}

}  // namespace sculpt
