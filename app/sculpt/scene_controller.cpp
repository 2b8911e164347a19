#include "sculpt/scene_controller.h"

#include <chrono>
#include <stdexcept>
#include <utility>

namespace sculpt::app {

SceneController::SceneController(bool threaded) : threaded_(threaded) {
  if (!threaded_) return;
  builder_ = std::thread([this] { builderLoop(); });
  simulation_ = std::thread([this] { simulationLoop(); });
}

SceneController::~SceneController() {
  {
    const std::lock_guard lock(mutex_);
    stop_.store(true);
    if (runningJob_) runningJob_->cancel->store(true);
    pendingJob_.reset();
  }
  builderWake_.notify_all();
  simulationWake_.notify_all();
  if (builder_.joinable()) builder_.join();
  if (simulation_.joinable()) simulation_.join();
}

// ---------------------------------------------------------------------------------------------
// Commands from the caller

void SceneController::load(const SceneSource& source, const SceneSettings& settings) {
  if (const std::string problem = sceneSettingsProblem(settings); !problem.empty())
    throw std::invalid_argument(problem);
  {
    const std::lock_guard lock(mutex_);
    if (runningJob_) runningJob_->cancel->store(true);
    Job job;
    job.id = ++latestJob_;
    job.source = source;
    job.settings = settings;
    job.cancel = std::make_shared<std::atomic<bool>>(false);
    pendingJob_ = std::move(job);
    status_.running = true;
    status_.fraction = 0.0;
    status_.stage = "queued";
    status_.error.clear();
    live_ = settings;
    ++liveVersion_;
  }
  builderWake_.notify_one();
  simulationWake_.notify_one();
}

BuildStatus SceneController::buildStatus() const {
  const std::lock_guard lock(mutex_);
  return status_;
}

void SceneController::cancelBuild() {
  const std::lock_guard lock(mutex_);
  if (runningJob_) runningJob_->cancel->store(true);
  pendingJob_.reset();
  ++latestJob_;  // whatever is still winding down no longer owns the status
  status_.running = false;
  status_.fraction = 0.0;
  status_.stage.clear();
  status_.error.clear();
}

void SceneController::setProgressObserver(ProgressCallback observer) {
  const std::lock_guard lock(mutex_);
  observer_ = std::move(observer);
}

std::shared_ptr<const SceneGeometry> SceneController::takeNewGeometry() {
  const std::lock_guard lock(mutex_);
  return std::exchange(newGeometry_, nullptr);
}

bool SceneController::fetchNewer(SceneFrame& frame) {
  const std::lock_guard lock(mutex_);
  if (published_.version <= frame.version) return false;
  frame = published_;
  return true;
}

void SceneController::setPlaying(bool playing) {
  {
    const std::lock_guard lock(mutex_);
    playing_ = playing;
  }
  simulationWake_.notify_one();
}

bool SceneController::playing() const {
  const std::lock_guard lock(mutex_);
  return playing_;
}

void SceneController::stepOnce() {
  {
    const std::lock_guard lock(mutex_);
    ++stepRequests_;
  }
  simulationWake_.notify_one();
}

void SceneController::grab(const Eigen::Vector3d& rest, const Eigen::Vector3d& target) {
  {
    const std::lock_guard lock(mutex_);
    grabCommands_.push_back({GrabCommand::Grab, rest, target, false});
  }
  simulationWake_.notify_one();
}

void SceneController::moveGrab(const Eigen::Vector3d& target) {
  {
    const std::lock_guard lock(mutex_);
    // Only the newest target of a drag matters.
    if (!grabCommands_.empty() && grabCommands_.back().kind == GrabCommand::Move)
      grabCommands_.back().target = target;
    else
      grabCommands_.push_back({GrabCommand::Move, Eigen::Vector3d::Zero(), target, false});
  }
  simulationWake_.notify_one();
}

void SceneController::releaseGrab(bool keep) {
  {
    const std::lock_guard lock(mutex_);
    grabCommands_.push_back({GrabCommand::Release, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), keep});
  }
  simulationWake_.notify_one();
}

void SceneController::playScript(SessionScript script) {
  {
    const std::lock_guard lock(mutex_);
    pendingScript_ = std::move(script);
  }
  simulationWake_.notify_one();
}

void SceneController::reset() {
  {
    const std::lock_guard lock(mutex_);
    resetRequested_ = true;
  }
  simulationWake_.notify_one();
}

const SceneController::Job* SceneController::jobInFlightLocked() const {
  if (pendingJob_) return &*pendingJob_;
  if (runningJob_ && !runningJob_->cancel->load()) return &*runningJob_;
  return nullptr;
}

