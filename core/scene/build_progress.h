#pragma once
// Progress of a scene build: each stage owns a span [begin, end] of the whole build's fraction
// and reports under its own name, and its milliseconds are recorded.

#include <chrono>
#include <string>
#include <utility>

#include "scene/scene_builder.h"
#include "util/progress.h"

namespace sculpt {

/// One stage of a build. start() reports the stage's beginning (false: cancelled); reporter()
/// maps a sub-task's fractions [0, 1] into the span (null when the build reports nothing).
class BuildStage {
 public:
  BuildStage(ProgressReporter* outer, double begin, double end, std::string name)
      : outer_(outer), begin_(begin), name_(std::move(name)),
        inner_([outer, begin, end, name = name_](double f, std::string_view) {
          return outer->report(begin + f * (end - begin), name);
        }) {}
  bool start() { return !outer_ || outer_->report(begin_, name_); }
  ProgressReporter* reporter() { return outer_ ? &inner_ : nullptr; }
  bool cancelled() const { return outer_ && (outer_->cancelled() || inner_.cancelled()); }

 private:
  ProgressReporter* outer_;
  double begin_;
  std::string name_;
  ProgressReporter inner_;
};

/// Records the milliseconds between successive lap() calls.
class StageClock {
 public:
  explicit StageClock(StageTimes& out) : out_(out), start_(Clock::now()) {}
  void lap(std::string name) {
    const Clock::time_point now = Clock::now();
    out_.emplace_back(std::move(name),
                      std::chrono::duration<double, std::milli>(now - start_).count());
    start_ = now;
  }

 private:
  using Clock = std::chrono::steady_clock;
  StageTimes& out_;
  Clock::time_point start_;
};

}  // namespace sculpt
