#pragma once
// The running simulation of a scene: steps its ScenePhysics on its own thread at the scene's
// fixed simulated step, paced by its own clock, and applies everything sent to it (tool strokes,
// edits, settings, reset, a script) at the next step boundary.
//
// Pacing: while playing, step k of a run is due at t0 + k h / rate of wall time (h the time
// step, rate the wanted ratio of simulated to real time, 1 by default), so the simulated time
// advances at `rate` whatever else happens. Commands never wake it early and never skip a step:
// a tool updated at 1 kHz has its newest input applied once per step. When a step takes longer
// than its share, the next ones start at once until the clock is caught up, as long as the lag
// is at most kCatchUpSteps shares; beyond that the clock is rebased to that lag (a simulation
// slower than the clock runs flat out, and a stall is not followed by a long burst).
// While paused, commands are applied as they come (no step) and the state is published.
//
// What leaves the loop:
//  - frames (SceneFrame, O(nodes + cells)): double-buffered, the newest one fetched by the UI;
//  - step observers: called on the simulation thread after every step with the step's state
//    (a recorder sees every step, not only the frames the UI draws);
//  - probes (scene_probe.h): a few hundred bytes per step that any number of readers, one per
//    channel, take wait-free.
// Non-threaded mode (headless rendering, the command line, tests): nothing runs by itself;
// iterate() does what one iteration of the thread would do, without waiting.

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "scene/scene_physics.h"
#include "scene/scene_probe.h"
#include "tools/tool.h"

namespace sculpt {

/// The state after a step, as observers see it (valid during the call only).
struct StepState {
  uint64_t sceneId = 0;
  uint64_t step = 0;           ///< steps taken on this scene, this one included
  double simulatedTime = 0.0;  ///< s since the last reset
  const Points* control = nullptr;  ///< the control points
  const StepReport* report = nullptr;
  /// The scene that stepped: for what else an observer reads on this thread (its surface map,
  /// its painted fields). Not to be kept or changed.
  const ScenePhysics* physics = nullptr;
};
using StepObserver = std::function<void(const StepState&)>;

/// The edited state of the running scene, as a project keeps it.
struct SceneEdits {
  uint64_t sceneId = 0;
  MaterialSamples materials;
  std::vector<uint32_t> pins;
};

class SimulationLoop {
 public:
  /// How far behind the clock (in steps' shares of wall time) late steps are made up.
  static constexpr int kCatchUpSteps = 4;

  /// threaded: a simulation thread runs the loop; otherwise iterate() does. Starts playing.
  explicit SimulationLoop(bool threaded);
  ~SimulationLoop();
  SimulationLoop(const SimulationLoop&) = delete;
  SimulationLoop& operator=(const SimulationLoop&) = delete;

  // Scenes (the builder's side)
  /// Shows `frame` (a rest frame of a scene without physics yet) as the newest; frames of any
  /// other scene are not published from now on.
  void showFrame(SceneFrame frame);
  /// Hands over a built scene with its first frame: it replaces the running one at the next
  /// step boundary (the old one is freed on the simulation thread, outside any lock).
  void install(std::unique_ptr<ScenePhysics> physics, SceneFrame first);
  /// True once a scene has been installed (it runs, or is about to).
  bool hasSimulation() const;

  // Frames
  /// Copies the newest frame into `frame` when it is newer than frame.version.
  bool fetchNewer(SceneFrame& frame);
  /// Called whenever a frame is published (on the publishing thread; keep it short).
  void setChangeNotifier(std::function<void()> notifier);
  /// Called with a sentence when a command or the simulation fails (on the simulation thread).
  void setProblemHandler(std::function<void(const std::string&)> handler);

