#pragma once
// One export of a take (anim/take_export.h) on a worker thread, so that the window keeps
// drawing while it runs. The worker publishes its progress through atomics and its outcome under
// a mutex; the UI thread polls and joins only once the worker has finished. Cancel goes through
// the export's ProgressReporter (the writer stops at its next report and leaves nothing behind).

#include <atomic>
#include <filesystem>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "anim/take.h"
#include "anim/take_export.h"

namespace sculpt::app {

class ExportJob {
 public:
  struct Outcome {
    enum class Kind { Written, Failed, Cancelled } kind = Kind::Written;
    std::filesystem::path path;
    ExportResult result;
    std::string error;  ///< Failed: one sentence
  };

  ExportJob() = default;
  /// Cancels an export in flight and waits for it (the window is closing).
  ~ExportJob();
  ExportJob(const ExportJob&) = delete;
  ExportJob& operator=(const ExportJob&) = delete;

  /// Starts writing every `every`-th frame of `range` of `take` to `path` (TakeSurface); false
  /// (nothing started) while an export runs or its outcome has not been collected.
  bool start(std::shared_ptr<const Take> take, FrameRange range, uint32_t every,
             std::filesystem::path path, ExportFormat format, TakeExportOptions options);
  /// Started and not yet collected by poll().
  bool busy() const { return busy_; }
  /// The fraction written so far, in [0, 1].
  double fraction() const { return fraction_.load(); }
  /// Asks the worker to stop at its next progress report.
  void cancel() { cancel_ = true; }
  /// Once the worker has finished: joins it and returns the outcome (once); otherwise nullopt.
  std::optional<Outcome> poll();

 private:
  std::thread worker_;
  bool busy_ = false;  // UI thread only
  std::atomic<bool> cancel_{false}, finished_{false};
  std::atomic<double> fraction_{0.0};
  std::mutex mutex_;
  Outcome outcome_;  // under mutex_, written by the worker before finished_
};

}  // namespace sculpt::app