SceneSettings SceneController::settings() const {
  const std::lock_guard lock(mutex_);
  SceneSettings settings = live_;
  const SceneSettings& built = jobInFlightLocked() ? jobInFlightLocked()->settings
                               : currentScene_     ? currentSettings_
                                                   : live_;
  settings.level = built.level;
  settings.cageCellsAcross = built.cageCellsAcross;
  settings.renderLevel = built.renderLevel;
  return settings;
}

SceneSource SceneController::source() const {
  const std::lock_guard lock(mutex_);
  if (const Job* job = jobInFlightLocked()) return job->source;
  return currentSource_;
}

void SceneController::applySettings(const SceneSettings& settings) {
  if (const std::string problem = sceneSettingsProblem(settings); !problem.empty())
    throw std::invalid_argument(problem);
  if (settings.needsRebuild(this->settings())) {
    load(source(), settings);
    return;
  }
  {
    const std::lock_guard lock(mutex_);
    live_ = settings;
    ++liveVersion_;
  }
  simulationWake_.notify_one();
}

void SceneController::advance(bool displayFirst) {
  if (threaded_) return;
  // A phase 2 left for this call (displayFirst): run it, unless it was cancelled meanwhile.
  if (std::optional<Phase2> work = std::exchange(deferred_, std::nullopt)) {
    runPhase2(*work);
    const std::lock_guard lock(mutex_);
    runningJob_.reset();
  }
  for (;;) {
    Job job;
    {
      const std::lock_guard lock(mutex_);
      if (!pendingJob_) break;
      job = std::move(*pendingJob_);
      pendingJob_.reset();
      runningJob_ = job;
    }
    std::optional<Phase2> work = runPhase1(job);
    if (work && displayFirst && work->early) {
      deferred_ = std::move(work);  // still in flight (runningJob_): load() and cancel see it
      return;
    }
    if (work) runPhase2(*work);
    const std::lock_guard lock(mutex_);
    runningJob_.reset();
  }
  simulationIteration();
}

// ---------------------------------------------------------------------------------------------
// Builds

void SceneController::publishLocked(SceneFrame& frame) {
  frame.version = ++version_;
  std::swap(published_, frame);
  if (notifier_) notifier_();
}

void SceneController::setChangeNotifier(std::function<void()> notifier) {
  const std::lock_guard lock(mutex_);
  notifier_ = std::move(notifier);
}

void SceneController::finishJob(const Job& job, const std::string& error, const StageTimes* times) {
  // mutex_ held by the caller
  if (job.id != latestJob_) return;  // a newer load or a cancel owns the status
  status_.running = false;
  status_.fraction = error.empty() ? 1.0 : 0.0;
  status_.stage = error.empty() ? "ready" : "failed";
  status_.error = error;
  if (times) status_.stageMs = *times;
  if (notifier_) notifier_();
}

ProgressReporter SceneController::progressFor(const Job& job) {
  ProgressCallback observer;
  {
    const std::lock_guard lock(mutex_);
    observer = observer_;
  }
  return ProgressReporter([this, &job, observer](double fraction, std::string_view stage) {
    if (job.cancel->load() || stop_.load()) return false;
    {
      const std::lock_guard lock(mutex_);
      if (job.id == latestJob_) {
        status_.fraction = fraction;
        status_.stage = stage;
      }
    }
    if (observer && !observer(fraction, stage)) job.cancel->store(true);
    return !job.cancel->load() && !stop_.load();
  });
}

bool SceneController::cancelled(const Job& job) const {
  return job.cancel->load() || stop_.load();
}

void SceneController::abandon(const Job& job) {
  // A cancelled build (cancelBuild, a newer load, the observer, destruction) ends quietly.
  const std::lock_guard lock(mutex_);
  if (job.id != latestJob_) return;
  status_.running = false;
  status_.fraction = 0.0;
  status_.stage.clear();
  status_.error.clear();
}

std::optional<SceneController::Phase2> SceneController::runPhase1(const Job& job) {
  try {
    ProgressReporter progress = progressFor(job);
    std::optional<SceneBuildPhase1> phase1 =
        buildSceneGeometry(job.source, job.settings, job.id, &progress);
    if (!phase1 || cancelled(job)) {
      abandon(job);
      return std::nullopt;
    }
    std::unique_lock lock(mutex_);
    if (cancelled(job)) {
      lock.unlock();
      abandon(job);
      return std::nullopt;
    }
    Phase2 next{job, std::move(*phase1), !simulationExists_};
    if (next.early) {  // nothing runs: show the rest shape now
      newGeometry_ = next.phase1.geometry;
      currentScene_ = job.id;
      currentSource_ = job.source;
      currentSettings_ = job.settings;
      SceneFrame rest = restFrame(*next.phase1.geometry, job.settings.material);
      publishLocked(rest);
    }
    return next;
  } catch (const std::exception& e) {
    const std::lock_guard lock(mutex_);
    finishJob(job, e.what(), nullptr);
    return std::nullopt;
  }
}

