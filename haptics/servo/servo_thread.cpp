#include "haptics/servo/servo_thread.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include <pthread.h>
#include <sched.h>

namespace sculpt::haptics {
namespace {

int64_t steadyNs() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(
             std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

// The servo asks for real-time priority and carries on without it when not allowed (a user's
// desktop usually is not): the safety layer tolerates the jitter either way.
void raisePriority() {
  sched_param param{};
  param.sched_priority = std::max(1, sched_get_priority_max(SCHED_FIFO) - 1);
  (void)pthread_setschedparam(pthread_self(), SCHED_FIFO, &param);
}

}  // namespace

ServoThread::ServoThread(HapticDevice& device, std::shared_ptr<ProbeChannel> probe,
                         const SafetySettings& safety, double rateHz, size_t recordTicks)
    : device_(device),
      probe_(std::move(probe)),
      controller_(device.info(), safety),
      period_(1.0 / std::clamp(rateHz, 1.0, 10000.0)),
      recordCapacity_(recordTicks) {
  records_.reserve(recordCapacity_);
  periods_.reserve(std::max<size_t>(recordCapacity_, 1 << 16));
  startNs_ = steadyNs();
}

ServoThread::~ServoThread() { stop(); }

double ServoThread::now() const { return static_cast<double>(steadyNs() - startNs_) * 1e-9; }

void ServoThread::start() {
  if (started_) return;
  started_ = true;
  thread_ = std::thread([this] { run(); });
}

void ServoThread::stop() {
  stop_.store(true);
  if (thread_.joinable()) thread_.join();
}

void ServoThread::run() {
  raisePriority();
  using clock = std::chrono::steady_clock;
  const auto period = std::chrono::nanoseconds(static_cast<int64_t>(std::llround(period_ * 1e9)));
  auto deadline = clock::now();
  double previous = now();
  HandState state;
  while (!stop_.load(std::memory_order_relaxed)) {
    const double t = now();
    ServoTickInput in;
    in.dt = std::max(0.0, t - previous);
    previous = t;
    in.device = device_.read(t);
    in.command = commands_.read();
    const SceneProbe* probe = nullptr;
    if (probe_) {
      probe = &probe_->read();
      in.probeAge = probe->generation == 0
                        ? 0.0
                        : static_cast<double>(steadyNs() - probe->publishedNs) * 1e-9;
    }
    in.probe = probe;
    const ServoTickResult result = controller_.tick(in);
    device_.sendForce(result.commanded);

    if (ticks_ == 0) firstTick_ = t;
    lastTick_ = t;
    ++ticks_;
    if (ticks_ > 1 && periods_.size() < periods_.capacity()) periods_.push_back(in.dt);
    if (result.clamped) ++clamped_;
    maxForce_ = std::max(maxForce_, result.commanded.norm());
    if (records_.size() < recordCapacity_)
      records_.push_back({t, in.dt, in.probeAge, in.device.position, result.commanded,
                          result.desired, result.onSolid, result.acting, result.clamped,
                          in.device.connected});
    state.tick = ticks_;
    state.time = t;
    state.device = in.device;
    state.result = result;
    state.probeAge = in.probeAge;
    state.tripped = controller_.safety().tripped();
    states_.publish(state);

    deadline += period;
    const auto late = clock::now() - deadline;
    if (late > 10 * period) {
      dropped_ += static_cast<uint64_t>(late / period);
      deadline = clock::now();
    }
    std::this_thread::sleep_until(deadline);
  }
  // Shutdown: zero at once (the safety's immediate-zero rule), and say so to the device.
  ServoTickInput last;
  last.shuttingDown = true;
  last.device = device_.read(now());
  last.command = commands_.read();
  device_.sendForce(controller_.tick(last).commanded);
}

ServoStatistics ServoThread::statistics() const {
  ServoStatistics s;
  s.ticks = ticks_;
  s.seconds = lastTick_ - firstTick_;
  s.meanHz = s.seconds > 0 ? static_cast<double>(ticks_ - 1) / s.seconds : 0.0;
  s.maxForce = maxForce_;
  s.clampedTicks = clamped_;
  s.droppedTicks = dropped_;
  if (!periods_.empty()) {
    std::vector<double> sorted = periods_;
    const size_t k =
        std::min(sorted.size() - 1, static_cast<size_t>(0.99 * static_cast<double>(sorted.size())));
    std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(k), sorted.end());
    s.periodP99Ms = sorted[k] * 1e3;
    s.periodMaxMs = *std::max_element(periods_.begin(), periods_.end()) * 1e3;
  }
  return s;
}

}  // namespace sculpt::haptics
