#pragma once
// A framebuffer with colour and depth attachments, for headless rendering and screenshots.

#include <cstdint>
#include <vector>

#include "render/gl.h"

namespace sculpt::render {

class OffscreenTarget {
 public:
  /// Throws std::runtime_error when the framebuffer is incomplete.
  OffscreenTarget(int width, int height);
  ~OffscreenTarget();
  OffscreenTarget(const OffscreenTarget&) = delete;
  OffscreenTarget& operator=(const OffscreenTarget&) = delete;

  void bind() const;
  int width() const { return width_; }
  int height() const { return height_; }
  /// RGBA8 pixels, top row first (flipped from GL's bottom-up order).
  std::vector<uint8_t> readPixels() const;

 private:
  int width_, height_;
  GLuint framebuffer_ = 0, colour_ = 0, depth_ = 0;
};

}  // namespace sculpt::render
