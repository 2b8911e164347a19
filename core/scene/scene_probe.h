#pragma once
// The small state a fast reader (a 1 kHz haptic servo, the window) takes after every step,
// without touching the simulation: per stroke acting now, its material point's position and
// velocity, its target, spring stiffness and force; the simulated time; a generation number.
//
// ProbeChannel hands it from the simulation thread to one reader through a triple buffer
// (util/triple_buffer.h): wait-free and O(1) on both sides, no copy of the nodes. Each reader
// opens its own channel.

#include <array>
#include <cstdint>

#include <Eigen/Core>

#include "util/triple_buffer.h"

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
  /// Non-zero for a contact (ToolSpring::normal): the outward surface normal (unit).
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
};

struct SceneProbe {
  uint64_t generation = 0;   ///< 0: nothing published yet; then one more per publication
  uint64_t sceneId = 0;
  uint64_t steps = 0;        ///< steps taken on this scene since it started
  double simulatedTime = 0;  ///< s since the last reset
  /// std::chrono::steady_clock time of publication (ns since its epoch): a reader's age of the
  /// data, whatever its own update rate.
  int64_t publishedNs = 0;
  int strokeCount = 0;       ///< strokes acting now (may exceed kProbeStrokes)
  std::array<ProbeStroke, kProbeStrokes> strokes{};
};

/// One reader's channel (util/triple_buffer.h).
using ProbeChannel = TripleBuffer<SceneProbe>;

}  // namespace sculpt
