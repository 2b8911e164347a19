#include "scene/simulation_loop.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace sculpt {

SimulationLoop::SimulationLoop(bool threaded) : threaded_(threaded) {
  if (threaded_) thread_ = std::thread([this] { run(); });
}

SimulationLoop::~SimulationLoop() {
  {
    const std::lock_guard lock(mutex_);
    stop_.store(true);
  }
  wake_.notify_all();
  if (thread_.joinable()) thread_.join();
}

// ---------------------------------------------------------------------------------------------
// Scenes and frames

void SimulationLoop::publishLocked(SceneFrame& frame) {
  frame.version = ++version_;
  std::swap(published_, frame);
  if (notifier_) notifier_();
}

void SimulationLoop::showFrame(SceneFrame frame) {
  const std::lock_guard lock(mutex_);
  currentScene_ = frame.sceneId;
  publishLocked(frame);
}

void SimulationLoop::install(std::unique_ptr<ScenePhysics> physics, SceneFrame first) {
  std::unique_ptr<ScenePhysics> replaced;  // a scene never run is freed after the lock
  {
    const std::lock_guard lock(mutex_);
    currentScene_ = physics->geometry().sceneId;
    publishLocked(first);
    replaced = std::exchange(ready_, std::move(physics));
    simulationExists_ = true;
  }
  wake_.notify_all();
}

bool SimulationLoop::hasSimulation() const {
  const std::lock_guard lock(mutex_);
  return simulationExists_;
}

bool SimulationLoop::fetchNewer(SceneFrame& frame) {
  const std::lock_guard lock(mutex_);
  if (published_.version <= frame.version) return false;
  frame = published_;
  return true;
}

void SimulationLoop::setChangeNotifier(std::function<void()> notifier) {
  const std::lock_guard lock(mutex_);
  notifier_ = std::move(notifier);
}

void SimulationLoop::setProblemHandler(std::function<void(const std::string&)> handler) {
  const std::lock_guard lock(mutex_);
  problemHandler_ = std::move(handler);
}

void SimulationLoop::report(const std::string& problem) {
  std::function<void(const std::string&)> handler;
  {
    const std::lock_guard lock(mutex_);
    handler = problemHandler_;
  }
  if (handler) handler(problem);
}

// ---------------------------------------------------------------------------------------------
// Commands

void SimulationLoop::setPlaying(bool playing) {
  {
    const std::lock_guard lock(mutex_);
    playing_ = playing;
  }
  wake_.notify_all();
}

bool SimulationLoop::playing() const {
  const std::lock_guard lock(mutex_);
  return playing_;
}

void SimulationLoop::stepOnce() {
  {
    const std::lock_guard lock(mutex_);
    ++stepRequests_;
  }
  wake_.notify_all();
}

void SimulationLoop::reset() {
  {
    const std::lock_guard lock(mutex_);
    resetRequested_ = true;
  }
  wake_.notify_all();
}

void SimulationLoop::setRealTimeRate(double rate) {
  if (!(rate > 0.0) || !std::isfinite(rate))
    throw std::invalid_argument("the real-time rate must be a finite number > 0");
  {
    const std::lock_guard lock(mutex_);
    rate_ = rate;
    rateChanged_ = true;
  }
  wake_.notify_all();
}

void SimulationLoop::applyLive(const SceneSettings& settings) {
  {
    const std::lock_guard lock(mutex_);
    live_ = settings;
    ++liveVersion_;
  }
  wake_.notify_all();
}

SceneSettings SimulationLoop::liveSettings() const {
  const std::lock_guard lock(mutex_);
  return live_;
}

void SimulationLoop::queue(Command command) {
  {
    const std::lock_guard lock(mutex_);
    // Only the newest input of a moving stroke matters.
    if (command.kind == Command::Update && !commands_.empty() &&
        commands_.back().kind == Command::Update && commands_.back().stroke == command.stroke)
      commands_.back().input = command.input;
    else
      commands_.push_back(std::move(command));
  }
  wake_.notify_all();  // while playing, the loop does not act on it before the next step
}

void SimulationLoop::queueStroke(int kind, uint64_t stroke, std::unique_ptr<Tool> tool,
                                 const ToolInput& input) {
  Command command;
  command.kind = static_cast<Command::Kind>(kind);
  command.stroke = stroke;
  command.tool = std::move(tool);
  command.input = input;
  queue(std::move(command));
}

uint64_t SimulationLoop::beginStroke(std::unique_ptr<Tool> tool, const ToolInput& input) {
  uint64_t id = 0;
  {
    const std::lock_guard lock(mutex_);
    id = ++nextStroke_;
  }
  queueStroke(Command::Begin, id, std::move(tool), input);
  return id;
}

void SimulationLoop::updateStroke(uint64_t stroke, const ToolInput& input) {
  queueStroke(Command::Update, stroke, nullptr, input);
}

