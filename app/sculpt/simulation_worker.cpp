#include "sculpt/simulation_worker.h"

#include <chrono>

namespace sculpt::app {

SimulationWorker::SimulationWorker(LiveScene& scene) : scene_(scene), thread_([this] { run(); }) {}

SimulationWorker::~SimulationWorker() {
  stop_.store(true);
  thread_.join();
}

void SimulationWorker::run() {
  using Clock = std::chrono::steady_clock;
  constexpr auto kStep = std::chrono::microseconds(16667);  // real time at 60 steps per second
  auto next = Clock::now();
  while (!stop_.load()) {
    scene_.step();
    {
      const std::lock_guard lock(mutex_);
      published_.nodes = scene_.nodes();
      published_.gradients = scene_.nodeGradients();
      published_.stepMs = scene_.lastStepMs();
      ++published_.version;
    }
    next += kStep;
    const auto now = Clock::now();
    if (next > now) {
      std::this_thread::sleep_until(next);
    } else {
      next = now;  // slower than real time: run as fast as possible, do not try to catch up
    }
  }
}

bool SimulationWorker::fetchNewer(PublishedState& state) {
  const std::lock_guard lock(mutex_);
  if (published_.version <= state.version) return false;
  state = published_;
  return true;
}

}  // namespace sculpt::app
