#pragma once
// The small state a fast reader (a 1 kHz haptic servo, the window) takes after every step,
// without touching the simulation: per stroke acting now, its material point's position and
// velocity, its target, spring stiffness and force; the simulated time; a generation number.
//
// ProbeChannel hands it from the simulation thread to one reader through three fixed slots (a
// triple buffer): publish() fills the writer's slot and swaps it with the middle one, read()
// swaps the middle one with the reader's when it is newer. Both are wait-free and O(1) (one
// atomic exchange; no lock, no allocation, no copy of the nodes), so neither side ever waits
// for the other. Each reader opens its own channel.

#include <array>
#include <atomic>
#include <cstdint>

#include <Eigen/Core>

namespace sculpt {

/// Strokes reported at most in one probe (the rest are counted in `strokeCount`).
inline constexpr int kProbeStrokes = 8;

struct ProbeStroke {
  uint64_t strokeId = 0;  ///< as SimulationLoop::beginStroke returned it
  Eigen::Vector3d point = Eigen::Vector3d::Zero();     ///< material point position (m)
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();  ///< its velocity (m/s)
  Eigen::Vector3d target = Eigen::Vector3d::Zero();    ///< spring target (m)
  double stiffness = 0.0;                              ///< N/m (0: the stroke has no spring)
  double force = 0.0;                                  ///< N, k |point - target|
};

struct SceneProbe {
  uint64_t generation = 0;   ///< 0: nothing published yet; then one more per publication
  uint64_t sceneId = 0;
  uint64_t steps = 0;        ///< steps taken on this scene since it started
  double simulatedTime = 0;  ///< s since the last reset
  int strokeCount = 0;       ///< strokes acting now (may exceed kProbeStrokes)
  std::array<ProbeStroke, kProbeStrokes> strokes{};
};

class ProbeChannel {
 public:
  /// Simulation thread: makes `probe` the newest.
  void publish(const SceneProbe& probe) {
    slots_[writer_] = probe;
    writer_ = middle_.exchange(writer_ | kFresh, std::memory_order_acq_rel) & kIndex;
  }
  /// Reader thread: the newest probe published (generation 0 before the first).
  const SceneProbe& read() {
    if (middle_.load(std::memory_order_relaxed) & kFresh)
      reader_ = middle_.exchange(reader_, std::memory_order_acq_rel) & kIndex;
    return slots_[reader_];
  }

 private:
  static constexpr unsigned kIndex = 3, kFresh = 4;
  std::array<SceneProbe, 3> slots_{};
  unsigned writer_ = 0, reader_ = 1;  // each touched by its own thread only
  std::atomic<unsigned> middle_{2};
};

}  // namespace sculpt
