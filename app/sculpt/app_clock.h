#pragma once
// Small helpers the window's frame code shares: its clock and the background clear.

#include <chrono>

#include "render/gl.h"

namespace sculpt::app {

using Clock = std::chrono::steady_clock;

inline double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

/// The view's background colour (transparent for screenshots that ask for it).
/// `tint` in [0, 1] saturates the grey towards red: the force the stylus feels (McDonnell-Qin
/// Fig. 8).
inline void clearBackground(bool transparent, float tint = 0.0f) {
  glClearColor(0.16f + 0.5f * tint, 0.17f - 0.08f * tint, 0.19f - 0.1f * tint,
               transparent ? 0.0f : 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

}  // namespace sculpt::app
