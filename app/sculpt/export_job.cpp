#include "sculpt/export_job.h"

#include <pthread.h>
#include <sched.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <exception>
#include <utility>

#include "anim/take_surface.h"
#include "util/parallel_for.h"

namespace sculpt::app {

ExportJob::~ExportJob() {
  cancel_ = true;
  if (worker_.joinable()) worker_.join();
}

bool ExportJob::start(std::shared_ptr<const Take> take, FrameRange range, uint32_t every,
                      std::filesystem::path path, ExportFormat format,
                      TakeExportOptions options) {
  if (busy_) return false;
  if (worker_.joinable()) worker_.join();  // finished: its outcome was collected
  busy_ = true;
  cancel_ = false;
  finished_ = false;
  fraction_ = 0.0;
  worker_ = std::thread([this, take = std::move(take), range, every, path = std::move(path), format,
                         options] {
    // On this thread alone and only on idle cores (SCHED_IDLE; where that is refused, nice 19):
    // the export takes what the drawing and the simulation leave, and never holds the worker
    // pool that their loops share.
    sched_param idle{};
    if (pthread_setschedparam(pthread_self(), SCHED_IDLE, &idle) != 0)
      setpriority(PRIO_PROCESS, static_cast<id_t>(::syscall(SYS_gettid)), 19);
    const InlineLoopsOnThisThread inlineLoops;
    Outcome outcome;
    outcome.path = path;
    try {
      // The surface's deformers are built here too: nothing of the export runs on the UI thread.
      const TakeSurface surface(take, range, every);
      ProgressReporter progress([this](double fraction, std::string_view) {
        fraction_ = fraction;
        return !cancel_.load();
      });
      outcome.result = exportAnimation(surface, path, format, options, &progress);
      if (outcome.result.cancelled || progress.cancelled())
        outcome.kind = Outcome::Kind::Cancelled;
    } catch (const std::exception& error) {
      outcome.kind = cancel_ ? Outcome::Kind::Cancelled : Outcome::Kind::Failed;
      outcome.error = error.what();
    }
    {
      const std::lock_guard lock(mutex_);
      outcome_ = std::move(outcome);
    }
    finished_ = true;
  });
  return true;
}

std::optional<ExportJob::Outcome> ExportJob::poll() {
  if (!busy_ || !finished_) return std::nullopt;
  worker_.join();  // it has finished: this does not wait
  busy_ = false;
  const std::lock_guard lock(mutex_);
  return std::move(outcome_);
}

}  // namespace sculpt::app