void SimulationLoop::endStroke(uint64_t stroke, const ToolInput& input) {
  queueStroke(Command::End, stroke, nullptr, input);
}

void SimulationLoop::playScript(SessionScript script) {
  {
    const std::lock_guard lock(mutex_);
    pendingScript_ = std::move(script);
  }
  wake_.notify_all();
}

void SimulationLoop::setStrainEnergyShown(bool shown) {
  if (strainEnergyShown_.exchange(shown) == shown) return;
  // runIteration passes the flag on; an empty command wakes a paused loop to publish a frame
  // with (or without) the field.
  Command command;
  command.other = [](ScenePhysics&) { return std::string(); };
  queue(std::move(command));
}

void SimulationLoop::restoreEdits(MaterialSamples samples, std::vector<uint32_t> pins) {
  Command command;
  command.other = [this, samples = std::move(samples),
                   pins = std::move(pins)](ScenePhysics& physics) {
    Material uniform;
    {
      const std::lock_guard lock(mutex_);
      uniform = live_.material;
    }
    const std::string problem = physics.restoreEdits(samples, pins, uniform);
    return problem.empty() ? problem : "cannot restore the edit: " + problem;
  };
  queue(std::move(command));
}

void SimulationLoop::requestEdits() {
  Command command;
  command.other = [this](ScenePhysics& physics) {
    SceneEdits edits{physics.geometry().sceneId, physics.captureMaterialSamples(),
                     physics.pinnedPoints()};
    const std::lock_guard lock(mutex_);
    capturedEdits_ = std::move(edits);
    return std::string();
  };
  queue(std::move(command));
}

std::optional<SceneEdits> SimulationLoop::takeEdits() {
  const std::lock_guard lock(mutex_);
  return std::exchange(capturedEdits_, std::nullopt);
}

// ---------------------------------------------------------------------------------------------
// Observers and probes

uint64_t SimulationLoop::addStepObserver(StepObserver observer) {
  const std::lock_guard lock(mutex_);
  observers_.emplace_back(++nextObserver_,
                          std::make_shared<const StepObserver>(std::move(observer)));
  return nextObserver_;
}

void SimulationLoop::removeStepObserver(uint64_t id) {
  const std::lock_guard lock(mutex_);
  std::erase_if(observers_, [id](const auto& entry) { return entry.first == id; });
}

std::shared_ptr<ProbeChannel> SimulationLoop::openProbe() {
  auto channel = std::make_shared<ProbeChannel>();
  const std::lock_guard lock(mutex_);
  probes_.push_back(channel);
  return channel;
}

void SimulationLoop::publishProbe(ScenePhysics& physics) {
  std::vector<std::shared_ptr<ProbeChannel>> channels;
  {
    const std::lock_guard lock(mutex_);
    std::erase_if(probes_, [](const auto& channel) { return channel.use_count() == 1; });
    channels = probes_;
  }
  if (channels.empty()) return;
  std::vector<std::pair<uint64_t, ToolSpring>> springs;
  physics.strokeSprings(springs);
  SceneProbe probe;
  probe.generation = ++probeGeneration_;
  probe.sceneId = physics.geometry().sceneId;
  probe.steps = steps_;
  probe.simulatedTime = physics.simulatedTime();
  probe.publishedNs = std::chrono::duration_cast<std::chrono::nanoseconds>(
                          std::chrono::steady_clock::now().time_since_epoch())
                          .count();
  probe.strokeCount = static_cast<int>(springs.size());
  for (size_t i = 0; i < springs.size() && i < probe.strokes.size(); ++i) {
    const ToolSpring& spring = springs[i].second;
    ProbeStroke& out = probe.strokes[i];
    out.strokeId = springs[i].first;
    out.point = spring.point;
    out.velocity = spring.velocity;
    out.target = spring.target;
    out.stiffness = spring.stiffness;
    out.force = spring.stiffness * (spring.point - spring.target).norm();
    out.normal = spring.normal;
  }
  for (const std::shared_ptr<ProbeChannel>& channel : channels) channel->publish(probe);
}

void SimulationLoop::notifyStep(ScenePhysics& physics, const StepReport& report) {
  std::vector<std::shared_ptr<const StepObserver>> observers;
  {
    const std::lock_guard lock(mutex_);
    for (const auto& entry : observers_) observers.push_back(entry.second);
  }
  if (observers.empty()) return;
  StepState state;
  state.sceneId = physics.geometry().sceneId;
  state.step = steps_;
  state.simulatedTime = physics.simulatedTime();
  state.control = &physics.simulator().positions();
  state.report = &report;
  state.physics = &physics;
  for (const auto& observer : observers) (*observer)(state);
}

// ---------------------------------------------------------------------------------------------
// The loop

bool SimulationLoop::workWaitingLocked(bool playingToo) const {
  if (ready_) return true;
  if (!physics_) return false;
  return (playingToo && playing_) || stepRequests_ > 0 || resetRequested_ || pendingScript_ ||
         !commands_.empty() || liveVersion_ != appliedLiveVersion_;
}

