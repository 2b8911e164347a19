#pragma once
// Small helpers the window's frame code shares: its clock and the background clear.

#include <chrono>

#include <glm/glm.hpp>

#include "render/gl.h"

namespace sculpt::app {

using Clock = std::chrono::steady_clock;

inline double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

/// The view's background colour (RGB in [0, 1]). `tint` in [0, 1] saturates the grey towards
/// red: the force the stylus feels (McDonnell-Qin Fig. 8).
inline glm::vec3 backgroundColour(float tint = 0.0f) {
  return {0.16f + 0.5f * tint, 0.17f - 0.08f * tint, 0.19f - 0.1f * tint};
}

/// Clears to the background colour (transparent for screenshots that ask for it).
inline void clearBackground(bool transparent, float tint = 0.0f) {
  const glm::vec3 colour = backgroundColour(tint);
  glClearColor(colour.r, colour.g, colour.b, transparent ? 0.0f : 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

}  // namespace sculpt::app
