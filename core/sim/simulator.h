#pragma once
// Time integration and static equilibrium of a FemModel (docs/design/local-frame-fem.md,
// "Integrators"):
//  - Paper: eq. 20, central differences with the elastic force at time t; the constant matrix
//    2M~ + dt D~ is solved by Jacobi-preconditioned CG warm-started from the previous step, to a
//    relative residual of 1e-4. We solve for the increment over the extrapolation 2p(t) - p(t-dt)
//    (the same equation), so that 1e-4 is relative to the forces and not to the positions.
//  - Implicit (default): backward Euler, the co-rotated stiffness linearised once per step (one
//    Newton step on the incremental potential), matrix-free CG preconditioned by a Cholesky
//    factor of M~ + h D~ + h^2 K~lin (see linear_stiffness.h).
//  - Static: Newton on the co-rotated equilibrium with the same CG.
// Fixed control points are eliminated. A step that produces non-finite values or a kinetic energy
// beyond what the loads could have supplied is undone and retried with halved sub-steps.

#include <Eigen/Geometry>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "fem/elastic_model.h"
#include "fem/fem_model.h"
#include "sim/conjugate_gradient.h"
#include "sim/extrapolated_start.h"
#include "sim/form.h"
#include "sim/system_preconditioner.h"

namespace sculpt {

class ElasticForm;
class InertiaForm;
class DampingForm;

enum class Integrator { Paper, Implicit };
const char* integratorName(Integrator integrator);
std::optional<Integrator> parseIntegrator(const std::string& name);

struct SimulationSettings {
  Integrator integrator = Integrator::Implicit;
  double timeStep = 1.0 / 60.0;     ///< seconds per step()
  bool corotated = true;            ///< false: small-strain linear elasticity (rotations = I)
  ElasticModel elasticModel = kDefaultElasticModel;  ///< with or without the inversion barrier
  double paperTolerance = 1e-4;     ///< relative CG residual of the paper's scheme
  double implicitTolerance = 1e-6;  ///< relative CG residual of the implicit and static solves
  int maxIterations = 2000;         ///< CG iterations per solve
  /// After an implicit solve of at least this many CG iterations the next one starts from the
  /// last two corrections extrapolated (sim/extrapolated_start.h). Below it, the start's Hessian
  /// product costs about what it saves: the default bunny takes 3.4 iterations from zero, 2.4
  /// and the product from the extrapolation; block10's collapse 20.6, and 17.9 and the product.
  int extrapolatedStartIterations = 8;
  int maxHalvings = 10;             ///< a failing step is retried with up to 2^this sub-steps
  /// The same inputs give the same bits: preconditioner factors made on a worker thread are
  /// taken at fixed steps, waited for when late. False (the window): taken when ready, never
  /// waited for.
  bool reproducible = true;
};

struct StepReport {
  bool ok = true;         ///< false: nothing worked, the state is the one before the step
  int substeps = 1;       ///< sub-steps finally used
  int iterations = 0;     ///< CG iterations, all sub-steps together
  double residual = 0;    ///< worst relative CG residual met
  std::string message;    ///< what went wrong and what was done about it; empty when nothing
};

struct StaticReport {
  bool converged = false;
  int newtonIterations = 0;
  int cgIterations = 0;
  int loadSteps = 0;    ///< 0: the whole load at once; otherwise the load steps it took
  double residual = 0;  ///< relative force residual |g| / |f_ext| on the free coordinates
  std::string message;
};

/// Empty when the settings are usable; otherwise a sentence naming the bad one.
std::string settingsProblem(const SimulationSettings& settings);

class Simulator {
 public:
  /// Throws std::invalid_argument when settingsProblem(settings) is not empty.
  explicit Simulator(FemModel& model, SimulationSettings settings = {});
  ~Simulator();
  Simulator(const Simulator&) = delete;
  Simulator& operator=(const Simulator&) = delete;

  FemModel& model() { return model_; }
  const SimulationSettings& settings() const { return settings_; }
  /// Returns a sentence when a setting is invalid (and keeps the old settings).
  std::string setSettings(const SimulationSettings& settings);

  const Points& positions() const { return position_; }  ///< control points
  const Points& velocities() const { return velocity_; }
  void setState(const Points& positions, const Points& velocities);
  double time() const { return time_; }

  const std::vector<uint8_t>& fixedMask() const { return fixed_; }
  void setFixed(uint32_t controlPoint, bool fixed);
  /// Fixes every control point whose rest position lies in `box`; returns how many.
  uint32_t fixInBox(const Eigen::AlignedBox3d& box);

  /// Adds an external load (gravity, forces, springs, pressure, contact); returns it.
  Form* addLoad(std::unique_ptr<Form> load);
  void removeLoad(const Form* load);
  size_t numLoads() const { return loads_.size(); }

