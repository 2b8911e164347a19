#pragma once
// The window's scene and its simulation: builds scenes (scene_builder.h, scene_physics.h) on a
// builder thread with progress and Cancel, and steps the current one on a simulation thread at
// up to 60 steps per second, so that drawing never waits for either.
//
// Threads (threaded mode). The caller (the UI) only ever takes short locks: to queue commands
// and settings, to read the build status, and to copy the latest published frame.
//  - Builder: runs one build at a time. Phase 1 ("display") gives the geometry; phase 2
//    ("physics") the simulation. When no simulation is running (the first scene, or after a
//    failed one) the geometry is handed over after phase 1 with its rest frame, so the first
//    frame comes early. Otherwise the current scene keeps running and drawing until both phases
//    are done, and the new geometry and simulation replace it together. A second load() or
//    cancelBuild() cancels the build in flight; a cancelled or failed build leaves the current
//    scene untouched.
//  - Simulation: owns the running ScenePhysics; between steps it takes a newly built one,
//    applies queued settings, reset and single steps, then publishes a frame (double-buffered:
//    filled outside the lock, swapped in under it). Frames of a replaced scene are never
//    published after its successor's geometry.
// Non-threaded mode (headless rendering, tests): nothing runs until advance(), which runs a
// queued build to completion and then does what one simulation iteration would do.

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "sculpt/scene_builder.h"
#include "sculpt/scene_physics.h"
#include "util/progress.h"

namespace sculpt::app {

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
  /// Observes the build's progress on the building thread (fraction, stage); returning false
  /// cancels the build like cancelBuild(). For headless progress output and tests.
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

  void setPlaying(bool playing);
  bool playing() const;
  /// One step while paused (or an extra one while playing).
  void stepOnce();
  /// Back to rest: rest positions, zero velocity, time 0 (a script being replayed ends).
  void reset();
  /// The window's pull tool, applied on the simulation thread before its next step: grab the
  /// material point at rest position `rest` towards `target`, move the target, let go.
  void grab(const Eigen::Vector3d& rest, const Eigen::Vector3d& target);
  void moveGrab(const Eigen::Vector3d& target);
  void releaseGrab(bool keep = false);  ///< keep: the spring stays (PullTool ReleaseMode::Keep)
  /// Edits of the user's work with the window's brushes, applied on the simulation thread in the
  /// order given before its next step (scene_physics.h): a material dab, a pin or unpin dab, the
  /// inflate brush pressed (or moved) and released.
  void paint(const Eigen::Vector3d& centre, const MaterialBrushSettings& brush);
  void pin(const Eigen::Vector3d& centre, double radius, bool pin);
  void pressInflate(const Eigen::Vector3d& centre, double radius, double pressure);
  void releaseInflate();
  /// The curve tool (scene_physics.h), on the simulation thread like the brushes.
  void grabCurve(std::vector<Eigen::Vector3d> polyline, bool smooth);
  void dragCurve(const Eigen::Vector3d& offset);
  void releaseCurve();
  /// Undo/redo of materials and pins on the running scene (empty samples: the uniform material
  /// of the settings). A failure lands in buildStatus().error.
  void restoreEdits(MaterialSamples samples, std::vector<uint32_t> pins);
  /// Asks the simulation for the edited state of the scene running now (after the edits queued
  /// before this call); takeEdits() gives it once captured (in non-threaded mode after advance()).
  void requestEdits();
  struct Edits {
    uint64_t sceneId = 0;
    MaterialSamples materials;
    std::vector<uint32_t> pins;
  };
  std::optional<Edits> takeEdits();
  /// Replays a session script on the current scene from its next step (once its physics is
  /// ready); an error (a grab point outside the solid) lands in buildStatus().error.
  void playScript(SessionScript script);
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
  struct Phase2 {  // a build between its phases
    Job job;
    SceneBuildPhase1 phase1;
    bool early = false;  // its geometry was handed over after phase 1
  };
  const Job* jobInFlightLocked() const;
  ProgressReporter progressFor(const Job& job);
  bool cancelled(const Job& job) const;
  void abandon(const Job& job);
  std::optional<Phase2> runPhase1(const Job& job);  // nullopt: failed or cancelled
  void runPhase2(const Phase2& work);
  void finishJob(const Job& job, const std::string& error, const StageTimes* times);
  void publishLocked(SceneFrame& frame);  // swaps `frame` in as the latest; mutex_ held
  void queuePhysicsCommand(std::function<std::string(ScenePhysics&)> command);
  bool simulationIteration();             // returns whether it published
  void builderLoop();
  void simulationLoop();

  const bool threaded_;

  mutable std::mutex mutex_;
  std::condition_variable builderWake_, simulationWake_;
  std::atomic<bool> stop_{false};
  // Builds (under mutex_)
  std::optional<Job> pendingJob_;
  std::optional<Job> runningJob_;
  uint64_t latestJob_ = 0;
  BuildStatus status_;
  ProgressCallback observer_;
  std::function<void()> notifier_;
  // Hand-over and frames (under mutex_)
  std::shared_ptr<const SceneGeometry> newGeometry_;
  std::unique_ptr<ScenePhysics> readyPhysics_;
  uint64_t currentScene_ = 0;    // the scene whose frames are published
  SceneSource currentSource_;    // and what it was built from
  SceneSettings currentSettings_;
  bool simulationExists_ = false;  // currentScene_ has a physics (ready or running)
  SceneFrame published_;
  uint64_t version_ = 0;
  // Commands (under mutex_)
  bool playing_ = true;
  int stepRequests_ = 0;
  bool resetRequested_ = false;
  std::optional<SessionScript> pendingScript_;
  struct GrabCommand {
    enum Kind { Grab, Move, Release } kind;
    Eigen::Vector3d rest, target;
    bool keep = false;
  };
  std::vector<GrabCommand> grabCommands_;
  /// Brush and undo edits for the simulation thread; each returns a problem sentence or "".
  std::vector<std::function<std::string(ScenePhysics&)>> physicsCommands_;
  std::optional<Edits> capturedEdits_;
  SceneSettings live_;  // the caller's latest settings
  uint64_t liveVersion_ = 0;
  // Simulation thread only (or the caller's in non-threaded mode)
  std::unique_ptr<ScenePhysics> physics_;
  uint64_t appliedLiveVersion_ = 0;
  SceneFrame back_;
  std::optional<Phase2> deferred_;  // non-threaded: phase 2 left for the next advance()

  std::thread builder_, simulation_;  // last: they start after everything they use exists
};

}  // namespace sculpt::app
