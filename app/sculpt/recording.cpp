#include "sculpt/recording.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace sculpt::app {

Recording::~Recording() = default;

void Recording::setFps(double fps) {
  if (const std::string problem = frameRateProblem(fps); !problem.empty())
    throw std::invalid_argument(problem);
  fps_ = fps;
}

void Recording::start(SimulationLoop& loop) {
  goLive();
  recorder_ = std::make_unique<Recorder>(fps_);
  strokes_.clear();
  recorder_->attach(loop);
  recorder_->start();
}

void Recording::stop() {
  if (!recorder_) return;
  strokes_.end(recorder_->time());  // a stroke still held ends with the take
  recorder_->stop();
  recorder_->detach();
  std::shared_ptr<const Take> take = recorder_->take();
  recorder_.reset();
  if (take->frameCount() > 0) take_ = std::move(take);
}

uint32_t Recording::frameCount() const {
  if (recorder_) return recorder_->frameCount();
  return take_ ? take_->frameCount() : 0;
}

double Recording::seconds() const {
  if (recorder_) return recorder_->duration();
  return take_ ? take_->duration() : 0.0;
}

double Recording::takeTime() const { return recorder_ ? recorder_->time() : seconds(); }

size_t Recording::memoryBytes() const {
  if (recorder_) return recorder_->memoryBytes();
  return take_ ? take_->memoryBytes() : 0;
}

void Recording::setPlayhead(uint32_t frame) {
  if (!take_ || recording()) return;
  playhead_ = std::min(frame, take_->frameCount() - 1);
  playbackStart_.reset();
}

void Recording::goLive() {
  playhead_.reset();
  playbackStart_.reset();
}

void Recording::play(Clock::time_point now) {
  if (!take_ || recording()) return;
  uint32_t from = playhead();
  if (isLive() || from + 1 >= take_->frameCount()) from = 0;
  playhead_ = from;
  playbackFirst_ = from;
  playbackStart_ = now;
}

bool Recording::advance(Clock::time_point now) {
  if (!playbackStart_ || !take_) return false;
  const double elapsed = std::chrono::duration<double>(now - *playbackStart_).count();
  const uint32_t last = take_->frameCount() - 1;
  const double frame = playbackFirst_ + std::floor(elapsed * take_->fps());
  const uint32_t next = frame >= last ? last : static_cast<uint32_t>(frame);
  if (next == last) playbackStart_.reset();  // played to the end: stay on the last frame
  const bool changed = next != playhead_;
  playhead_ = next;
  return changed;
}

}  // namespace sculpt::app
