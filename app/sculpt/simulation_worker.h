#pragma once
// Runs the scene's simulation on its own thread so that drawing never waits for it: the worker
// steps at up to 60 steps per second and publishes each new state (node positions and node
// gradients, O(nodes)) under a mutex; the frame copies the latest one when there is a new one.

#include <atomic>
#include <cstdint>
#include <mutex>
#include <thread>
#include <vector>

#include <Eigen/Core>

#include "sculpt/live_scene.h"

namespace sculpt::app {

struct PublishedState {
  uint64_t version = 0;
  Points nodes;
  std::vector<Eigen::Matrix3d> gradients;
  double stepMs = 0.0;
};

class SimulationWorker {
 public:
  /// Starts stepping `scene` (which the worker then owns for writing until destruction).
  explicit SimulationWorker(LiveScene& scene);
  /// Stops after the current step and joins.
  ~SimulationWorker();
  SimulationWorker(const SimulationWorker&) = delete;
  SimulationWorker& operator=(const SimulationWorker&) = delete;

  /// Copies the published state into `state` when it is newer than state.version.
  bool fetchNewer(PublishedState& state);

 private:
  void run();

  LiveScene& scene_;
  std::atomic<bool> stop_{false};
  std::mutex mutex_;
  PublishedState published_;
  std::thread thread_;  // last: starts after everything it uses exists
};

}  // namespace sculpt::app
