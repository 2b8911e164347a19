#include "anim/recorder.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "scene/scene_physics.h"

namespace sculpt {

std::string frameRateProblem(double fps) {
  if (std::isfinite(fps) && fps > 0.0 && fps <= 1000.0) return {};
  std::ostringstream out;
  out << "the frame rate must be more than 0 and at most 1000 frames per second (got " << fps
      << ")";
  return out.str();
}

Recorder::Recorder(double fps) : fps_(fps), take_(fps) {
  if (const std::string problem = frameRateProblem(fps); !problem.empty())
    throw std::invalid_argument(problem);
}

Recorder::~Recorder() { detach(); }

void Recorder::attach(SimulationLoop& loop) {
  detach();
  loop_ = &loop;
  observerId_ = loop.addStepObserver([this](const StepState& state) { observe(state); });
}

void Recorder::detach() {
  if (loop_) loop_->removeStepObserver(observerId_);
  loop_ = nullptr;
}

void Recorder::start() {
  const std::lock_guard lock(mutex_);
  take_ = Take(fps_);
  recording_ = true;
  full_ = started_ = false;
  takeTime_ = 0.0;
  fieldsScene_ = nullptr;
}

void Recorder::stop() {
  const std::lock_guard lock(mutex_);
  recording_ = false;
}

bool Recorder::recording() const {
  const std::lock_guard lock(mutex_);
  return recording_;
}

bool Recorder::full() const {
  const std::lock_guard lock(mutex_);
  return full_;
}

uint32_t Recorder::frameCount() const {
  const std::lock_guard lock(mutex_);
  return take_.frameCount();
}

double Recorder::duration() const {
  const std::lock_guard lock(mutex_);
  return take_.duration();
}

double Recorder::time() const {
  const std::lock_guard lock(mutex_);
  return takeTime_;
}

size_t Recorder::memoryBytes() const {
  const std::lock_guard lock(mutex_);
  return take_.memoryBytes();
}

std::shared_ptr<const Take> Recorder::take() const {
  const std::lock_guard lock(mutex_);
  return std::make_shared<const Take>(take_);
}

bool Recorder::frame(uint32_t frame, Points& control,
                     std::shared_ptr<const SceneSurfaceMap>& surface) const {
  const std::lock_guard lock(mutex_);
  if (frame >= take_.frameCount()) return false;
  take_.controlPoints(frame, control);
  surface = take_.segments()[take_.segmentOf(frame)].surface;
  return true;
}

void Recorder::observe(const StepState& state) {
  if (!state.physics || !state.control) return;
  const ScenePhysics& physics = *state.physics;
  const std::lock_guard lock(mutex_);
  if (!recording_) return;
  // The step's length: the simulated time it advanced (since the reset, after one).
  const double h = state.simulatedTime >= lastSimulatedTime_
                       ? state.simulatedTime - lastSimulatedTime_
                       : state.simulatedTime;
  lastSimulatedTime_ = state.simulatedTime;
  if (!started_) {
    started_ = true;
    takeTime_ = 0.0;
  } else {
    takeTime_ += h;
  }
  // Relative slack so that t = k/fps computed as a sum of steps still counts as due.
  const double slack = 1e-9 * std::max(1.0, takeTime_);
  while (take_.frameCount() * (1.0 / fps_) <= takeTime_ + 0.5 * h + slack) {
    if (take_.frameCount() >= kMaxTakeFrames) {
      recording_ = false;
      full_ = true;
      return;
    }
    if (fieldsScene_ != physics.surfaceMap().get() || fieldsVersion_ != physics.materialVersion()) {
      auto fields = std::make_shared<CellFields>();
      physics.cellMaterialFields(fields->youngs, fields->density, fields->damping);
      take_.setFields(std::move(fields));
      fieldsScene_ = physics.surfaceMap().get();
      fieldsVersion_ = physics.materialVersion();
    }
    take_.append(physics.surfaceMap(), *state.control);
  }
}

}  // namespace sculpt