void SceneController::runPhase2(const Phase2& work) {
  const Job& job = work.job;
  if (cancelled(job)) return abandon(job);
  try {
    ProgressReporter progress = progressFor(job);
    StageTimes times = work.phase1.geometry->stageMs;
    std::unique_ptr<ScenePhysics> physics = ScenePhysics::build(
        work.phase1.geometry, work.phase1.solid, job.settings, &progress, &times);
    if (!physics || cancelled(job)) return abandon(job);
    SceneFrame frame;
    physics->fillFrame(frame);
    std::unique_ptr<ScenePhysics> replaced;  // freed after the lock
    {
      std::unique_lock lock(mutex_);
      if (cancelled(job)) {
        lock.unlock();
        return abandon(job);
      }
      if (!work.early) newGeometry_ = work.phase1.geometry;
      currentScene_ = job.id;
      currentSource_ = job.source;
      currentSettings_ = job.settings;
      publishLocked(frame);
      replaced = std::exchange(readyPhysics_, std::move(physics));
      simulationExists_ = true;
      finishJob(job, {}, &times);
    }
    simulationWake_.notify_one();
  } catch (const std::exception& e) {
    const std::lock_guard lock(mutex_);
    finishJob(job, e.what(), nullptr);
  }
}

void SceneController::builderLoop() {
  for (;;) {
    Job job;
    {
      std::unique_lock lock(mutex_);
      builderWake_.wait(lock, [this] { return stop_.load() || pendingJob_.has_value(); });
      if (stop_.load()) return;
      job = std::move(*pendingJob_);
      pendingJob_.reset();
      runningJob_ = job;
    }
    if (std::optional<Phase2> work = runPhase1(job)) runPhase2(*work);
    const std::lock_guard lock(mutex_);
    runningJob_.reset();
  }
}

// ---------------------------------------------------------------------------------------------
// Simulation

void SceneController::paint(const Eigen::Vector3d& centre, const MaterialBrushSettings& brush) {
  queuePhysicsCommand([centre, brush](ScenePhysics& physics) {
    try {
      physics.paint(centre, brush);
    } catch (const std::invalid_argument& e) {
      return std::string("cannot paint: ") + e.what();
    }
    return std::string();
  });
}

void SceneController::pin(const Eigen::Vector3d& centre, double radius, bool pin) {
  queuePhysicsCommand([centre, radius, pin](ScenePhysics& physics) {
    physics.pin(centre, radius, pin);
    return std::string();
  });
}

void SceneController::pressInflate(const Eigen::Vector3d& centre, double radius, double pressure) {
  queuePhysicsCommand([centre, radius, pressure](ScenePhysics& physics) {
    try {
      physics.pressInflate(centre, radius, pressure);
    } catch (const std::invalid_argument& e) {
      return std::string("cannot inflate: ") + e.what();
    }
    return std::string();
  });
}

void SceneController::releaseInflate() {
  queuePhysicsCommand([](ScenePhysics& physics) {
    physics.releaseInflate();
    return std::string();
  });
}

void SceneController::grabCurve(std::vector<Eigen::Vector3d> polyline, bool smooth) {
  queuePhysicsCommand([polyline = std::move(polyline), smooth](ScenePhysics& physics) {
    try {
      physics.grabCurve(polyline, smooth);
    } catch (const std::invalid_argument& e) {
      return std::string("cannot grab the curve: ") + e.what();
    }
    return std::string();
  });
}

void SceneController::dragCurve(const Eigen::Vector3d& offset) {
  queuePhysicsCommand([offset](ScenePhysics& physics) {
    physics.dragCurve(offset);
    return std::string();
  });
}

void SceneController::releaseCurve() {
  queuePhysicsCommand([](ScenePhysics& physics) {
    physics.releaseCurve();
    return std::string();
  });
}

void SceneController::restoreEdits(MaterialSamples samples, std::vector<uint32_t> pins) {
  queuePhysicsCommand([this, samples = std::move(samples), pins = std::move(pins)](ScenePhysics& physics) {
    Material uniform;
    {
      const std::lock_guard lock(mutex_);
      uniform = live_.material;
    }
    const std::string problem = physics.restoreEdits(samples, pins, uniform);
    return problem.empty() ? problem : "cannot restore the edit: " + problem;
  });
}

void SceneController::requestEdits() {
  queuePhysicsCommand([this](ScenePhysics& physics) {
    Edits edits{physics.geometry().sceneId, physics.captureMaterialSamples(), physics.pinnedPoints()};
    const std::lock_guard lock(mutex_);
    capturedEdits_ = std::move(edits);
    return std::string();
  });
}

