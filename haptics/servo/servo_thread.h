#pragma once
// The 1 kHz haptic servo on its own thread. Tick k is due at t0 + k T (absolute deadlines, so
// the rate does not drift with the work done per tick); a tick more than ten periods late drops
// the missed ones and starts again from now. Each tick measures its dt, reads the device
// (never blocking), takes the newest probe (wait-free), runs ServoController::tick and sends the
// force. It never waits on the simulation and never calls hidapi.
//
// What leaves it: the newest HandState, wait-free for one reader (the haptic session); and,
// when asked for, a record of every tick (preallocated, read after stop()) for the command
// line's force log.

#include <atomic>
#include <cstdint>
#include <memory>
#include <thread>
#include <vector>

#include "haptics/device/haptic_device.h"
#include "haptics/servo/servo_controller.h"
#include "scene/scene_probe.h"
#include "util/triple_buffer.h"

namespace sculpt::haptics {

/// The servo's newest state, for the session and the window.
struct HandState {
  uint64_t tick = 0;  ///< 0: no tick yet
  double time = 0.0;  ///< s since the servo started
  DeviceSample device;
  ServoTickResult result;
  double probeAge = 0.0;
  bool tripped = false;  ///< the safety is latched at zero (re-arm to feel again)
};

/// One tick, as the force log has it.
struct ServoRecord {
  double time = 0.0, dt = 0.0, probeAge = 0.0;
  Eigen::Vector3d devicePosition = Eigen::Vector3d::Zero();
  Eigen::Vector3d commanded = Eigen::Vector3d::Zero();
  Eigen::Vector3d desired = Eigen::Vector3d::Zero();
  Eigen::Vector3d onSolid = Eigen::Vector3d::Zero();
  bool acting = false, clamped = false, connected = false;
};

struct ServoStatistics {
  uint64_t ticks = 0;
  double seconds = 0.0;        ///< from the first tick to the last
  double meanHz = 0.0;
  double periodP99Ms = 0.0;    ///< of the measured dt (recorded ticks)
  double periodMaxMs = 0.0;
  double maxForce = 0.0;       ///< largest |commanded| (N)
  uint64_t clampedTicks = 0;
  uint64_t droppedTicks = 0;   ///< deadlines skipped after a long stall
};

class ServoThread {
 public:
  /// `device` outlives the thread. `recordTicks`: how many ticks to record (0: none).
  ServoThread(HapticDevice& device, std::shared_ptr<ProbeChannel> probe,
              const SafetySettings& safety, double rateHz = 1000.0, size_t recordTicks = 0);
  ~ServoThread();
  ServoThread(const ServoThread&) = delete;
  ServoThread& operator=(const ServoThread&) = delete;

  void start();
  /// Sends zero force, then joins. Idempotent.
  void stop();
  /// One writer thread (the session): the command from the next tick on.
  void command(const ServoCommand& command) { commands_.publish(command); }
  /// One reader thread (the session): the newest state.
  const HandState& latest() { return states_.read(); }
  /// After stop().
  const std::vector<ServoRecord>& records() const { return records_; }
  ServoStatistics statistics() const;  ///< after stop()
  double now() const;  ///< s on the servo's clock

 private:
  void run();
  HapticDevice& device_;
  std::shared_ptr<ProbeChannel> probe_;
  ServoController controller_;
  double period_;
  size_t recordCapacity_;
  TripleBuffer<ServoCommand> commands_;
  TripleBuffer<HandState> states_;
  std::vector<ServoRecord> records_;
  std::atomic<bool> stop_{false};
  bool started_ = false;
  int64_t startNs_ = 0;
  // Written by the servo thread, read after join.
  uint64_t ticks_ = 0, clamped_ = 0, dropped_ = 0;
  double firstTick_ = 0, lastTick_ = 0, maxForce_ = 0;
  std::vector<double> periods_;
  std::thread thread_;
};

}  // namespace sculpt::haptics
