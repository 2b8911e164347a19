#include "sim/simulator.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include "sim/conjugate_gradient.h"
#include "sim/standard_forms.h"
#include "sim/system_preconditioner.h"
#include "util/short_number.h"

namespace sculpt {
namespace {


Eigen::VectorXd gather(const Points& p, const std::vector<int>& dofs) {
  Eigen::VectorXd v(Eigen::Index(dofs.size()));
  const double* data = p.data();
  for (size_t k = 0; k < dofs.size(); ++k) v[Eigen::Index(k)] = data[dofs[k]];
  return v;
}

void scatter(const Eigen::VectorXd& v, const std::vector<int>& dofs, Points& p) {
  double* data = p.data();
  for (size_t k = 0; k < dofs.size(); ++k) data[dofs[k]] = v[Eigen::Index(k)];
}

}  // namespace

const char* integratorName(Integrator integrator) {
  return integrator == Integrator::Paper ? "paper" : "implicit";
}

std::optional<Integrator> parseIntegrator(const std::string& name) {
  if (name == "paper") return Integrator::Paper;
  if (name == "implicit") return Integrator::Implicit;
  return std::nullopt;
}

Simulator::Simulator(FemModel& model, SimulationSettings settings)
    : model_(model),
      settings_(validated(settings)),
      elastic_(std::make_unique<ElasticForm>(model, settings.corotated)),
      preconditioner_(std::make_unique<SystemPreconditioner>()) {
  model.elastic().setModel(settings_.elasticModel);
  preconditioner_->setReproducible(settings_.reproducible);
  const Eigen::Index n = model.numControlPoints();
  position_ = model.restControl();
  velocity_.setZero(n, 3);
  fixed_.assign(size_t(n), 0);
  refreshFreeDofs();
  // Energies below this are noise for the explosion test: a millionth of the energy of the
  // whole mass moving by its own size in a second.
  const Eigen::Vector3d extent =
      (position_.colwise().maxCoeff() - position_.colwise().minCoeff()).transpose();
  extent_ = std::max(extent.norm(), 1e-12);
  energyFloor_ = 1e-6 * std::max(model.totalMass(), 1e-12) * extent_ * extent_;
  energyBudget_ = 0;
}

Simulator::~Simulator() = default;

const PreconditionerStats& Simulator::preconditionerStats() const {
  return preconditioner_->stats();
}

void Simulator::refactorPreconditioner() { preconditioner_->refactor(model_); }

std::string settingsProblem(const SimulationSettings& s) {
  if (!(s.timeStep > 0) || !std::isfinite(s.timeStep))
    return "time step " + shortNumber(s.timeStep) + " s must be positive and finite";
  if (!(s.paperTolerance > 0) || !(s.implicitTolerance > 0))
    return "solver tolerances must be positive";
  if (s.maxIterations < 1 || s.maxHalvings < 0 || s.maxHalvings > 30)
    return "iteration limits out of range";
  return {};
}

const SimulationSettings& Simulator::validated(const SimulationSettings& s) {
  if (const std::string problem = settingsProblem(s); !problem.empty())
    throw std::invalid_argument("invalid simulation settings: " + problem);
  return s;
}

std::string Simulator::setSettings(const SimulationSettings& s) {
  if (std::string problem = settingsProblem(s); !problem.empty()) return problem;
  if (s.corotated != settings_.corotated)
    elastic_ = std::make_unique<ElasticForm>(model_, s.corotated);
  if (s.elasticModel != model_.elastic().model()) model_.elastic().setModel(s.elasticModel);
  preconditioner_->setReproducible(s.reproducible);
  settings_ = s;
  return {};
}

void Simulator::setState(const Points& positions, const Points& velocities) {
  position_ = positions;
  velocity_ = velocities;
  previousStep_ = 0;
  lastIncrement_.resize(0, 3);
  implicitStart_.clear();
  energyBudget_ = kineticEnergy() + elasticEnergy();
}

void Simulator::setFixed(uint32_t controlPoint, bool fixed) {
  if (controlPoint >= fixed_.size()) return;
  fixed_[controlPoint] = fixed ? 1 : 0;
  if (fixed) velocity_.row(controlPoint).setZero();
  refreshFreeDofs();
}

uint32_t Simulator::fixInBox(const Eigen::AlignedBox3d& box) {
  uint32_t count = 0;
  const Points& rest = model_.restControl();
  for (Eigen::Index i = 0; i < rest.rows(); ++i) {
    if (!box.contains(rest.row(i).transpose())) continue;
    fixed_[size_t(i)] = 1;
    velocity_.row(i).setZero();
    ++count;
  }
  refreshFreeDofs();
  return count;
}

void Simulator::refreshFreeDofs() {
  freeDofs_.clear();
  for (size_t i = 0; i < fixed_.size(); ++i)
    if (!fixed_[i])
      for (int c = 0; c < 3; ++c) freeDofs_.push_back(int(3 * i) + c);
  ++freeDofsVersion_;
  lastIncrement_.resize(0, 3);
}

Form* Simulator::addLoad(std::unique_ptr<Form> load) {
  loads_.push_back(std::move(load));
  return loads_.back().get();
}

void Simulator::removeLoad(const Form* load) {
  std::erase_if(loads_, [&](const std::unique_ptr<Form>& f) { return f.get() == load; });
}

void Simulator::zeroFixed(Points& x) const {
  for (size_t i = 0; i < fixed_.size(); ++i)
    if (fixed_[i]) x.row(Eigen::Index(i)).setZero();
}

void Simulator::refreshNodes(const Points& x) {
  // A step evaluates the same control state several times (load energies before and after,
  // the forces, the energy check, the next step's start): A x is computed once per state.
  if (scratchControl_.rows() == x.rows() && scratchControl_ == x) return;
  model_.nodesFromControl(x, scratchNodes_);
  scratchControl_ = x;
}

Points Simulator::prepareAndGradient(const Points& x, bool withInertia) {
  refreshNodes(x);
  const FormState state{x, scratchNodes_};
  FormGradient g;
  g.setZero(x.rows(), scratchNodes_.rows());
  elastic_->prepareAndAddGradient(state, g);
  for (auto& load : loads_) load->prepare(state);
  if (withInertia) {
    inertia_->prepare(state);
    damping_->prepare(state);
  }
  if (loadFactor_ == 1.0) {
    for (auto& load : loads_) load->addGradient(state, g);
  } else if (loadFactor_ != 0.0) {
    FormGradient l;
    l.setZero(x.rows(), scratchNodes_.rows());
    for (auto& load : loads_) load->addGradient(state, l);
    g.control += loadFactor_ * l.control;
    g.nodes += loadFactor_ * l.nodes;
  }
  if (withInertia) {
    inertia_->addGradient(state, g);
    damping_->addGradient(state, g);
  }
  model_.addToControl(g.nodes, g.control);
  zeroFixed(g.control);
  return g.control;
}

Points Simulator::hessianProduct(const Points& dx, bool withInertia) {
  model_.nodesFromControl(dx, scratchNodeDirection_);
  const FormState state{position_, scratchNodes_};
  const FormState direction{dx, scratchNodeDirection_};
  FormGradient r;
  r.setZero(dx.rows(), scratchNodeDirection_.rows());
  elastic_->addHessianProduct(state, direction, r);
  if (loadFactor_ == 1.0) {
    for (auto& load : loads_) load->addHessianProduct(state, direction, r);
  } else if (loadFactor_ != 0.0) {
    FormGradient l;
    l.setZero(dx.rows(), scratchNodeDirection_.rows());
    for (auto& load : loads_) load->addHessianProduct(state, direction, l);
    r.control += loadFactor_ * l.control;
    r.nodes += loadFactor_ * l.nodes;
  }
  if (withInertia) r.control += applyScalarMatrix(inertiaDamping_, dx);
  model_.addToControl(r.nodes, r.control);
  zeroFixed(r.control);
  return r.control;
}

CgResult Simulator::newtonStep(const Points& gradient, bool withInertia, double tolerance,
                               Points& dx, const Points* start) {
  const Eigen::VectorXd b = -gather(gradient, freeDofs_);
  // From zero, CG's first residual costs no Hessian product.
  Eigen::VectorXd x = start ? gather(*start, freeDofs_) : Eigen::VectorXd::Zero(b.size());
  Points direction = Points::Zero(position_.rows(), 3);
  const LinearOperator op = [&](const Eigen::VectorXd& in, Eigen::VectorXd& out) {
    direction.setZero();
    scatter(in, freeDofs_, direction);
    out = gather(hessianProduct(direction, withInertia), freeDofs_);
  };
  const LinearOperator pre = [&](const Eigen::VectorXd& r, Eigen::VectorXd& z) {
    preconditioner_->apply(r, z);
  };
  const CgResult cg = conjugateGradient(op, pre, b, x, tolerance, settings_.maxIterations);
  preconditioner_->reportIterations(cg.iterations);
  dx = Points::Zero(position_.rows(), 3);
  scatter(x, freeDofs_, dx);
  return cg;
}

double Simulator::systemLoadEnergy(const Points& x) {
  refreshNodes(x);
  const FormState state{x, scratchNodes_};
  double e = 0;
  for (auto& load : loads_) e += load->energy(state);
  return e;
}

double Simulator::kineticEnergy() const {
  const Points Mv = applyScalarMatrix(model_.reducedMass(), velocity_);
  return 0.5 * velocity_.cwiseProduct(Mv).sum();
}

double Simulator::elasticEnergy() {
  // A query (a progress line about once a second of wall time): without the warm start kept,
  // the same run would give different results depending on how fast it ran.
  const ElasticKernel::WarmStartKept kept(model_.elastic());
  refreshNodes(position_);
  const FormState state{position_, scratchNodes_};
  elastic_->prepare(state);
  return elastic_->energy(state);
}

double Simulator::loadEnergy() {
  refreshNodes(position_);
  const FormState state{position_, scratchNodes_};
  for (auto& load : loads_) load->prepare(state);
  return systemLoadEnergy(position_);
}

Simulator::Attempt Simulator::checkState(const Points& start, double loadEnergyBefore) {
  Attempt a;
  if (!position_.allFinite() || !velocity_.allFinite()) {
    a.ok = false;
    a.failure = "non-finite positions";
    return a;
  }
  // The mechanical energy cannot exceed what the state had plus the work the loads did (with a
  // factor 10 of slack for the paper scheme's energy oscillation). The elastic energy costs a
  // kernel pass, so it is measured only when something moved noticeably or the kinetic
  // energy alone already looks wrong.
  // The work of conservative loads is the drop of their potential, signed: energy the body gives
  // back to the loads (rising against gravity) leaves the budget again, so an oscillation
  // cannot inflate it.
  const double loadEnergyAfter = systemLoadEnergy(position_);
  const double work = loadEnergyBefore - loadEnergyAfter;
  if (std::isfinite(work)) energyBudget_ = std::max(0.0, energyBudget_ + work);
  const double limit = 10.0 * energyBudget_ + energyFloor_;
  double energy = kineticEnergy();
  const double moved = (position_ - start).cwiseAbs().maxCoeff();
  if (std::isfinite(energy) && energy <= limit && moved > 1e-3 * extent_) {
    // With the rotations the step was solved with, not new ones: they differ from the new
    // state's by one step's rotation, which changes the energy only to second order (and can
    // only raise it), and the polar decompositions would cost a third of an element pass.
    refreshNodes(position_);
    energy += elastic_->energy(FormState{position_, scratchNodes_});
  }
  if (!std::isfinite(work)) {
    // The loads' work beyond double precision (forces of 1e200 N): smaller steps cannot help.
    a.ok = false;
    a.hopeless = true;
    a.failure = "the work of the loads exceeds double precision (" + shortNumber(work) +
                " J): the loads are too large";
  } else if (!std::isfinite(energy) || energy > limit) {
    a.ok = false;
    a.failure = "mechanical energy " + shortNumber(energy) + " J exceeds the energy supplied (" +
                shortNumber(energyBudget_) + " J)";
  }
  return a;
}

bool Simulator::finiteForces(const Points& gradient, Attempt& attempt) const {
  if (gradient.allFinite()) return true;
  attempt.ok = false;
  attempt.hopeless = true;
  attempt.failure = "a load or material gives non-finite forces";
  return false;
}

Simulator::Attempt Simulator::implicitSubstep(double h) {
  Attempt a;
  preconditioner_->prepareFirstFactor(model_, freeDofs_);
  inertia_ = std::make_unique<InertiaForm>(model_, h);
  damping_ = std::make_unique<DampingForm>(model_, h);
  if (inertiaDampingStep_ != h || inertiaDampingVersion_ != model_.massVersion()) {
    inertiaDamping_ =
        inertia_->scale() * inertia_->matrix() + damping_->scale() * damping_->matrix();
    inertiaDampingStep_ = h;
    inertiaDampingVersion_ = model_.massVersion();
  }
  const Points start = position_;
  Points predicted = position_ + h * velocity_;
  for (size_t i = 0; i < fixed_.size(); ++i)
    if (fixed_[i]) predicted.row(Eigen::Index(i)) = start.row(Eigen::Index(i));
  inertia_->setPrediction(predicted);
  damping_->setStart(start);
  const double loadBefore = systemLoadEnergy(start);

  position_ = predicted;
  const Points g = prepareAndGradient(position_, true);
  if (!finiteForces(g, a)) {
    position_ = start;
    return a;
  }
  preconditioner_->update(model_, 1.0 / (h * h), 1.0 / h, 1.0, freeDofs_);
  Points dx;
  const Points guess = implicitStart_.start(h, settings_.extrapolatedStartIterations);
  const CgResult cg = newtonStep(g, true, settings_.implicitTolerance, dx,
                                 guess.rows() > 0 ? &guess : nullptr);
  implicitStart_.remember(dx, h, cg.iterations);
  a.iterations = cg.iterations;
  a.residual = cg.relativeResidual;
  if (cg.indefinite && !cg.converged) {
    // A load whose stiffness outweighs the solid's and the inertia's at this step (a pressure
    // far above the Young's modulus): the linearised step has no minimum, and a shorter one
    // (more inertia per step) does.
    position_ = start;
    a.ok = false;
    a.failure = "the step's system is not positive definite (a load stiffer than the solid)";
    return a;
  }
  position_ += dx;
  velocity_ = (position_ - start) / h;
  Attempt check = checkState(start, loadBefore);
  check.iterations = a.iterations;
  check.residual = a.residual;
  return check;
}

Simulator::Attempt Simulator::paperSubstep(double h) {
  Attempt a;
  if (previousStep_ != h || previous_.rows() != position_.rows()) {
    previous_ = position_ - h * velocity_;
    previousStep_ = h;
    lastIncrement_.resize(0, 3);
  }
  const Points start = position_;
  const double loadBefore = systemLoadEnergy(start);
  const Points g = prepareAndGradient(position_, false);  // = -f
  if (!finiteForces(g, a)) return a;
  const SparseMatrix& M = model_.reducedMass();
  const SparseMatrix& D = model_.reducedDamping();
  // (2M~ + h D~) delta = 2 h^2 f - 2 h D~ (p - p_prev), p(t+h) = 2p - p_prev + delta.
  Points rhs = -2.0 * h * h * g - 2.0 * h * applyScalarMatrix(D, position_ - previous_);
  zeroFixed(rhs);
  const Eigen::VectorXd b = gather(rhs, freeDofs_);
  // 2M~ + h D~ changes only with the step and the materials; it is kept on the free
  // coordinates (each control point's block is the scalar entry times I3), so that a CG
  // iteration is one sparse product.
  if (paperMatrixStep_ != h || paperMatrixVersion_ != model_.massVersion() ||
      paperMatrixFreeVersion_ != freeDofsVersion_ || paperMatrix_.rows() == 0) {
    const SparseMatrix lhs = 2.0 * M + h * D;
    std::vector<int> freeIndex(size_t(3 * lhs.rows()), -1);
    for (size_t k = 0; k < freeDofs_.size(); ++k) freeIndex[size_t(freeDofs_[k])] = int(k);
    std::vector<Eigen::Triplet<double>> entries;
    for (int j = 0; j < lhs.outerSize(); ++j)
      for (SparseMatrix::InnerIterator it(lhs, j); it; ++it)
        for (int c = 0; c < 3; ++c) {
          const int row = freeIndex[size_t(3 * it.row() + c)], col = freeIndex[size_t(3 * j + c)];
          if (row >= 0 && col >= 0) entries.emplace_back(row, col, it.value());
        }
    paperMatrix_.resize(Eigen::Index(freeDofs_.size()), Eigen::Index(freeDofs_.size()));
    paperMatrix_.setFromTriplets(entries.begin(), entries.end());
    paperDiagonal_ = paperMatrix_.diagonal();
    paperMatrixStep_ = h;
    paperMatrixVersion_ = model_.massVersion();
    paperMatrixFreeVersion_ = freeDofsVersion_;
  }
  const LinearOperator op = [&](const Eigen::VectorXd& in, Eigen::VectorXd& out) {
    out.noalias() = paperMatrix_ * in;
  };
  const LinearOperator jacobi = [&](const Eigen::VectorXd& r, Eigen::VectorXd& z) {
    z = r.cwiseQuotient(paperDiagonal_);
  };
  Eigen::VectorXd x = lastIncrement_.rows() == position_.rows()
                          ? gather(lastIncrement_, freeDofs_)
                          : Eigen::VectorXd::Zero(b.size());
  const CgResult cg = conjugateGradient(op, jacobi, b, x, settings_.paperTolerance,
                                        settings_.maxIterations);
  a.iterations = cg.iterations;
  a.residual = cg.relativeResidual;
  Points delta = Points::Zero(position_.rows(), 3);
  scatter(x, freeDofs_, delta);
  lastIncrement_ = delta;
  Points next = 2.0 * position_ - previous_ + delta;
  for (size_t i = 0; i < fixed_.size(); ++i)
    if (fixed_[i]) next.row(Eigen::Index(i)) = start.row(Eigen::Index(i));
  previous_ = position_;
  position_ = next;
  velocity_ = (position_ - previous_) / h;
  Attempt check = checkState(start, loadBefore);
  check.iterations = a.iterations;
  check.residual = a.residual;
  return check;
}

StepReport Simulator::step() {
  StepReport report;
  const Points savedPosition = position_, savedVelocity = velocity_, savedPrevious = previous_;
  const double savedPreviousStep = previousStep_, savedBudget = energyBudget_;
  std::string firstFailure;
  bool hopeless = false;
  for (int halvings = 0; halvings <= settings_.maxHalvings; ++halvings) {
    const int substeps = 1 << halvings;
    const double h = settings_.timeStep / substeps;
    bool ok = true;
    report.iterations = 0;
    report.residual = 0;
    for (int s = 0; s < substeps && ok; ++s) {
      const Attempt a = settings_.integrator == Integrator::Paper ? paperSubstep(h)
                                                                   : implicitSubstep(h);
      report.iterations += a.iterations;
      report.residual = std::max(report.residual, a.residual);
      if (!a.ok) {
        ok = false;
        if (firstFailure.empty()) firstFailure = a.failure;
        hopeless = hopeless || a.hopeless;
      }
    }
    if (ok) {
      report.substeps = substeps;
      time_ += settings_.timeStep;
      if (halvings > 0)
        report.message = std::string("step of ") + shortNumber(settings_.timeStep) +
                         " s failed (" + firstFailure + "); restored and took " +
                         std::to_string(substeps) + " sub-steps of " + shortNumber(h) + " s";
      return report;
    }
    position_ = savedPosition;
    velocity_ = savedVelocity;
    previous_ = savedPrevious;
    previousStep_ = savedPreviousStep;
    energyBudget_ = savedBudget;
    lastIncrement_.resize(0, 3);
    implicitStart_.clear();
    if (hopeless) break;  // smaller steps cannot repair non-finite inputs
  }
  report.ok = false;
  if (hopeless) {
    report.message = "step refused (" + firstFailure + "); the state before the step was kept";
    return report;
  }
  report.substeps = 1 << settings_.maxHalvings;
  report.message = "step failed (" + firstFailure + ") even with " +
                   std::to_string(report.substeps) +
                   " sub-steps; the state before the step was kept. Reduce the time step or "
                   "use the implicit integrator";
  return report;
}

}  // namespace sculpt
