// Simulator::solveStatic and its helpers: static equilibrium by Newton with a line search, load
// steps, and the rounding floor of the elastic forces (docs/fem.md, "Integrators", 3).

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "sim/simulator.h"
#include "sim/system_preconditioner.h"
#include "util/short_number.h"

namespace sculpt {
namespace {

/// The static residual's rounding floor in units of eps x |K X| (elasticRoundingFloor). On the
/// beam of the CLI tests the residual stalls at 0.35–0.7 of eps |K X| for loads that are tiny
/// against the stiffness (docs/fem.md, "Integrators", 3); 4 leaves room for other meshes.
constexpr double kStaticRoundingFloor = 4.0;
/// Below this many eps x the solid's size, a displacement at the rounding floor is not resolved.
constexpr double kResolvableDisplacement = 1e3;

/// |p| without overflow for entries near the largest double (a load of 1e200 N).
double overflowFreeNorm(const Points& p) {
  const double largest = p.cwiseAbs().maxCoeff();
  if (!(largest > 0.0) || !std::isfinite(largest)) return largest;
  return largest * (p / largest).norm();
}

}  // namespace

Points Simulator::loadGradient(const Points& x) {
  refreshNodes(x);
  const FormState state{x, scratchNodes_};
  for (auto& load : loads_) load->prepare(state);
  FormGradient g;
  g.setZero(x.rows(), scratchNodes_.rows());
  for (auto& load : loads_) load->addGradient(state, g);
  model_.addToControl(g.nodes, g.control);
  zeroFixed(g.control);
  return g.control;
}

double Simulator::elasticRoundingFloor() {
  // The elastic forces come from absolute positions (R^T x - X per element), so they carry
  // rounding of about eps x (the forces a displacement as large as the positions would give),
  // whatever the load. That force scale is |K X|: the elastic gradient of the uniform dilation
  // x = 2 X (its rotations are the identity) minus the one at rest.
  const double previous = loadFactor_;
  loadFactor_ = 0.0;
  const Points& rest = model_.restControl();
  const double scale =
      overflowFreeNorm(prepareAndGradient(2.0 * rest, false) - prepareAndGradient(rest, false));
  loadFactor_ = previous;
  return kStaticRoundingFloor * std::numeric_limits<double>::epsilon() * scale;
}

Simulator::NewtonOutcome Simulator::newtonToEquilibrium(double target, double tight,
                                                        int maxIterations, StaticReport& report) {
  for (int it = 0; it < maxIterations; ++it) {
    const Points g = prepareAndGradient(position_, false);
    const double residual = overflowFreeNorm(g);
    if (!std::isfinite(residual)) return NewtonOutcome::Failed;
    // The rounding floor may exceed a tiny load's own residual: one step is taken anyway.
    if (residual <= target && (it > 0 || residual <= tight)) return NewtonOutcome::Converged;
    Points dx;
    const CgResult cg = newtonStep(g, false, std::min(1e-3, 0.1 * target / residual), dx);
    report.cgIterations += cg.iterations;
    ++report.newtonIterations;
    // Backtracking on the residual: a full step from far away (a large load) can overshoot
    // into a state with larger forces.
    double step = 1.0;
    bool accepted = false;
    for (int k = 0; k < 12 && !accepted; ++k, step *= 0.5) {
      const Points trial = position_ + step * dx;
      const double trialResidual = overflowFreeNorm(prepareAndGradient(trial, false));
      if (std::isfinite(trialResidual) && trialResidual < residual) {
        position_ = trial;
        accepted = true;
      }
    }
    if (!accepted) return NewtonOutcome::Failed;
    // Positions carry about 1e-16 of the solid's size: once the update is below what they can
    // represent of the displacement, more iterations cannot reduce the residual.
    const double displacement = (position_ - model_.restControl()).cwiseAbs().maxCoeff();
    if (step * dx.cwiseAbs().maxCoeff() <= 1e-10 * displacement) return NewtonOutcome::Converged;
  }
  return overflowFreeNorm(prepareAndGradient(position_, false)) <= target ? NewtonOutcome::Converged
                                                                     : NewtonOutcome::Failed;
}

StaticReport Simulator::solveStatic(double tolerance, int maxNewtonIterations) {
  StaticReport report;
  velocity_.setZero();
  const bool ok = preconditioner_->update(model_, 0.0, 0.0, 1.0, freeDofs_);
  if (!ok) {
    report.message = "the stiffness could not be factored";
    return report;
  }
  // Scale of the loads: the external gradient at the start.
  const double scale = overflowFreeNorm(loadGradient(position_));
  if (scale == 0) {
    report.converged = true;
    report.message = "no loads";
    return report;
  }
  if (!std::isfinite(scale)) {
    report.message = "the loads are not finite";
    return report;
  }
  const double floor = elasticRoundingFloor();
  const auto target = [&](double factor, double relative) {
    return std::max(relative * factor * scale, floor);
  };
  const auto tight = [&](double factor, double relative) { return relative * factor * scale; };
  const Points start = position_;

  // The whole load at once; where Newton fails (large deformation), load steps from the start:
  // each step starts from the previous equilibrium, and a step that fails is halved.
  NewtonOutcome outcome = newtonToEquilibrium(target(1.0, tolerance), tight(1.0, tolerance),
                                              maxNewtonIterations, report);
  if (outcome != NewtonOutcome::Converged) {
    position_ = start;
    double reached = 0.0, increment = 0.125;
    while (reached < 1.0 && increment >= 1.0 / 4096) {
      const double next = std::min(1.0, reached + increment);
      loadFactor_ = next;
      const Points before = position_;
      // Intermediate equilibria need not be tight: they are starting points.
      const double relative = next < 1.0 ? 1e-6 : tolerance;
      if (newtonToEquilibrium(target(next, relative), tight(next, relative), maxNewtonIterations,
                              report) == NewtonOutcome::Converged) {
        reached = next;
        ++report.loadSteps;
        increment = std::min(2.0 * increment, 0.25);
      } else {
        position_ = before;
        increment *= 0.5;
      }
    }
    loadFactor_ = 1.0;
    outcome = reached == 1.0 ? NewtonOutcome::Converged : NewtonOutcome::Failed;
  }
  const double residual = overflowFreeNorm(prepareAndGradient(position_, false));
  report.residual = residual / scale;
  report.converged = outcome == NewtonOutcome::Converged && std::isfinite(residual);
  const bool unresolved =
      residual > tolerance * scale &&
      (position_ - model_.restControl()).cwiseAbs().maxCoeff() <
          kResolvableDisplacement * std::numeric_limits<double>::epsilon() * extent_;
  if (unresolved && !(floor < scale)) {
    // The elastic forces' rounding exceeds the load and nothing moved: the positions cannot
    // represent what the load does (a stiffness of 1e308 Pa). No answer to report.
    report.converged = false;
    report.message = "the load (" + shortNumber(scale) +
                     " N) moves the solid by less than its positions can resolve (the elastic "
                     "forces round to " +
                     (std::isfinite(floor) ? shortNumber(floor) + " N" : std::string("infinity")) +
                     "): it is too small for this stiffness";
  } else if (!report.converged || unresolved) {
    report.converged = false;
    report.message = std::isfinite(residual)
                         ? "no equilibrium found (residual " + shortNumber(report.residual) +
                               " of the load after " + std::to_string(report.newtonIterations) +
                               " Newton iterations" +
                               (report.loadSteps ? " and " + std::to_string(report.loadSteps) +
                                                       " load steps"
                                                 : std::string()) +
                               ")"
                         : "the solve produced non-finite forces";
  } else if (residual > tolerance * scale) {
    report.message = "equilibrium to the rounding of the elastic forces (" +
                     shortNumber(residual) + " N, " + shortNumber(report.residual) +
                     " of the load)";
  } else if (report.loadSteps > 0) {
    report.message = "equilibrium reached in " + std::to_string(report.loadSteps) + " load steps";
  }
  return report;
}

}  // namespace sculpt
