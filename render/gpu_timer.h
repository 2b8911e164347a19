#pragma once
// GPU time of a span of draw calls (GL_TIME_ELAPSED queries), read one frame late so that the
// frame never waits for the GPU: begin()/end() around the calls, then lastMilliseconds().

#include "render/gl.h"

namespace sculpt::render {

class GpuTimer {
 public:
  GpuTimer();
  ~GpuTimer();
  GpuTimer(const GpuTimer&) = delete;
  GpuTimer& operator=(const GpuTimer&) = delete;

  void begin();
  void end();
  /// The most recent finished measurement (0 before the first).
  double lastMilliseconds();

 private:
  GLuint queries_[2] = {0, 0};
  int current_ = 0;          ///< the query begin() uses next
  bool pending_[2] = {false, false};
  double last_ = 0.0;
};

}  // namespace sculpt::render
