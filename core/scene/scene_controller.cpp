#include "scene/scene_controller.h"

#include <chrono>
#include <stdexcept>
#include <utility>

#include "util/parallel_for.h"

namespace sculpt {

SceneController::SceneController(bool threaded) : threaded_(threaded), loop_(threaded) {
  loop_.setProblemHandler([this](const std::string& problem) {
    const std::lock_guard lock(mutex_);
    status_.error = problem;
  });
  if (threaded_) builder_ = std::thread([this] { builderLoop(); });
}

SceneController::~SceneController() {
  {
    const std::lock_guard lock(mutex_);
    stop_.store(true);
    if (runningJob_) runningJob_->cancel->store(true);
    pendingJob_.reset();
  }
  builderWake_.notify_all();
  if (builder_.joinable()) builder_.join();
  deferred_.reset();  // a phase 2 still building sees the cancel and stops
  loop_.setProblemHandler(nullptr);
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
  }
  loop_.applyLive(settings);
  builderWake_.notify_one();
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

bool SceneController::fetchNewer(SceneFrame& frame) { return loop_.fetchNewer(frame); }

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
  }
  loop_.applyLive(settings);
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
  loop_.iterate();
}

// ---------------------------------------------------------------------------------------------
// Builds

void SceneController::setChangeNotifier(std::function<void()> notifier) {
  loop_.setChangeNotifier(notifier);
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

std::future<SceneController::PhysicsBuild> SceneController::startPhysics(
    const Job& job, const SceneSolidPart& part, std::shared_future<void> stencilsReady) {
  // The job is copied: its progress reporter refers to it for as long as the build runs.
  return std::async(std::launch::async, [this, job, geometry = part.geometry, solid = part.solid,
                                         stencilsReady = std::move(stencilsReady)] {
    ProgressReporter progress = progressFor(job);
    PhysicsBuild build;
    build.physics = ScenePhysics::build(geometry, solid, job.settings, &progress, &build.stageMs,
                                        stencilsReady);
    if (build.physics && threaded_) {
      // The window's steps never wait for a factor made on a worker (simulator.h).
      SimulationSettings simulation = build.physics->simulator().settings();
      simulation.reproducible = false;
      build.physics->simulator().setSettings(simulation);
    }
    return build;
  });
}

std::optional<SceneController::Phase2> SceneController::runPhase1(const Job& job) {
  std::future<PhysicsBuild> physics;
  try {
    ProgressReporter progress = progressFor(job);
    std::optional<SceneSolidPart> part =
        buildSceneSolid(job.source, job.settings, job.id, &progress);
    if (!part || cancelled(job)) {
      abandon(job);
      return std::nullopt;
    }
    // Phase 2 waits for the stencils only at the end of its first step. A promise left unkept
    // (cancelled, failed) releases it with an exception that nobody reads.
    std::promise<void> stencils;
    physics = startPhysics(job, *part, stencils.get_future().share());
    // The stencils' and the surface's stages only check for cancelling: the build's progress
    // is phase 2's. Their loops run on this thread alone, so that phase 2's never wait for the
    // shared workers.
    ProgressReporter surfaceProgress(
        [this, &job](double, std::string_view) { return !cancelled(job); });
    bool surfaceBuilt = false;
    {
      const InlineLoopsOnThisThread inlineLoops;
      if (buildSceneStencils(job.source, *part, &surfaceProgress)) {
        stencils.set_value();
        surfaceBuilt = buildSceneSurface(job.source, *part, &surfaceProgress);
      }
    }
    if (!surfaceBuilt || cancelled(job)) {
      abandon(job);
      return std::nullopt;  // phase 2 sees the cancel and stops; its future waits for it
    }
    std::unique_lock lock(mutex_);
    if (cancelled(job)) {
      lock.unlock();
      abandon(job);
      return std::nullopt;
    }
    Phase2 next{job, SceneBuildPhase1{part->geometry, part->solid}, !loop_.hasSimulation(),
                std::move(physics)};
    if (next.early) {  // nothing runs: show the rest shape now
      newGeometry_ = next.phase1.geometry;
      currentScene_ = job.id;
      currentSource_ = job.source;
      currentSettings_ = job.settings;
      loop_.showFrame(restFrame(*next.phase1.geometry, job.settings.material));
    }
    return next;
  } catch (const std::exception& e) {
    job.cancel->store(true);  // a phase 2 under way stops
    const std::lock_guard lock(mutex_);
    finishJob(job, e.what(), nullptr);
    return std::nullopt;
  }
}

void SceneController::runPhase2(Phase2& work) {
  const Job& job = work.job;
  try {
    PhysicsBuild built = work.physics.get();
    if (!built.physics || cancelled(job)) return abandon(job);
    StageTimes times = work.phase1.geometry->stageMs;
    times.insert(times.end(), built.stageMs.begin(), built.stageMs.end());
    std::unique_ptr<ScenePhysics> physics = std::move(built.physics);
    SceneFrame frame;
    physics->fillFrame(frame);
    {
      std::unique_lock lock(mutex_);
      if (cancelled(job)) {
        lock.unlock();
        return abandon(job);
      }
      // The geometry and the first frame go out under the lock, so that no caller takes the
      // frame without the geometry it belongs to.
      if (!work.early) newGeometry_ = work.phase1.geometry;
      currentScene_ = job.id;
      currentSource_ = job.source;
      currentSettings_ = job.settings;
      loop_.install(std::move(physics), std::move(frame));
      finishJob(job, {}, &times);
    }
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

}  // namespace sculpt
