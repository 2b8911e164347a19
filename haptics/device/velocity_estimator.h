#pragma once
// Linear velocity of a device from its positions, as haptic SDKs estimate it: the least-squares
// slope of the positions over a short window of time (a plain two-sample difference amplifies
// the encoder's quantisation by 1/dt and buzzes when used for damping). Samples older than the
// window are dropped; the estimate is zero until two samples span a non-zero time.

#include <array>
#include <cstddef>

#include <Eigen/Core>

namespace sculpt::haptics {

class VelocityEstimator {
 public:
  /// `window` in seconds (> 0; 5 ms by default, five servo ticks).
  explicit VelocityEstimator(double window = 0.005) : window_(window) {}
  /// Adds a sample at time `t` (s, non-decreasing) and returns the estimate.
  Eigen::Vector3d add(double t, const Eigen::Vector3d& position);
  Eigen::Vector3d velocity() const { return velocity_; }
  void reset();

 private:
  static constexpr size_t kCapacity = 32;
  struct Sample {
    double t = 0;
    Eigen::Vector3d x = Eigen::Vector3d::Zero();
  };
  double window_;
  std::array<Sample, kCapacity> samples_{};
  size_t first_ = 0, count_ = 0;
  Eigen::Vector3d velocity_ = Eigen::Vector3d::Zero();
};

}  // namespace sculpt::haptics
