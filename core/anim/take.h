#pragma once
// A recorded take: the control points of every sampled frame at a fixed simulated frame rate,
// in segments of one scene each (a rebuild, e.g. after a topology edit, starts a new segment),
// and the painted per-cell fields from the frame where they last changed. O(control points) per
// frame: the surface is evaluated from them on export (take_surface.h), so a long take stays
// small in memory (control points are kept as float32).

#include <cstdint>
#include <memory>
#include <vector>

#include "anim/animated_surface.h"
#include "mesh/cell_complex.h"
#include "scene/scene_surface_map.h"

namespace sculpt {

struct TakeSegment {
  std::shared_ptr<const SceneSurfaceMap>
      surface;  ///< the scene's geometry and control-to-nodes map
  FrameRange frames;
};

/// Painted fields in force from `firstFrame` on (until the next change).
struct TakeFields {
  uint32_t firstFrame = 0;
  std::shared_ptr<const CellFields> fields;
};

/// The most frames a take holds (about 55 minutes at 30 fps).
inline constexpr uint32_t kMaxTakeFrames = 100'000;

class Take {
 public:
  explicit Take(double fps = 30.0) : fps_(fps) {}

  double fps() const { return fps_; }
  uint32_t frameCount() const { return static_cast<uint32_t>(frameOffset_.size()); }
  double duration() const { return frameCount() == 0 ? 0.0 : (frameCount() - 1) / fps_; }
  const std::vector<TakeSegment>& segments() const { return segments_; }
  const std::vector<TakeFields>& fields() const { return fields_; }
  uint32_t segmentOf(uint32_t frame) const;
  /// The fields in force at `frame` (null when none were recorded).
  const CellFields* fieldsAt(uint32_t frame) const;

  /// The control points of `frame` (#control by 3, double).
  void controlPoints(uint32_t frame, Points& control) const;

  /// Appends a frame of the scene `surface` (a new segment when it is not the last one's).
  void append(const std::shared_ptr<const SceneSurfaceMap>& surface, const Points& control);
  /// Records the fields in force from the next appended frame on.
  void setFields(std::shared_ptr<const CellFields> fields);

  /// Bytes held by the frames (not the shared scenes).
  size_t memoryBytes() const;

 private:
  double fps_;
  std::vector<TakeSegment> segments_;
  std::vector<TakeFields> fields_;
  std::vector<float> control_;         // 3 per control point per frame
  std::vector<uint64_t> frameOffset_;  // per frame: its first value in control_
};

}  // namespace sculpt
