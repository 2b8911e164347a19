#pragma once
// A simulated PHANTOM-class arm (Touch-like or Omni-like limits) for tests, demos and the window
// without hardware. Three ways to move it:
//   - trajectory: the stylus follows the script (device_script.h) exactly, whatever the force;
//   - hand: a hand, a mass-spring-damper, pulls the stylus towards the script's position while
//     the device renders the force the servo last sent, so the hand feels it: the stylus lags
//     behind the script by force / hand stiffness;
//   - external: the same hand, pulled towards a set point another thread gives (the window's
//     mouse) through setHandTarget().
// The hand is integrated with fixed substeps of at most 0.1 ms (semi-implicit Euler, damping
// implicit) from the previous read to `now` in read(now); the force is held between sends.
//
// Threading: read() and sendForce() on the servo thread (HapticDevice's rule). setHandTarget()
// from one other thread, wait-free (a triple buffer). setConnected() from any thread (atomic).
// forces() and droppedForces() only once the servo thread has stopped: the record is written
// without synchronisation, into storage reserved up front so the servo never allocates.

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "haptics/device/haptic_device.h"
#include "haptics/device/velocity_estimator.h"
#include "haptics/mock/device_script.h"
#include "util/triple_buffer.h"

namespace sculpt::haptics {

enum class MockMode { kTrajectory, kHand, kExternal };

/// A force the device was sent, stamped with the time of the read() before it (s).
struct TimedForce {
  double time = 0.0;
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
};

class MockPhantom : public HapticDevice {
 public:
  /// The script's clutch shows as this button (the Touch's second stylus button).
  static constexpr uint32_t kClutchButton = 1u << 1;
  static constexpr double kSubstep = 1e-4;  ///< s, the hand's longest integration step
  static constexpr size_t kDefaultForceCapacity = size_t{1} << 16;  ///< about 65 s at 1 kHz

  /// "Mock Touch" (3.3 N, 400 N/m, damping 4.0, radius 0.075 m) or "Mock Omni" (3.3 N, 700 N/m,
  /// 5.0, 0.10 m): CHAI3D's figures for the real arms.
  static DeviceInfo modelInfo(PhantomModel model);

  /// Trajectory or hand mode, as the script says.
  explicit MockPhantom(DeviceScript script, size_t forceCapacity = kDefaultForceCapacity);
  /// External mode: the hand pulls towards setHandTarget()'s set point (the centre until then).
  /// A hand outside the script's limits is clamped into them.
  MockPhantom(PhantomModel model, const HandDynamics& hand,
              size_t forceCapacity = kDefaultForceCapacity);

  const DeviceInfo& info() const override { return info_; }
  DeviceSample read(double now) override;
  /// Recorded as sent; rendered (in hand and external modes) while connected, non-finite as zero.
  void sendForce(const Eigen::Vector3d& force) override;

  /// External mode, one writer thread: where the hand means the stylus to be (device m).
  void setHandTarget(const Eigen::Vector3d& position, uint32_t buttons);
  /// Any thread: unplugged, the device reads connected = false and renders no force.
  void setConnected(bool connected) { connected_.store(connected, std::memory_order_relaxed); }

  MockMode mode() const { return mode_; }
  const DeviceScript& script() const { return script_; }
  const HandDynamics& hand() const { return hand_; }

  /// After the servo stopped: every force sent, in order (up to the capacity).
  const std::vector<TimedForce>& forces() const { return forces_; }
  /// After the servo stopped: forces sent once the record was full (counted, not stored).
  size_t droppedForces() const { return dropped_; }

 private:
  struct HandTarget {
    Eigen::Vector3d position = Eigen::Vector3d::Zero();
    uint32_t buttons = 0;
  };
  struct Goal {
    Eigen::Vector3d position, velocity;
  };
  Goal goalAt(double t) const;
  void moveHand(double to);

  DeviceInfo info_;
  MockMode mode_;
  DeviceScript script_;
  HandDynamics hand_;

  TripleBuffer<HandTarget> target_;  // external mode: window thread -> servo thread
  HandTarget externalTarget_;        // servo thread: the newest target read
  std::atomic<bool> connected_{true};

  // Servo thread state.
  bool started_ = false;
  double time_ = 0.0;  // s, the time of the hand's state
  Eigen::Vector3d position_ = Eigen::Vector3d::Zero(), velocity_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d rendered_ = Eigen::Vector3d::Zero();  // N, the force held on the stylus
  VelocityEstimator velocityEstimator_;
  std::vector<TimedForce> forces_;
  size_t forceCapacity_;
  size_t dropped_ = 0;
};

}  // namespace sculpt::haptics
