#pragma once
// Key frames for a morph-target animation: the frames between two keys are replaced by the
// linear interpolation of the keys' positions, so keys are chosen where that interpolation would
// stray more than a tolerance from the recorded surface.

#include <cstdint>
#include <functional>
#include <vector>

#include "anim/animated_surface.h"

namespace sculpt {

/// The keys of one segment.
struct MorphKeys {
  std::vector<uint32_t> frames;  ///< take frame indices, increasing; first and last of the segment
  double maxError = 0.0;         ///< metres: the largest vertex distance at a frame between keys
};

struct MorphKeyOptions {
  double tolerance = 0.0;  ///< metres: the largest vertex distance allowed between keys
  /// The most frames from one key to the next, so that the frames held in memory stay bounded.
  uint32_t maxSpan = 32;
};

/// The absolute tolerance for a relative one: tolerance_m = relative x the diagonal of the
/// bounding box of the rest surface's positions.
double morphKeyTolerance(const SurfaceMesh& rest, double relative);

/// Called after every evaluated frame; returns false to stop (chooseMorphKeys then returns the
/// keys so far, which are of no use).
using MorphFrameCallback = std::function<bool(uint32_t frame)>;
/// Called once per key, in order, with its evaluated surface.
using MorphKeyCallback = std::function<void(uint32_t frame, const SurfaceFrameData& surface)>;

/// Greedy choice: the segment's first frame is a key; from key a the next key is the last b
/// (b - a <= maxSpan) such that every frame between them lies within the tolerance of the
/// interpolation of a and b; the segment's last frame is a key. Evaluates each frame of the
/// segment once and holds at most maxSpan + 1 of them.
MorphKeys chooseMorphKeys(const AnimatedSurface& take, uint32_t segment,
                          const MorphKeyOptions& options, const MorphFrameCallback& onFrame = {},
                          const MorphKeyCallback& onKey = {});

}  // namespace sculpt
