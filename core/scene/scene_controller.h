#pragma once
// A scene's life: builds scenes (scene_builder.h, scene_physics.h) on a builder thread with
// progress and Cancel, and runs the current one in a SimulationLoop (simulation_loop.h), so that
// drawing never waits for either. The window, the command line and the tests use it alike.
//
// Threads (threaded mode). The caller (the UI) only ever takes short locks: to queue commands
// and settings, to read the build status, and to copy the latest published frame.
//  - Builder: runs one build at a time. Phase 1 ("display") gives the geometry; phase 2
//    ("physics") the simulation. When no simulation is running (the first scene, or after a
//    failed one) the geometry is handed over after phase 1 with its rest frame, so the first
//    frame comes early. Otherwise the current scene keeps running and drawing until both phases
//    are done, and the new geometry and simulation replace it together. Phase 2 starts on a
//    thread of its own once phase 1 has the solid, and phase 1 makes the drawn surface
//    meanwhile. A second load() or cancelBuild() cancels the build in flight; a cancelled or
//    failed build leaves the current scene untouched.
//  - Simulation: the loop's thread owns the running ScenePhysics and takes a newly built one at
//    a step boundary. Frames of a replaced scene are never published after its successor's
//    geometry.
// Non-threaded mode (headless rendering, tests): nothing runs until advance(), which runs a
// queued build to completion and then does what one simulation iteration would do.

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <future>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "scene/scene_builder.h"
#include "scene/scene_physics.h"
#include "scene/simulation_loop.h"
#include "util/progress.h"

namespace sculpt {

struct BuildStatus {
  bool running = false;    ///< a build is queued or in progress
  double fraction = 0.0;   ///< of the whole build (both phases), in [0, 1]
  std::string stage;       ///< what it is doing now
  std::string error;       ///< why the last build failed (one sentence); empty otherwise
  StageTimes stageMs;      ///< stage times of the last completed build (both phases)
};

class SceneController {
 public:
  /// threaded: builder and simulation threads (the window); otherwise everything runs on the
  /// caller's thread inside advance() (headless, tests, deterministic). Starts playing.
  explicit SceneController(bool threaded);
  /// Cancels the build in flight and joins the threads.
  ~SceneController();
  SceneController(const SceneController&) = delete;
  SceneController& operator=(const SceneController&) = delete;

  /// Starts building `source` with `settings` (cancelling a build in flight); the current scene
  /// keeps running and drawing until the new one is ready. Throws std::invalid_argument for
  /// invalid settings (sceneSettingsProblem), before changing anything.
  void load(const SceneSource& source, const SceneSettings& settings);
  BuildStatus buildStatus() const;
  /// Cancels the queued or running build; the current scene stays, no error is reported.
  void cancelBuild();
  /// Observes the build's progress (fraction, stage) on the threads that build: phase 1's, and
  /// phase 2's own; returning false cancels the build like cancelBuild(). For headless progress
  /// output and tests.
  void setProgressObserver(ProgressCallback observer);

  /// Called (on the publishing thread, under the controller's lock: keep it short and do not call
  /// back into the controller) whenever a frame is published or a build finishes; the window
  /// wakes its event loop with it (glfwPostEmptyEvent).
  void setChangeNotifier(std::function<void()> notifier);

  /// The geometry of a newly built scene, once (null otherwise). Take it before fetchNewer():
  /// frames published after it belong to it (SceneFrame::sceneId).
  std::shared_ptr<const SceneGeometry> takeNewGeometry();
  /// Copies the latest published frame into `frame` when it is newer than frame.version.
  bool fetchNewer(SceneFrame& frame);

  /// The running simulation: play, pause, step, reset, tool strokes, edits, scripts, step
  /// observers and probes (simulation_loop.h).
  SimulationLoop& loop() { return loop_; }
  const SimulationLoop& loop() const { return loop_; }

  /// Level, cage or render level changes (against settings()) rebuild the scene of source()
  /// with load(); the rest applies live. Throws std::invalid_argument for invalid settings.
  void applySettings(const SceneSettings& settings);
  /// The settings in force: level, cage and render level of the build in flight or else of the
  /// scene shown (a cancelled or failed build does not change them), the rest as last given.
  SceneSettings settings() const;
  /// The source of the build in flight, or else of the scene shown.
  SceneSource source() const;

  /// Non-threaded mode only (a no-op otherwise): runs a queued build to completion, then one
  /// simulation iteration (queued settings, reset, a step if playing or asked for). With
  /// `displayFirst`, a build whose geometry is handed over early (nothing simulates yet) stops
  /// after phase 1 and the next advance() runs phase 2: a headless first frame then comes as
  /// early as a windowed one.
  void advance(bool displayFirst = false);

 private:
  struct Job {
    uint64_t id = 0;
    SceneSource source;
    SceneSettings settings;
    std::shared_ptr<std::atomic<bool>> cancel;
  };
  struct PhysicsBuild {
    std::unique_ptr<ScenePhysics> physics;  // null: cancelled
    StageTimes stageMs;
  };
  struct Phase2 {  // a build between its phases
    Job job;
    SceneBuildPhase1 phase1;
    bool early = false;  // its geometry was handed over after phase 1
    // Phase 2, started on its own thread as soon as the solid was built: it runs while the
    // drawn surface is made (and, headless, while the rest shape is drawn).
    std::future<PhysicsBuild> physics;
  };
  const Job* jobInFlightLocked() const;
  ProgressReporter progressFor(const Job& job);
  bool cancelled(const Job& job) const;
  void abandon(const Job& job);
  std::optional<Phase2> runPhase1(const Job& job);  // nullopt: failed or cancelled
  std::future<PhysicsBuild> startPhysics(const Job& job, const SceneSolidPart& part,
                                         std::shared_future<void> stencilsReady);
  void runPhase2(Phase2& work);
  void finishJob(const Job& job, const std::string& error, const StageTimes* times);
  void builderLoop();

  const bool threaded_;
  SimulationLoop loop_;

  mutable std::mutex mutex_;
  std::condition_variable builderWake_;
  std::atomic<bool> stop_{false};
  // Builds (under mutex_)
  std::optional<Job> pendingJob_;
  std::optional<Job> runningJob_;
  uint64_t latestJob_ = 0;
  BuildStatus status_;
  ProgressCallback observer_;
  std::function<void()> notifier_;
  std::shared_ptr<const SceneGeometry> newGeometry_;
  uint64_t currentScene_ = 0;    // the scene shown
  SceneSource currentSource_;    // and what it was built from
  SceneSettings currentSettings_;
  SceneSettings live_;  // the caller's latest settings
  // Builder thread only (or the caller's in non-threaded mode)
  std::optional<Phase2> deferred_;  // non-threaded: phase 2 left for the next advance()

  std::thread builder_;  // last: it starts after everything it uses exists
};

}  // namespace sculpt
