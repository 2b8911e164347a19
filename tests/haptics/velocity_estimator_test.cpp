#include "haptics/device/velocity_estimator.h"

#include <cmath>

#include <gtest/gtest.h>

namespace sculpt::haptics {
namespace {

TEST(VelocityEstimator, RecoversAConstantVelocityExactly) {
  VelocityEstimator estimator(0.005);
  const Eigen::Vector3d v(0.1, -0.25, 0.03), x0(0.01, 0.02, -0.03);
  Eigen::Vector3d estimate = Eigen::Vector3d::Zero();
  for (int i = 0; i < 20; ++i) estimate = estimator.add(i * 1e-3, x0 + v * (i * 1e-3));
  EXPECT_LT((estimate - v).norm(), 1e-12 * v.norm());
}

TEST(VelocityEstimator, AveragesQuantisationNoiseBetterThanADifference) {
  // An encoder with 0.1 mm steps moving at 10 mm/s: a two-sample difference jumps between 0 and
  // 100 mm/s (error 90 mm/s); the 5 ms least-squares slope spreads each step over the window.
  VelocityEstimator estimator(0.005);
  const double step = 1e-4, speed = 0.01;
  double worst = 0;
  for (int i = 0; i < 200; ++i) {
    const double t = i * 1e-3;
    const double x = std::floor(speed * t / step) * step;
    const Eigen::Vector3d estimate = estimator.add(t, Eigen::Vector3d(x, 0, 0));
    if (i > 10) worst = std::max(worst, std::abs(estimate.x() - speed));
  }
  const double differenceWorst = step / 1e-3 - speed;
  EXPECT_LT(worst, 0.25 * differenceWorst);
}

TEST(VelocityEstimator, IgnoresNonFiniteSamplesAndRestartsWhenTimeGoesBack) {
  VelocityEstimator estimator;
  estimator.add(0.0, Eigen::Vector3d::Zero());
  estimator.add(0.001, Eigen::Vector3d(0.001, 0, 0));
  EXPECT_NEAR(estimator.add(NAN, Eigen::Vector3d::Zero()).x(), 1.0, 1e-12);
  EXPECT_EQ(estimator.add(0.0, Eigen::Vector3d(5, 5, 5)).norm(), 0.0);
}

}  // namespace
}  // namespace sculpt::haptics
