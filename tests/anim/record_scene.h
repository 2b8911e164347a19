#pragma once
// A take of a real scene recorded in the test's own process, as `sculpt-cli record` records it:
// the scene built by the scene pipeline, the script started after the build's first step, the
// recorder observing every step after that.

#include <memory>
#include <optional>
#include <string>

#include "anim/recorder.h"
#include "scene/scene_builder.h"
#include "scene/scene_physics.h"
#include "tools/session_script.h"

namespace sculpt::test {

inline std::shared_ptr<const Take> recordScene(const SceneSource& source,
                                               const SceneSettings& settings,
                                               const std::optional<SessionScript>& script,
                                               double fps, uint32_t frames) {
  std::optional<SceneBuildPhase1> phase1 = buildSceneGeometry(source, settings, 1);
  std::unique_ptr<ScenePhysics> physics =
      ScenePhysics::build(phase1->geometry, phase1->solid, settings, nullptr, nullptr);
  if (script) physics->playScript(*script);
  Recorder recorder(fps);
  recorder.start();
  uint64_t steps = 0;
  while (recorder.frameCount() < frames) {
    const StepReport report = physics->step();
    StepState state;
    state.step = ++steps;
    state.simulatedTime = physics->simulatedTime();
    state.control = &physics->simulator().positions();
    state.report = &report;
    state.physics = physics.get();
    recorder.observe(state);
  }
  return recorder.take();
}

}  // namespace sculpt::test
