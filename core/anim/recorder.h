#pragma once
// Records a running scene: a step observer of the simulation loop (scene/simulation_loop.h)
// that keeps the control points of one frame per 1/fps of simulated time (take.h).
//
// Sampling: the take's clock starts at the first step observed after start() (frame 0) and
// advances by each step's simulated time (after a reset, by the time since the reset). Frame k
// is the state after the first step whose take time t satisfies t >= k/fps - h/2 (h that step's
// length): the nearest step to the frame's time. When the step divides 1/fps (1/60 s steps at
// 30 fps) the frames are exact steps; when steps are longer than 1/fps a state is repeated.
//
// Threads: observe() runs on the simulation thread; everything else may be called from any
// thread and waits only for a short copy under one mutex.

#include <cstdint>
#include <memory>
#include <mutex>
#include <string>

#include "anim/take.h"
#include "scene/simulation_loop.h"

namespace sculpt {

/// Empty when `fps` is usable (0 < fps <= 1000); otherwise the sentence refusing it.
std::string frameRateProblem(double fps);

class Recorder {
 public:
  /// Throws std::invalid_argument with frameRateProblem's sentence.
  explicit Recorder(double fps = 30.0);
  ~Recorder();
  Recorder(const Recorder&) = delete;
  Recorder& operator=(const Recorder&) = delete;

  /// Observes `loop` from now on (until detach() or destruction; the loop must outlive it).
  void attach(SimulationLoop& loop);
  void detach();

  /// Starts a new take (the old one is dropped); frames come with the next steps.
  void start();
  /// Stops recording; the take stays.
  void stop();
  bool recording() const;
  /// True when the take stopped because it reached kMaxTakeFrames.
  bool full() const;

  double fps() const { return fps_; }
  uint32_t frameCount() const;
  double duration() const;
  /// The take time of the last step observed (s; 0 before the first): where a stroke made now
  /// lands, to the step rather than to the frame.
  double time() const;
  size_t memoryBytes() const;
  /// A copy of the take so far (cheap next to an export: O(frames x control points)).
  std::shared_ptr<const Take> take() const;
  /// Frame `frame`'s control points and its scene; false when there is no such frame.
  bool frame(uint32_t frame, Points& control,
             std::shared_ptr<const SceneSurfaceMap>& surface) const;

  /// The step observer (public for callers that step a scene themselves).
  void observe(const StepState& state);

 private:
  const double fps_;
  mutable std::mutex mutex_;
  Take take_;
  bool recording_ = false, full_ = false, started_ = false;
  double takeTime_ = 0.0, lastSimulatedTime_ = 0.0;
  uint64_t fieldsVersion_ = 0;
  const SceneSurfaceMap* fieldsScene_ = nullptr;  // the scene whose fields were recorded last
  SimulationLoop* loop_ = nullptr;
  uint64_t observerId_ = 0;
};

}  // namespace sculpt
