#pragma once
// The window's recording: a Recorder (anim/recorder.h) on the running simulation loop while
// recording, the last take once stopped, and the timeline's playhead over it. Live (no playhead)
// the view follows the simulation; otherwise it shows the take's frame at the playhead, which
// playback advances at the take's rate in wall time, without simulating.

#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>

#include "anim/recorder.h"
#include "anim/stroke_capture.h"
#include "anim/take.h"
#include "scene/simulation_loop.h"

namespace sculpt::app {

class Recording {
 public:
  using Clock = std::chrono::steady_clock;

  Recording() = default;
  ~Recording();
  Recording(const Recording&) = delete;
  Recording& operator=(const Recording&) = delete;

  /// The frame rate of the next take (frameRateProblem's range; throws std::invalid_argument).
  void setFps(double fps);
  double fps() const { return fps_; }

  /// Starts a new take on `loop` (which must outlive the recording or its stop()); goes Live.
  void start(SimulationLoop& loop);
  /// Stops recording and keeps the take (a take without frames is dropped).
  void stop();
  bool recording() const { return recorder_ && recorder_->recording(); }
  /// True when the take stopped itself at its length limit (stop() still collects it).
  bool full() const { return recorder_ && recorder_->full(); }
  /// While recording: the recorder's figures; otherwise the last take's.
  uint32_t frameCount() const;
  double seconds() const;
  size_t memoryBytes() const;
  /// The last stopped take (null before one exists).
  const std::shared_ptr<const Take>& take() const { return take_; }

  // The timeline
  bool isLive() const { return !playhead_; }
  /// The frame shown when not live (0 when live).
  uint32_t playhead() const { return playhead_.value_or(0); }
  /// Shows frame `frame` of the take (clamped), leaving Live; stops playback. No-op without a take.
  void setPlayhead(uint32_t frame);
  void goLive();
  /// Plays the take from the playhead (from the start when at its end), in wall time.
  void play(Clock::time_point now);
  void pause() { playbackStart_.reset(); }
  bool playingBack() const { return playbackStart_.has_value(); }
  /// Moves the playhead on by the wall time since play(); stops at the last frame. Returns
  /// whether the playhead changed.
  bool advance(Clock::time_point now);

  /// The mouse strokes of the take being recorded (or of the last one), as script events.
  const StrokeCapture& strokes() const { return strokes_; }
  /// The take time of the latest step while recording (finer than seconds(), which counts
  /// whole frames); seconds() otherwise.
  double takeTime() const;
  /// Where the strokes made now go, at takeTime(): null unless recording.
  StrokeCapture* capturing() { return recording() ? &strokes_ : nullptr; }

 private:
  StrokeCapture strokes_;
  double fps_ = 30.0;
  std::unique_ptr<Recorder> recorder_;
  std::shared_ptr<const Take> take_;
  std::optional<uint32_t> playhead_;
  std::optional<Clock::time_point> playbackStart_;
  uint32_t playbackFirst_ = 0;
};

}  // namespace sculpt::app
