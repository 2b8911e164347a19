#pragma once
// The frames of a rendered export, written as they come: each to name_####.png files and to
// H.264 videos (VideoEncoder). Until finish() succeeds, the sequence frames written are removed
// when this is destroyed and the videos are abandoned, so a cancelled or failed export leaves
// nothing behind.

#include <cstdint>
#include <filesystem>
#include <memory>
#include <vector>

#include "anim/frame_pattern.h"
#include "sculpt/video_encoder.h"

namespace sculpt::app {

class RenderedFrames {
 public:
  /// PNG sequences named by `pngs` (frame patterns, anim/frame_pattern.h) and videos `videos`
  /// at `fps`. Nothing is written before the first frame. Throws std::invalid_argument for a
  /// name that is not a frame pattern.
  RenderedFrames(std::vector<std::filesystem::path> pngs, std::vector<std::filesystem::path> videos,
                 double fps);
  ~RenderedFrames();
  RenderedFrames(const RenderedFrames&) = delete;
  RenderedFrames& operator=(const RenderedFrames&) = delete;

  /// Frame `number` (1-based: the sequence's file number): `width` x `height` RGBA8 pixels, top
  /// row first. The videos take the even part of the size they saw first. Throws (FileError,
  /// std::filesystem::filesystem_error).
  void write(uint32_t number, const std::vector<uint8_t>& pixels, int width, int height);
  /// Completes the videos; returns the bytes of every file written. Throws as write().
  uint64_t finish();
  /// The files written: the sequence frames (and, after finish(), the videos).
  const std::vector<std::filesystem::path>& files() const { return written_; }

 private:
  std::vector<FramePattern> pngs_;
  std::vector<std::filesystem::path> videos_;
  double fps_;
  std::vector<std::filesystem::path> written_;
  std::vector<std::unique_ptr<VideoEncoder>> encoders_;
  uint64_t bytes_ = 0;
  bool finished_ = false;
};

}  // namespace sculpt::app
