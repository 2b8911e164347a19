#pragma once
// Reproducible pseudo-random test vectors.

#include <Eigen/Core>
#include <random>

namespace sculpt::test {

/// n values uniform in [-1, 1), the same for the same seed.
inline Eigen::VectorXd randomVector(Eigen::Index n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  Eigen::VectorXd v(n);
  for (Eigen::Index i = 0; i < n; ++i) v[i] = u(rng);
  return v;
}

}  // namespace sculpt::test