bool SimulationLoop::iterate() {
  if (threaded_) return false;
  return runIteration();
}

bool SimulationLoop::runIteration() {
  std::unique_ptr<ScenePhysics> retired;
  bool doReset = false, doStep = false, liveChanged = false;
  std::optional<SessionScript> script;
  std::vector<Command> commands;
  SceneSettings live;
  {
    const std::lock_guard lock(mutex_);
    if (ready_) {
      retired = std::exchange(physics_, std::move(ready_));
      appliedLiveVersion_ = 0;  // settings changed during the build apply to it too
      steps_ = 0;
    }
    if (!physics_) return false;
    doReset = std::exchange(resetRequested_, false);
    script = std::exchange(pendingScript_, std::nullopt);
    commands = std::exchange(commands_, {});
    if (liveVersion_ != appliedLiveVersion_) {
      live = live_;
      appliedLiveVersion_ = liveVersion_;
      liveChanged = liveVersion_ != 0;
    }
    doStep = playing_ || stepRequests_ > 0;
    if (stepRequests_ > 0) --stepRequests_;
  }
  retired.reset();  // a replaced scene is freed outside the lock
  physics_->setStrainEnergyWanted(strainEnergyShown_.load());  // a new scene's too
  std::vector<std::string> problems;
  StepReport stepReport;
  try {
    if (liveChanged)
      if (std::string problem = physics_->applyLive(live); !problem.empty())
        problems.push_back(std::move(problem));
    if (doReset) {
      physics_->reset();
      steps_ = 0;
    }
    if (script) {
      try {
        physics_->playScript(*script);
      } catch (const std::invalid_argument& e) {  // the scene goes on without the script
        problems.push_back(std::string("the session script cannot be played: ") + e.what());
      }
    }
    for (Command& command : commands) {
      try {
        switch (command.kind) {
          case Command::Begin:
            physics_->beginStroke(command.stroke, std::move(command.tool), command.input);
            break;
          case Command::Update: physics_->updateStroke(command.stroke, command.input); break;
          case Command::End: physics_->endStroke(command.stroke, command.input); break;
          case Command::Other:
            if (std::string problem = command.other(*physics_); !problem.empty())
              problems.push_back(std::move(problem));
            break;
        }
      } catch (const std::invalid_argument& e) {
        problems.push_back(e.what());
      }
    }
    if (doStep) {
      stepReport = physics_->step();
      ++steps_;
    }
  } catch (const std::exception& e) {  // nothing the simulator is known to throw; stop calmly
    {
      const std::lock_guard lock(mutex_);
      playing_ = false;
      stepRequests_ = 0;
    }
    report(std::string("the simulation stopped: ") + e.what());
    return false;
  }
  for (const std::string& problem : problems) report(problem);
  if (!doStep && !doReset && !liveChanged && !script && commands.empty()) return false;
  physics_->fillFrame(back_);
  bool published = false;
  {
    const std::lock_guard lock(mutex_);
    if (physics_->geometry().sceneId == currentScene_) {  // else it is being replaced
      publishLocked(back_);
      published = true;
    }
  }
  if (doStep) notifyStep(*physics_, stepReport);
  publishProbe(*physics_);
  return published;
}

void SimulationLoop::run() {
  using Clock = std::chrono::steady_clock;
  Clock::time_point next = Clock::now();  // when the next paced step is due
  bool wasPlaying = false;
  for (;;) {
    {
      std::unique_lock lock(mutex_);
      for (;;) {
        if (stop_.load()) return;
        if (ready_ || stepRequests_ > 0) break;
        if (physics_ && playing_) {
          if (!wasPlaying || rateChanged_) next = Clock::now();
          wasPlaying = true;
          rateChanged_ = false;
          // Only the clock, a stop, a new scene, an extra step or a pause end this wait.
          if (wake_.wait_until(lock, next, [this] {
                return stop_.load() || ready_ || stepRequests_ > 0 || !playing_ || rateChanged_;
              }))
            continue;
          break;  // the step is due
        }
        wasPlaying = false;
        if (workWaitingLocked(false)) break;
        wake_.wait(lock);
      }
    }
    const bool paced = wasPlaying && Clock::now() >= next;
    runIteration();
    if (!paced || !physics_) continue;
    double step = 0.0, rate = 1.0;
    {
      const std::lock_guard lock(mutex_);
      rate = rate_;
    }
    step = physics_->simulator().settings().timeStep;
    const auto share =
        std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(step / rate));
    next += share;
    // A late step is made up by the next ones starting at once; further behind than a few
    // shares (the simulation slower than the clock, a stall), the clock is rebased to that lag.
    if (const Clock::time_point now = Clock::now(); next < now - kCatchUpSteps * share)
      next = now - kCatchUpSteps * share;
  }
}

}  // namespace sculpt