std::optional<SceneController::Edits> SceneController::takeEdits() {
  const std::lock_guard lock(mutex_);
  return std::exchange(capturedEdits_, std::nullopt);
}

void SceneController::queuePhysicsCommand(std::function<std::string(ScenePhysics&)> command) {
  {
    const std::lock_guard lock(mutex_);
    physicsCommands_.push_back(std::move(command));
  }
  simulationWake_.notify_all();
}

bool SceneController::simulationIteration() {
  std::unique_ptr<ScenePhysics> retired;
  bool doReset = false, doStep = false, liveChanged = false;
  std::optional<SessionScript> script;
  std::vector<GrabCommand> grabs;
  std::vector<std::function<std::string(ScenePhysics&)>> commands;
  SceneSettings live;
  {
    const std::lock_guard lock(mutex_);
    if (readyPhysics_) {
      retired = std::exchange(physics_, std::move(readyPhysics_));
      appliedLiveVersion_ = 0;  // settings changed during the build apply to it too
    }
    if (!physics_) return false;
    doReset = std::exchange(resetRequested_, false);
    script = std::exchange(pendingScript_, std::nullopt);
    grabs = std::exchange(grabCommands_, {});
    commands = std::exchange(physicsCommands_, {});
    if (liveVersion_ != appliedLiveVersion_) {
      live = live_;
      appliedLiveVersion_ = liveVersion_;
      liveChanged = true;
    }
    doStep = playing_ || stepRequests_ > 0;
    if (stepRequests_ > 0) --stepRequests_;
  }
  retired.reset();  // a replaced scene is freed outside the lock
  std::string problem;
  try {
    if (liveChanged) problem = physics_->applyLive(live);
    if (doReset) physics_->reset();
    if (script) {
      try {
        physics_->playScript(*script);
      } catch (const std::invalid_argument& e) {  // the scene goes on without the script
        problem = std::string("the session script cannot be played: ") + e.what();
      }
    }
    for (const GrabCommand& command : grabs) {
      if (command.kind == GrabCommand::Grab) {
        if (!physics_->grab(command.rest, command.target)) problem = "nothing to grab there";
      } else if (command.kind == GrabCommand::Move) {
        physics_->moveGrab(command.target);
      } else {
        physics_->releaseGrab(command.keep);
      }
    }
    for (const auto& command : commands)
      if (std::string message = command(*physics_); !message.empty()) problem = std::move(message);
    if (doStep) physics_->step();
  } catch (const std::exception& e) {  // nothing the simulator is known to throw; stop calmly
    const std::lock_guard lock(mutex_);
    status_.error = std::string("the simulation stopped: ") + e.what();
    playing_ = false;
    stepRequests_ = 0;
    return false;
  }
  if (!doStep && !doReset && !liveChanged && !script && grabs.empty() && commands.empty())
    return false;
  physics_->fillFrame(back_);
  const std::lock_guard lock(mutex_);
  if (!problem.empty()) status_.error = problem;
  if (physics_->geometry().sceneId != currentScene_) return false;  // being replaced
  publishLocked(back_);
  return true;
}

void SceneController::simulationLoop() {
  using Clock = std::chrono::steady_clock;
  constexpr auto kStep = std::chrono::microseconds(16667);  // real time at 60 steps per second
  auto next = Clock::now();
  for (;;) {
    {
      // Sleep until there is something to do.
      std::unique_lock lock(mutex_);
      simulationWake_.wait(lock, [this] {
        return stop_.load() || readyPhysics_ ||
               (physics_ && (playing_ || stepRequests_ > 0 || resetRequested_ ||
                             pendingScript_ || !grabCommands_.empty() ||
                             !physicsCommands_.empty() || liveVersion_ != appliedLiveVersion_));
      });
      if (stop_.load()) return;
    }
    const bool wasPlaying = playing();
    simulationIteration();
    if (!wasPlaying) {
      next = Clock::now();
      continue;
    }
    // Pace at 60 steps per second; slower than real time runs as fast as it can.
    next += kStep;
    const auto now = Clock::now();
    if (next <= now) {
      next = now;
      continue;
    }
    std::unique_lock lock(mutex_);
    simulationWake_.wait_until(lock, next, [this] {
      return stop_.load() || readyPhysics_ || stepRequests_ > 0 || resetRequested_ ||
             (physics_ && (pendingScript_ || !grabCommands_.empty() ||
                           !physicsCommands_.empty())) ||
             liveVersion_ != appliedLiveVersion_;
    });
  }
}

}  // namespace sculpt::app
