#pragma once
// Playing a take back without simulating: a recorded frame as the SceneFrame the window draws
// (nodes and node gradients through the scene's own maps, so it looks as it did live; the
// strain energy is not recorded and reads 0).

#include <cstdint>

#include "anim/take.h"
#include "scene/scene_physics.h"

namespace sculpt {

/// Fills `out` (all but version) with frame `frame` of `take`. Throws std::out_of_range.
void playbackFrame(const Take& take, uint32_t frame, SceneFrame& out);

}  // namespace sculpt
