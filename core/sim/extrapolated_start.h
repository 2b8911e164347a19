#pragma once
// Where the implicit step's CG starts: the last two steps' corrections over the prediction
// x + h v, extrapolated linearly. In a smooth motion they change slowly, and a start near the
// answer saves iterations; the start costs one Hessian product (for its residual), so it is
// used only after a solve that took many (SimulationSettings::extrapolatedStartIterations;
// docs/fem.md, "Where the implicit step's CG starts").

#include "mesh/cell_complex.h"

namespace sculpt {

class ExtrapolatedStart {
 public:
  /// 2 c1 - c2 from the last two corrections, when both were for steps of `h` and the last
  /// solve took at least `leastIterations`; otherwise empty (start from zero).
  Points start(double h, int leastIterations) const;
  /// The correction a solve of step h found, and the CG iterations it took.
  void remember(const Points& correction, double h, int iterations);
  /// Forgets the history (a new state, a failed step).
  void clear();

 private:
  Points last_, beforeLast_;
  double step_ = 0;
  int iterations_ = 0;
};

}  // namespace sculpt