  /// Advances by settings().timeStep.
  StepReport step();
  /// Moves the free control points to equilibrium under the loads (velocities set to zero):
  /// Newton with a line search on the force residual, and load steps where the whole load at
  /// once fails. Converged: the residual is at most `tolerance` of the load, or at the rounding
  /// floor of the elastic forces (for loads tiny against the stiffness; said in the message).
  StaticReport solveStatic(double tolerance = 1e-9, int maxNewtonIterations = 40);

  const PreconditionerStats& preconditionerStats() const;
  /// Refactors the implicit solve's preconditioner for the current materials and pins now,
  /// outside any step (nothing before the first implicit step). A benchmark's reference: steps
  /// with a factor that knows every edit, against the rescaled factor painting normally gets.
  void refactorPreconditioner();

  double kineticEnergy() const;  ///< 1/2 v^T M~ v
  double elasticEnergy();        ///< with rotations of the current state
  double loadEnergy();           ///< sum of the loads' potentials

 private:
  struct Attempt {
    bool ok = true;
    int iterations = 0;
    double residual = 0;
    std::string failure;
    bool hopeless = false;  ///< smaller steps cannot help (non-finite inputs)
  };
  static const SimulationSettings& validated(const SimulationSettings& settings);
  Attempt implicitSubstep(double h);
  Attempt paperSubstep(double h);
  Attempt checkState(const Points& start, double loadEnergyBefore);
  bool finiteForces(const Points& gradient, Attempt& attempt) const;

  // The forms in the current system: prepared at x (rotations, contact sets) with their summed
  // gradient, or their Hessian product at the prepared state; folded onto the control points
  // with fixed rows zeroed.
  Points prepareAndGradient(const Points& x, bool withInertia);
  // Solves H dx = -gradient on the free coordinates by preconditioned CG (H at the prepared
  // state, the preconditioner already current), from `start` when given, else from zero.
  CgResult newtonStep(const Points& gradient, bool withInertia, double tolerance, Points& dx,
                      const Points* start = nullptr);
  Points hessianProduct(const Points& dx, bool withInertia);
  void zeroFixed(Points& x) const;
  double systemLoadEnergy(const Points& x);
  // scratchNodes_ = A x (reused while x equals scratchControl_).
  void refreshNodes(const Points& x);
  enum class NewtonOutcome { Converged, Failed };
  /// Static Newton iterations at the current load factor until the residual is <= target (N),
  /// after at least one step unless it is <= tight (the tolerance without the rounding floor).
  NewtonOutcome newtonToEquilibrium(double target, double tight, int maxIterations,
                                    StaticReport& report);
  Points loadGradient(const Points& x);  ///< the loads' gradient alone, free coordinates
  /// The force residual below which the elastic forces are rounding (N).
  double elasticRoundingFloor();
  void refreshFreeDofs();

  FemModel& model_;
  SimulationSettings settings_;
  std::unique_ptr<ElasticForm> elastic_;
  std::unique_ptr<InertiaForm> inertia_;
  std::unique_ptr<DampingForm> damping_;
  FormList loads_;
  /// Multiplies the loads' gradient and Hessian: the load steps of solveStatic (1 otherwise).
  double loadFactor_ = 1.0;
  std::unique_ptr<SystemPreconditioner> preconditioner_;

  Points position_, velocity_, previous_;  // previous_: p(t - dt) of the paper's scheme
  double previousStep_ = 0;                // the dt that previous_ belongs to (0: none)
  Points lastIncrement_;                   // warm start of the paper scheme's CG solves
  ExtrapolatedStart implicitStart_;        // start of the implicit step's CG solves
  double time_ = 0;
  std::vector<uint8_t> fixed_;
  std::vector<int> freeDofs_;  // indices 3i + c of free coordinates
  double energyBudget_ = 0;
  double energyFloor_ = 0;
  double extent_ = 1;  // diagonal of the rest bounding box
  Points scratchNodes_, scratchNodeDirection_;
  Points scratchControl_;  // the control state scratchNodes_ belongs to (no rows: none)
  uint64_t freeDofsVersion_ = 0;  // counts changes of freeDofs_
  // 2M~ + h D~ of the paper's scheme on the free coordinates (in freeDofs_ order), for
  // paperMatrixStep_, the mass matrix version and the free set it was built for.
  SparseMatrix paperMatrix_;
  Eigen::VectorXd paperDiagonal_;
  double paperMatrixStep_ = 0;
  uint64_t paperMatrixVersion_ = ~uint64_t(0), paperMatrixFreeVersion_ = ~uint64_t(0);
  // The inertia's and the damping's Hessians as one matrix (a CG iteration then streams one
  // matrix, not two), for inertiaDampingStep_ and the mass version.
  SparseMatrix inertiaDamping_;
  double inertiaDampingStep_ = 0;
  uint64_t inertiaDampingVersion_ = ~uint64_t(0);
};

}  // namespace sculpt
