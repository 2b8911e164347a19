#pragma once
// A take (take.h) as an AnimatedSurface: the frames' control points turned into the embedded
// surface with the CPU Phong deformation (embed/embedded_deformer.h, the reference the GPU
// deformer is tested against) and into the level-K solid (scene/scene_surface_map.h), on demand,
// optionally over a range of the take's frames and at a fraction of its frame rate.

#include <memory>
#include <optional>
#include <vector>

#include "anim/animated_surface.h"
#include "anim/take.h"
#include "embed/embedded_deformer.h"
#include "embed/interpolation_method.h"

namespace sculpt {

/// How many of `count` consecutive frames every `every`-th one keeps, starting with the first.
inline uint32_t framesEvery(uint32_t count, uint32_t every) { return (count + every - 1) / every; }

class TakeSurface : public AnimatedSurface {
 public:
  /// Frames [range.first, range.first + range.count) of `take` (count 0: to the end), every
  /// `every`-th of them from the first (its frame f is the take's range.first + f x every, at
  /// the take's fps / every). Throws std::invalid_argument for an empty take, a range outside
  /// it or every = 0.
  explicit TakeSurface(std::shared_ptr<const Take> take, FrameRange range = {}, uint32_t every = 1,
                       InterpolationMethod method = InterpolationMethod::Phong);
  ~TakeSurface() override;

  double fps() const override { return take_->fps() / every_; }
  uint32_t frameCount() const override { return frames_; }
  uint32_t segmentCount() const override { return static_cast<uint32_t>(segments_.size()); }
  FrameRange segment(uint32_t s) const override { return segments_[s].frames; }
  const SurfaceMesh& restSurface(uint32_t s) const override;
  const std::vector<float>& restVertexNormals(uint32_t s) const override;
  const std::vector<uint32_t>& triangles(uint32_t s) const override;
  const VolumeMesh& restSolid(uint32_t s) const override;
  void evaluateSurface(uint32_t frame, SurfaceFrameData& out) const override;
  void evaluateSolid(uint32_t frame, SolidFrameData& out) const override;

  /// Vertices of the largest segment's surface (for size estimates).
  uint32_t maxVertices() const;

 private:
  struct Segment {
    std::shared_ptr<const SceneSurfaceMap> surface;
    FrameRange frames;  // in this view's frame numbers
    std::vector<float> restNormals;
    std::vector<uint32_t> normalAnchors;  // of the source surface's own normals
    std::vector<uint32_t> vertexAnchors;  // 0, 1, ...: one rest normal per vertex
    mutable std::unique_ptr<EmbeddedDeformer> deformer;  // made on first use
  };
  const Segment& segmentFor(uint32_t frame) const;
  uint32_t takeFrame(uint32_t frame) const { return range_.first + frame * every_; }
  EmbeddedDeformer& deformer(const Segment& segment) const;

  std::shared_ptr<const Take> take_;
  FrameRange range_;  // of the take's frames
  uint32_t every_ = 1, frames_ = 0;
  InterpolationMethod method_;
  std::vector<Segment> segments_;
  mutable Points control_, nodes_;
};

}  // namespace sculpt
