#pragma once
// H.264 video through the ffmpeg program: frames go to it as raw RGBA on a pipe, it writes a
// temporary file beside the output, renamed to the output once ffmpeg has exited cleanly (and
// removed otherwise), so a failed or interrupted encode leaves nothing under the final name.

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <span>
#include <string>

namespace sculpt::app {

class VideoEncoder {
 public:
  /// Starts ffmpeg for `width` x `height` (both even) frames at `fps`. Throws FileError.
  VideoEncoder(std::filesystem::path path, int width, int height, double fps);
  /// Without finish(): stops ffmpeg and removes the temporary file.
  ~VideoEncoder();
  VideoEncoder(const VideoEncoder&) = delete;
  VideoEncoder& operator=(const VideoEncoder&) = delete;

  int width() const { return width_; }
  int height() const { return height_; }
  /// One frame: width x height RGBA8 pixels, top row first. Throws FileError when ffmpeg has
  /// stopped taking them.
  void write(std::span<const uint8_t> rgba);
  /// Closes the pipe, waits for ffmpeg and renames the video into place; returns its size.
  /// Throws FileError (ffmpeg failed: nothing is left behind).
  uint64_t finish();

 private:
  void abandon();
  std::filesystem::path path_, temporary_;
  int width_, height_;
  FILE* pipe_ = nullptr;
};

}  // namespace sculpt::app