  // Running
  void setPlaying(bool playing);
  bool playing() const;
  /// One step while paused (or an extra one while playing).
  void stepOnce();
  /// Back to rest: rest positions, zero velocity, time 0; strokes and a script end.
  void reset();
  /// Simulated seconds per wall-clock second while playing (> 0; default 1).
  void setRealTimeRate(double rate);
  /// Whether frames carry the strain energy density (ScenePhysics::setStrainEnergyWanted): the
  /// window asks for it while the field is on show. Off at first.
  void setStrainEnergyShown(bool shown);
  /// Settings that apply live (material, integrator, time step, gravity; scene_builder.h).
  void applyLive(const SceneSettings& settings);
  SceneSettings liveSettings() const;

  // Tools (tools/tool.h): applied at the next step boundary, in the order sent
  /// Starts a stroke of `tool`; returns its id. A stroke that cannot start reports a problem.
  uint64_t beginStroke(std::unique_ptr<Tool> tool, const ToolInput& input);
  /// Only the newest update of a stroke before a step is applied.
  void updateStroke(uint64_t stroke, const ToolInput& input);
  void endStroke(uint64_t stroke, const ToolInput& input);
  /// Replays a session script from the next step on.
  void playScript(SessionScript script);
  /// Undo/redo of materials and pins (empty samples: the live uniform material).
  void restoreEdits(MaterialSamples samples, std::vector<uint32_t> pins);
  /// Asks for the edited state after the commands sent before; takeEdits() gives it once.
  void requestEdits();
  std::optional<SceneEdits> takeEdits();

  // Observers and probes
  /// Registers an observer; returns an id for removeStepObserver.
  uint64_t addStepObserver(StepObserver observer);
  void removeStepObserver(uint64_t id);
  /// A new channel for one reader thread; the loop publishes into it after every step (and after
  /// commands applied while paused) until the channel is released by every holder but the loop.
  std::shared_ptr<ProbeChannel> openProbe();

  /// Non-threaded mode: applies what was sent and takes a step when playing or asked for.
  /// Returns whether a frame was published. A no-op in threaded mode.
  bool iterate();

 private:
  struct Command {
    enum Kind { Begin, Update, End, Other } kind = Other;
    uint64_t stroke = 0;
    std::unique_ptr<Tool> tool;
    ToolInput input;
    std::function<std::string(ScenePhysics&)> other;  // returns a problem sentence or ""
  };
  void queue(Command command);
  void queueStroke(int kind, uint64_t stroke, std::unique_ptr<Tool> tool, const ToolInput& input);
  bool runIteration();  // the simulation thread's (or iterate()'s) work
  void publishProbe(ScenePhysics& physics);
  void notifyStep(ScenePhysics& physics, const StepReport& report);
  void publishLocked(SceneFrame& frame);
  void report(const std::string& problem);
  bool workWaitingLocked(bool playingToo) const;
  void run();

  const bool threaded_;
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  std::atomic<bool> stop_{false};
  std::atomic<bool> strainEnergyShown_{false};
  // Under mutex_
  std::unique_ptr<ScenePhysics> ready_;
  uint64_t currentScene_ = 0;
  bool simulationExists_ = false;
  SceneFrame published_;
  uint64_t version_ = 0;
  std::function<void()> notifier_;
  std::function<void(const std::string&)> problemHandler_;
  bool playing_ = true;
  int stepRequests_ = 0;
  bool resetRequested_ = false;
  double rate_ = 1.0;
  bool rateChanged_ = false;
  std::optional<SessionScript> pendingScript_;
  std::vector<Command> commands_;
  std::optional<SceneEdits> capturedEdits_;
  SceneSettings live_;
  uint64_t liveVersion_ = 0;
  uint64_t nextStroke_ = 0;
  uint64_t nextObserver_ = 0;
  std::vector<std::pair<uint64_t, std::shared_ptr<const StepObserver>>> observers_;
  std::vector<std::shared_ptr<ProbeChannel>> probes_;
  // Simulation thread only (or iterate()'s caller)
  std::unique_ptr<ScenePhysics> physics_;
  uint64_t appliedLiveVersion_ = 0;
  uint64_t steps_ = 0, probeGeneration_ = 0;
  SceneFrame back_;

  std::thread thread_;  // last: it starts after everything it uses exists
};

}  // namespace sculpt
