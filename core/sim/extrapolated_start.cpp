#include "sim/extrapolated_start.h"

#include <utility>

namespace sculpt {

Points ExtrapolatedStart::start(double h, int leastIterations) const {
  if (iterations_ < leastIterations || step_ != h || beforeLast_.rows() == 0) return {};
  return 2.0 * last_ - beforeLast_;
}

void ExtrapolatedStart::remember(const Points& correction, double h, int iterations) {
  if (step_ != h) clear();
  beforeLast_ = std::move(last_);
  last_ = correction;
  step_ = h;
  iterations_ = iterations;
}

void ExtrapolatedStart::clear() {
  last_.resize(0, 3);
  beforeLast_.resize(0, 3);
  step_ = 0;
  iterations_ = 0;
}

}  // namespace sculpt
