#include "haptics/device/velocity_estimator.h"

#include <cmath>

namespace sculpt::haptics {

Eigen::Vector3d VelocityEstimator::add(double t, const Eigen::Vector3d& position) {
  if (!std::isfinite(t) || !position.allFinite()) return velocity_;
  if (count_ > 0 && t < samples_[(first_ + count_ - 1) % kCapacity].t) reset();
  if (count_ == kCapacity) first_ = (first_ + 1) % kCapacity, --count_;
  samples_[(first_ + count_) % kCapacity] = {t, position};
  ++count_;
  while (count_ > 2 && t - samples_[first_].t > window_)
    first_ = (first_ + 1) % kCapacity, --count_;

  // Least-squares slope: sum (t - tm)(x - xm) / sum (t - tm)^2.
  double tm = 0;
  Eigen::Vector3d xm = Eigen::Vector3d::Zero();
  for (size_t i = 0; i < count_; ++i) {
    const Sample& s = samples_[(first_ + i) % kCapacity];
    tm += s.t, xm += s.x;
  }
  tm /= static_cast<double>(count_), xm /= static_cast<double>(count_);
  double stt = 0;
  Eigen::Vector3d stx = Eigen::Vector3d::Zero();
  for (size_t i = 0; i < count_; ++i) {
    const Sample& s = samples_[(first_ + i) % kCapacity];
    stt += (s.t - tm) * (s.t - tm);
    stx += (s.t - tm) * (s.x - xm);
  }
  velocity_ = stt > 0 ? Eigen::Vector3d(stx / stt) : Eigen::Vector3d::Zero();
  return velocity_;
}

void VelocityEstimator::reset() {
  first_ = count_ = 0;
  velocity_.setZero();
}

}  // namespace sculpt::haptics
