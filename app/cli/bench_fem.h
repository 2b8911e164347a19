#pragma once
// The FEM step benchmark (sculpt-cli bench fem): wall times of Simulator::step() on a simulator
// the caller has set up (pins, loads, settings), of one elastic force evaluation, and optionally
// stiffness dabs painted between steps, as the paint tool paints them, or pins made and released.

#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "cli/cli_args.h"
#include "sim/simulator.h"

namespace sculpt::cli {

struct FemBenchOptions {
  int steps = 100;       ///< measured steps
  int warmupSteps = 3;   ///< untimed steps after the first one
  int paintEvery = 0;    ///< a stiffness dab before every N-th warm-up and measured step; 0: none
  /// The dabs start at this measured step (none in the warm-up) where more than 0: painting
  /// then begins from the factors a solid that has stood still has (the rest-stiffness one).
  int paintFrom = 0;
  bool paintDensity = false;  ///< the dabs paint density (10x and 0.1x) instead of stiffness
  /// Before every N-th warm-up and measured step, the pin of the control points in the top
  /// quarter of the solid (by rest y) that no other pin holds: made, then released, and so on;
  /// 0: none.
  int pinEvery = 0;
  /// After each dab or pin edit, outside the timing, a new preconditioner factor for the new
  /// materials and pins (Simulator::refactorPreconditioner): steps free of the factor's age,
  /// for comparison.
  bool freshFactor = false;
  /// Writes one line per measured step to the error stream: its time, CG iterations and the
  /// elastic pass timed before it.
  bool trace = false;
  /// The first step's time when the caller took that step already (a scene's build does);
  /// none: the benchmark takes and times it.
  std::optional<double> firstStepMs;
};

struct FemBenchFigures {
  double firstStepMs = 0;    ///< the first step (the preconditioner's first factorisation)
  double medianStepMs = 0;   ///< median of the measured steps
  double p99StepMs = 0;      ///< their 99th percentile (nearest rank)
  double maxStepMs = 0;      ///< the slowest of them
  double elasticPassMs = 0;  ///< median of one ElasticForm::prepareAndAddGradient, one timed
                             ///< before each measured step
  double stepPasses = 0;     ///< medianStepMs / elasticPassMs: a step in elastic passes
  double meanCgIterations = 0;  ///< per measured step
  int failures = 0;             ///< steps (all of them) that needed sub-steps or failed
  bool failed = false;          ///< a measured step failed
  int dabs = 0;                 ///< dabs painted before measured steps
  int warmupDabs = 0;           ///< dabs painted before warm-up steps
  double dabRadius = 0;         ///< m (rest): one control cell, controlCellSize()
  long paintedSamples = 0;      ///< Gauss samples touched by all dabs
  int pinEdits = 0;             ///< pins made or released before measured steps
  int warmupPinEdits = 0;       ///< before warm-up steps
  uint32_t pinnedPoints = 0;    ///< control points each pin edit holds or releases
};

/// Fixes the control points whose rest y is the least (the bottom layer); returns how many.
uint32_t fixLowestLayer(Simulator& simulator);

/// Edge length of a typical control cell: cbrt(rest volume / #control cells) (m).
double controlCellSize(const FemModel& model);

/// Steps `simulator` and times it (see FemBenchOptions); a failing step's first message goes to
/// `err`. Dab k (0, 1, ...) is centred on a control cell's centre, the cells visited in a fixed
/// stride order, with Young's modulus 10x (even k) or 0.1x (odd k) the model's initial one.
FemBenchFigures runFemBench(Simulator& simulator, const FemBenchOptions& options,
                            std::ostream& err);
inline FemBenchFigures runFemBench(Simulator& simulator, int steps, int paintEvery,
                                   std::ostream& err) {
  FemBenchOptions options;
  options.steps = steps;
  options.paintEvery = paintEvery;
  return runFemBench(simulator, options, err);
}

/// The options bench fem takes besides the FEM options.
extern const std::vector<OptionSpec> kFemBenchOptions;

/// sculpt-cli bench fem CONTROL|SCENE ...: sets `file` for error messages; returns the exit code.
/// Throws UsageError.
int benchFemCommand(const CliArgs& args, std::string& file);

}  // namespace sculpt::cli
