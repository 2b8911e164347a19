#include "sim/system_preconditioner.h"

#include <algorithm>
#include <chrono>
#include <optional>
#include <stdexcept>
#include <utility>

#include "fem/elastic_kernel.h"
#include "sim/assembled_stiffness.h"
#include "sim/linear_stiffness.h"
#include "sim/restricted_matrix.h"

namespace sculpt {

struct SystemPreconditioner::Factor {
  SparseCholesky cholesky;
  bool valid = false;
  bool restStiffness = false;  // the elements' own rest stiffness, not the stand-in
  // The stiffness makes up enough of S's diagonal for solves in the points' rotated frames to
  // be worth trying: where the inertia dominates, turning it with the points (R M~ R^T, not M~)
  // costs more than the turned stiffness saves.
  bool stiffnessDominated = false;
  double scales[3] = {0, 0, 0};
  std::vector<int> freeDofs;
  uint64_t materialVersion = 0;
  Eigen::VectorXd stiffnessDiagonal;  // K~lin's diagonal (all 3N coordinates)
  Eigen::VectorXd modulus;            // controlPointModulus of the factored materials
  // S on every coordinate: what extending the factor to coordinates it lacks reads.
  SparseMatrix system;
  // The stiffness in S, unscaled, with its materials: the next factor of its kind starts there.
  std::shared_ptr<const AssembledStiffness> assembled;
  double milliseconds = 0;
  explicit Factor(SparseCholesky::Method method) : cholesky(method) {}
};

// What a factorisation needs, copied: the worker thread must not read the model while the
// simulation paints it.
struct SystemPreconditioner::Request {
  const FemMesh* mesh = nullptr;
  const SparseMatrix* A = nullptr;
  std::vector<LameParameters> lame;
  SparseMatrix inertia;  // a M~ + b D~ (scalar; empty when a = b = 0)
  double scales[3] = {0, 0, 0};
  std::vector<int> freeDofs;
  uint64_t materialVersion = 0;
  std::optional<SparseMatrix> stiffness;  // K~lin, when assembled already
  std::optional<Eigen::VectorXd> modulus;  // its controlPointModulus
  bool restStiffness = false;  // the elements' own rest stiffness instead of K~lin
  // The last stiffness of this kind assembled, if any: only the elements painted since are
  // assembled again.
  std::shared_ptr<const AssembledStiffness> base;
  std::shared_ptr<const std::atomic<bool>> cancelled;  // set: give up (no factor)
};

// Reproducible: taken a fixed number of solves after its start (waiting if it is late), never
// when it happens to be ready, so that the results do not depend on timing. Otherwise (the
// window): taken at the first solve that finds it ready, never waited for. Dropped or
// destroyed, it is told to stop.
class SystemPreconditioner::WorkerFactor {
 public:
  WorkerFactor(Request request, SparseCholesky::Method method, int delay);
  ~WorkerFactor() { drop(); }
  WorkerFactor(const WorkerFactor&) = delete;
  WorkerFactor& operator=(const WorkerFactor&) = delete;
  bool running() const { return future_.valid(); }
  // Done (or never started): dropping it now waits for nothing.
  bool finished() const {
    return !running() ||
           future_.wait_for(std::chrono::seconds(0)) == std::future_status::ready;
  }
  void cancel() { *cancelled_ = true; }
  bool restStiffness() const { return restStiffness_; }
  // Counts this solve; the factor when its turn has come (null before, and once taken).
  std::unique_ptr<Factor> takeWhenDue(bool reproducible) {
    if (!running()) return nullptr;
    ++solvesSinceStart_;
    if (!reproducible)
      return future_.wait_for(std::chrono::seconds(0)) == std::future_status::ready
                 ? future_.get()
                 : nullptr;
    return solvesSinceStart_ < delay_ ? nullptr : future_.get();
  }
  void drop() {
    *cancelled_ = true;
    if (running()) future_.wait();
    future_ = {};
  }

 private:
  std::shared_ptr<std::atomic<bool>> cancelled_ = std::make_shared<std::atomic<bool>>(false);
  std::future<std::unique_ptr<Factor>> future_;
  int solvesSinceStart_ = 0, delay_;
  bool restStiffness_;
};

namespace {
using Clock = std::chrono::steady_clock;
// Where the per-kind arrays keep a factor's kind: 0 the stand-in, 1 the rest stiffness.
int kindIndex(bool restStiffness) { return restStiffness ? 1 : 0; }
// The default bunny: 0.57 (rotated solves: 3 CG iterations instead of 5); the blocks, the head
// and the bridge of docs/BENCHMARKS.md at K = 1 and 2: 0.10-0.19 (rotated solves took 1.3-1.9x
// the iterations).
constexpr double kStiffnessShareForRotations = 1.0 / 3.0;
}  // namespace

SystemPreconditioner::SystemPreconditioner(SparseCholesky::Method method) : method_(method) {}

SystemPreconditioner::~SystemPreconditioner() {
  upgrade_.reset();
  pending_.reset();
  abandoned_.clear();
  if (firstFactor_.valid()) firstFactor_.wait();
}

namespace {

SystemPreconditioner::Request requestFor(const FemModel& model, double a, double b, double c,
                                         const std::vector<int>& freeDofs) {
  SystemPreconditioner::Request request;
  request.mesh = &model.mesh();
  request.A = &model.stencilMatrix();
  request.lame = model.mesh().gaussLame;
  if (a != 0 || b != 0) request.inertia = a * model.reducedMass() + b * model.reducedDamping();
  request.scales[0] = a;
  request.scales[1] = b;
  request.scales[2] = c;
  request.freeDofs = freeDofs;
  request.materialVersion = model.materialVersion();
  return request;
}

// S restricted to the free coordinates; adds the restricted diagonal to `diagonalSum` when
// given.
SparseMatrix restrictToFree(const SparseMatrix& S, const std::vector<int>& freeDofs,
                            double* diagonalSum = nullptr) {
  SparseMatrix restricted = restrictedMatrix(S, freeDofs, freeDofs);
  if (diagonalSum)
    for (Eigen::Index k = 0; k < restricted.rows(); ++k) *diagonalSum += restricted.coeff(k, k);
  return restricted;
}

// S = c K~lin + (a M~ + b D~) x I3 on K~lin's pattern. The consistent mass couples control
// points one B-spline support further than the stand-in does; those entries are left out (per
// axis the cubic B-spline Gram entry at that distance is 1/2416 of the diagonal), so that S's
// pattern, and its ordering and symbolic analysis, are known once K~lin is.
SparseMatrix systemMatrix(SparseMatrix S, const SystemPreconditioner::Request& request) {
  S *= request.scales[2];  // K~lin taken and scaled in place: no second copy of it
  const SparseMatrix& inertia = request.inertia;  // added to the diagonal of each 3x3 block
  if (inertia.nonZeros() == 0) return S;
  for (Eigen::Index column = 0; column < S.outerSize(); ++column) {
    const Eigen::Index point = column / 3, coordinate = column % 3;
    SparseMatrix::InnerIterator m(inertia, point);
    for (SparseMatrix::InnerIterator it(S, column); it; ++it) {
      if (it.row() % 3 != coordinate) continue;
      const Eigen::Index other = it.row() / 3;
      while (m && m.row() < other) ++m;
      if (m && m.row() == other) it.valueRef() += m.value();
    }
  }
  return S;
}

std::unique_ptr<SystemPreconditioner::Factor> factorRequest(
    SystemPreconditioner::Request request, SparseCholesky::Method method,
    std::unique_ptr<SystemPreconditioner::Factor> analysed = nullptr) {
  const Clock::time_point start = Clock::now();
  auto factor = analysed ? std::move(analysed)
                         : std::make_unique<SystemPreconditioner::Factor>(method);
  const std::atomic<bool>* cancelled = request.cancelled.get();
  const FemMesh& mesh = *request.mesh;
  SparseMatrix stiffness =
      request.stiffness ? std::move(*request.stiffness)
      : request.base    ? stiffnessAt(mesh, *request.base, request.lame, *request.A, cancelled)
                        : assembleStiffness(mesh, request.lame, *request.A, request.restStiffness,
                                            cancelled);
  if (cancelled && *cancelled) return nullptr;
  factor->restStiffness = request.restStiffness;
  factor->stiffnessDiagonal = stiffness.diagonal();
  factor->modulus = request.modulus
                        ? *request.modulus
                        : controlPointModulus(*request.mesh, request.lame, *request.A);
  double diagonalSum = 0;
  factor->system = systemMatrix(stiffness, request);
  factor->assembled = std::make_shared<const AssembledStiffness>(
      AssembledStiffness{std::move(stiffness), std::move(request.lame), request.restStiffness});
  const SparseMatrix restricted = restrictToFree(factor->system, request.freeDofs, &diagonalSum);
  const int n = int(restricted.rows());
  double stiffnessSum = 0;
  for (int dof : request.freeDofs)
    stiffnessSum += request.scales[2] * factor->stiffnessDiagonal[dof];
  factor->stiffnessDominated = stiffnessSum >= kStiffnessShareForRotations * diagonalSum;

  // Every point pinned: nothing to solve for, and CHOLMOD refuses an empty matrix.
  if (n == 0) factor->valid = true;
  // A solid held by nothing but springs has rigid modes in K~lin: shift them slightly.
  const double meanDiagonal = n > 0 ? diagonalSum / n : 1.0;
  for (double shift : {0.0, 1e-10, 1e-6}) {
    if (n == 0) break;
    if (shift == 0) {
      factor->valid = factor->cholesky.factor(restricted);
    } else {
      SparseMatrix shifted = restricted;
      for (int i = 0; i < n; ++i) shifted.coeffRef(i, i) += shift * meanDiagonal;
      factor->valid = factor->cholesky.factor(shifted);
    }
    if (factor->valid) break;
  }
  std::copy(request.scales, request.scales + 3, factor->scales);
  factor->freeDofs = request.freeDofs;
  factor->materialVersion = request.materialVersion;
  factor->milliseconds =
      std::chrono::duration<double, std::milli>(Clock::now() - start).count();
  return factor;
}

}  // namespace

std::unique_ptr<SystemPreconditioner::Factor> SystemPreconditioner::makeFactor(
    const FemModel& model, double a, double b, double c, const std::vector<int>& freeDofs) {
  Request request = requestOfKind(model, a, b, c, freeDofs, factor_ && factor_->restStiffness);
  std::unique_ptr<Factor> analysed;
  if (firstFactor_.valid()) {
    FirstFactor early = firstFactor_.get();
    if (early.materialVersion == request.materialVersion) {
      request.stiffness = std::move(early.stiffness);
      request.modulus = std::move(early.modulus);
      if (early.analysed->freeDofs == freeDofs) analysed = std::move(early.analysed);
    }
  }
  return factorRequest(std::move(request), method_, std::move(analysed));
}

void SystemPreconditioner::prepareFirstFactor(const FemModel& model,
                                              const std::vector<int>& freeDofs) {
  if (factor_ || firstFactor_.valid()) return;
  // A copy of the materials: the worker must not read the model while the simulation runs on.
  firstFactor_ = std::async(
      std::launch::async, [&mesh = model.mesh(), &A = model.stencilMatrix(),
                           lame = model.mesh().gaussLame, version = model.materialVersion(),
                           freeDofs, method = method_] {
        FirstFactor first;
        first.materialVersion = version;
        first.stiffness = reducedLinearStiffness(mesh, lame, A);
        first.modulus = controlPointModulus(mesh, lame, A);
        // S has K~lin's pattern (systemMatrix): its ordering and analysis can be made now.
        first.analysed = std::make_unique<Factor>(method);
        first.analysed->freeDofs = freeDofs;
        if (!freeDofs.empty())
          first.analysed->cholesky.analyse(restrictToFree(first.stiffness, freeDofs));
        return first;
      });
}

SystemPreconditioner::Request SystemPreconditioner::requestOfKind(
    const FemModel& model, double a, double b, double c, const std::vector<int>& freeDofs,
    bool restStiffness) const {
  Request request = requestFor(model, a, b, c, freeDofs);
  request.restStiffness = restStiffness;
  request.base = assembled_[kindIndex(restStiffness)];
  return request;
}

void SystemPreconditioner::adopt(std::unique_ptr<Factor> factor) {
  factor_ = std::move(factor);
  if (factor_->assembled) assembled_[kindIndex(factor_->restStiffness)] = factor_->assembled;
  ++stats_.factorizations;
  stats_.lastFactorMs = factor_->milliseconds;
  stats_.restStiffness = factor_->restStiffness;
  if (factor_->restStiffness) ++stats_.restStiffnessFactorizations;
  stats_.factorNonZeros = factor_->cholesky.factorNonZeros();
  // A factor that came behind the materials (painting went on while it was made) never serves
  // a solve unrescaled: its drift is measured from the last factor of its kind that did.
  const bool current = factor_->materialVersion == materialVersion_;
  freshIterations_ = current ? -1 : kindFreshIterations_[kindIndex(factor_->restStiffness)];
  firstSolveBehind_ = !current;
  drifted_ = false;
  appliedMaterialVersion_ = ~uint64_t(0);  // the mapping and scaling are redone
}

SystemPreconditioner::WorkerFactor::WorkerFactor(Request request, SparseCholesky::Method method,
                                                 int delay)
    : delay_(delay), restStiffness_(request.restStiffness) {
  request.cancelled = cancelled_;
  future_ = std::async(std::launch::async, [request = std::move(request), method]() mutable {
    return factorRequest(std::move(request), method);
  });
}

void SystemPreconditioner::startBackground(const FemModel& model, double a, double b, double c,
                                           const std::vector<int>& freeDofs) {
  if (pending_ && pending_->running()) return;
  // Materials drifted from a rest-stiffness factor: another of its kind (only the elements
  // painted since its own are assembled again). Along a stroke it comes a few dabs behind and
  // still saves iterations over the stand-in (docs/BENCHMARKS.md, "A paint stroke").
  // Pins edited: the stand-in.
  const bool rest = factor_ && factor_->restStiffness && freeDofs == factor_->freeDofs;
  pending_ = std::make_unique<WorkerFactor>(requestOfKind(model, a, b, c, freeDofs, rest), method_,
                                            kDeterministicDelay);
}

void SystemPreconditioner::adoptFromWorker(std::unique_ptr<Factor> factor,
                                           const std::vector<int>& freeDofs) {
  // A factor made for another time step is of no use (sub-steps refactor on the spot); nor is a
  // rest-stiffness factor that failed.
  if (!factor || (factor_ && !std::equal(factor->scales, factor->scales + 3, factor_->scales)))
    return;
  if (factor->restStiffness && !factor->valid) return;
  // Nor one made for pins edited since, unless it is a stand-in and the factor in use does not
  // fit the pins either (pins edited back, a pin made and released: the new one would need
  // extending where the one in use serves them as they are).
  if (factor->freeDofs != freeDofs &&
      (factor->restStiffness || (factor_ && factor_->freeDofs == freeDofs)))
    return;
  adopt(std::move(factor));
  ++stats_.backgroundFactorizations;
}

bool SystemPreconditioner::update(const FemModel& model, double massScale, double dampingScale,
                                  double stiffnessScale, const std::vector<int>& freeDofs) {
  if (!std::is_sorted(freeDofs.begin(), freeDofs.end()))
    throw std::invalid_argument("SystemPreconditioner: free coordinates must be increasing");
  const double scales[3] = {massScale, dampingScale, stiffnessScale};
  materialVersion_ = model.materialVersion();
  const bool pinsEdited = freeDofs != freeDofs_;  // or the first solve
  if (pinsEdited && solves_ > 0) giveUpRestStiffness();
  std::erase_if(abandoned_, [](const std::unique_ptr<WorkerFactor>& w) { return w->finished(); });
  if (pending_)
    if (std::unique_ptr<Factor> factor = pending_->takeWhenDue(reproducible_))
      adoptFromWorker(std::move(factor), freeDofs);
  const bool pending = pending_ && pending_->running();
  if (!factor_ || !std::equal(scales, scales + 3, factor_->scales)) {
    factorNow(model, massScale, dampingScale, stiffnessScale, freeDofs);
  } else if (!pending &&
             (freeDofs != factor_->freeDofs ||
              (drifted_ && model.materialVersion() != factor_->materialVersion))) {
    // Pins or materials moved away from the factor: make a new one while this one serves.
    startBackground(model, massScale, dampingScale, stiffnessScale, freeDofs);
  }
  ++solves_;
  countQuietSolves(model);
  upgradeToRestStiffness(model, freeDofs);
  if (appliedMaterialVersion_ != model.materialVersion() || pinsEdited) rescale(model, freeDofs);
  chooseRotation(model);
  return factor_->valid;
}

void SystemPreconditioner::chooseRotation(const FemModel& model) {
  rotateThisSolve_ = rotationPreferred_;
  rotationProbe_ = false;
  // Not on the first solve: the first step is what a user waits for before anything moves,
  // and a solid starts near its rest frames.
  if (!factor_->stiffnessDominated || solves_ < 2) {
    rotateThisSolve_ = false;
    return;
  }
  if (++solvesSinceRotationProbe_ >= kRotationProbeEvery) {
    rotateThisSolve_ = !rotationPreferred_;
    rotationProbe_ = true;
    solvesSinceRotationProbe_ = 0;
  }
  if (!rotateThisSolve_) return;
  if (rotationsModel_ != &model) {
    pointRotations_ = std::make_unique<ControlPointRotations>(model);
    rotationsModel_ = &model;
  }
  pointRotations_->update(model.elastic().rotations());
  ++stats_.rotatedSolves;
}

void SystemPreconditioner::countQuietSolves(const FemModel& model) {
  const uint64_t version = model.materialVersion();
  if (quietMaterialVersion_ != version) {
    if (quietMaterialVersion_ != ~uint64_t(0)) quietSolves_ = 0;  // not the first materials
    quietMaterialVersion_ = version;
  }
  ++quietSolves_;
}

void SystemPreconditioner::giveUpRestStiffness() {
  quietSolves_ = 0;
  // Made for the old pins, it would be dropped at its turn: waiting for it then (a
  // reproducible run does) stalls a step for nothing. Told to stop, it is let finish unwatched.
  for (std::unique_ptr<WorkerFactor>* worker : {&upgrade_, &pending_}) {
    if (!*worker || !(*worker)->running() || !(*worker)->restStiffness()) continue;
    (*worker)->cancel();
    abandoned_.push_back(std::move(*worker));
    ++stats_.givenUp;
  }
}

void SystemPreconditioner::upgradeToRestStiffness(const FemModel& model,
                                                  const std::vector<int>& freeDofs) {
  if (upgrade_ && upgrade_->running()) {
    adoptFromWorker(upgrade_->takeWhenDue(reproducible_), freeDofs);
    return;
  }
  // Not from the first solve: its step is what the window waits for. Static solves (no
  // inertia) are a few Newton steps, over before such a factor would arrive. Without tricubic
  // elements the stand-in is the elements' own stiffness already. Where the inertia dominates,
  // the solves are not rotated, and the elements' own stiffness saves iterations only while the
  // solid stays near its rest shape. A rest-stiffness factor that came behind the materials is
  // replaced once they stay put: below the drift threshold, it would serve on rescaled.
  const bool currentRest =
      factor_->restStiffness && factor_->materialVersion == model.materialVersion();
  if (solves_ < 2 || currentRest || (pending_ && pending_->running()) ||
      factor_->scales[0] == 0 ||
      model.mesh().numTricubic() == 0 || !factor_->stiffnessDominated ||
      freeDofs != factor_->freeDofs || quietSolves_ < kQuietSolves)
    return;
  const double* scales = factor_->scales;
  Request request = requestOfKind(model, scales[0], scales[1], scales[2], freeDofs, true);
  // Making it costs about 0.07 ms of a core per element (the bunny's 2,968: 0.2 s). A
  // reproducible run takes it at the same turn as any worker factor, waiting if it is late:
  // steps drawn one by one (sculpt --bench) find it ready; a tight loop on two cores (sculpt-cli)
  // gains nothing by stepping beside it, as the worker and the steps share the cores.
  upgrade_ = std::make_unique<WorkerFactor>(std::move(request), method_, kDeterministicDelay);
}

void SystemPreconditioner::refactor(const FemModel& model) {
  if (!factor_) return;
  materialVersion_ = model.materialVersion();
  const double* s = factor_->scales;
  factorNow(model, s[0], s[1], s[2], freeDofs_);
  rescale(model, freeDofs_);
}

void SystemPreconditioner::factorNow(const FemModel& model, double a, double b, double c,
                                     const std::vector<int>& freeDofs) {
  pending_.reset();  // a factor on the worker is dropped
  adopt(makeFactor(model, a, b, c, freeDofs));
}

void SystemPreconditioner::rescale(const FemModel& model, const std::vector<int>& freeDofs) {
  if (freeDofs != freeDofs_) {  // not at every material edit
    rotatedPoints_.clear();
    for (size_t k = 0; k + 2 < freeDofs.size(); ++k)
      if (freeDofs[k] % 3 == 0 && freeDofs[k + 2] == freeDofs[k] + 2) {
        rotatedPoints_.emplace_back(Eigen::Index(k), uint32_t(freeDofs[k] / 3));
        k += 2;
      }
  }
  freeDofs_ = freeDofs;
  appliedMaterialVersion_ = model.materialVersion();
  const Factor& f = *factor_;
  mapped_ = freeDofs != f.freeDofs;
  const bool sameMaterials = model.materialVersion() == f.materialVersion;
  if (!mapped_ && sameMaterials) {
    inverseSqrtScale_.resize(0);
    toFactor_.clear();
    extendFactor({});
    return;
  }
  // The current diagonal of S, with the stand-in stiffness's diagonal following the materials
  // through the control points' modulus ratio.
  const Eigen::VectorXd modulus =
      sameMaterials ? f.modulus
                    : controlPointModulus(model.mesh(), model.mesh().gaussLame,
                                          model.stencilMatrix());
  const Eigen::VectorXd mass = model.reducedMass().diagonal();
  const Eigen::VectorXd damping = model.reducedDamping().diagonal();
  auto diagonal = [&](int dof, const Eigen::VectorXd& mod) {
    const int point = dof / 3;
    const double ratio = f.modulus[point] > 0 ? mod[point] / f.modulus[point] : 1.0;
    return f.scales[0] * mass[point] + f.scales[1] * damping[point] +
           f.scales[2] * f.stiffnessDiagonal[dof] * ratio;
  };
  std::vector<int> factorIndex(f.stiffnessDiagonal.size(), -1);
  for (size_t k = 0; k < f.freeDofs.size(); ++k) factorIndex[size_t(f.freeDofs[k])] = int(k);
  const Eigen::Index n = Eigen::Index(freeDofs.size());
  toFactor_.assign(freeDofs.size(), -1);
  inverseSqrtScale_.setOnes(n);
  currentDiagonal_.resize(n);
  for (Eigen::Index k = 0; k < n; ++k) {
    const int dof = freeDofs[size_t(k)];
    toFactor_[size_t(k)] = factorIndex[size_t(dof)];
    currentDiagonal_[k] = diagonal(dof, modulus);
    if (!sameMaterials) {
      const double factored = diagonal(dof, f.modulus);
      if (factored > 0 && currentDiagonal_[k] > 0)
        inverseSqrtScale_[k] = std::sqrt(factored / currentDiagonal_[k]);
    }
  }
  if (!sameMaterials) ++stats_.rescalings;
  std::vector<int> added;
  for (size_t k = 0; k < freeDofs.size(); ++k)
    if (toFactor_[k] < 0) added.push_back(freeDofs[k]);
  extendFactor(added);
}

void SystemPreconditioner::extendFactor(const std::vector<int>& added) {
  if (added.empty() || !factor_->valid) {
    extension_.clear();
    toExtension_.clear();
    extendedFactor_ = -1;
    return;
  }
  // Built again only for another factor or other coordinates; the positions in the free
  // vector are redone every time (pins the factor has may have been made since).
  if (extendedFactor_ != stats_.factorizations || extendedDofs_ != added) {
    extension_.clear();
    extendedFactor_ = stats_.factorizations;
    extendedDofs_ = added;
    const double cost =
        FactorExtension::buildCost(factor_->cholesky.factorNonZeros(), added.size());
    const bool coupled = added.size() <= kMostCoupledCoordinates && cost <= kMostCouplingCost;
    if (coupled ? extension_.build(factor_->cholesky, factor_->system, factor_->freeDofs, added)
                : extension_.buildUncoupled(factor_->system, added))
      ++stats_.extensions;
  }
  toExtension_.clear();
  if (extension_.empty()) return;
  toExtension_.assign(freeDofs_.size(), -1);
  size_t next = 0;
  for (size_t k = 0; k < freeDofs_.size(); ++k)
    if (toFactor_[k] < 0) toExtension_[k] = int(next++);
}

void SystemPreconditioner::apply(const Eigen::VectorXd& r, Eigen::VectorXd& z) const {
  if (!rotateThisSolve_ || !factor_ || !factor_->valid) {
    solve(r, z);
    return;
  }
  Eigen::VectorXd turned = r;
  rotate(turned, true);
  solve(turned, z);
  rotate(z, false);
}

void SystemPreconditioner::rotate(Eigen::VectorXd& x, bool transposed) const {
  const std::vector<Eigen::Matrix3d>& R = pointRotations_->rotations();
  for (const auto& [k, point] : rotatedPoints_) {
    const Eigen::Vector3d v = x.segment<3>(k);
    if (transposed) x.segment<3>(k) = R[point].transpose() * v;
    else x.segment<3>(k) = R[point] * v;
  }
}

void SystemPreconditioner::solve(const Eigen::VectorXd& r, Eigen::VectorXd& z) const {
  if (!factor_ || !factor_->valid) {
    z = r;
    return;
  }
  const bool empty = factor_->freeDofs.empty();  // factored with every point pinned
  if (inverseSqrtScale_.size() == 0) {
    if (empty) z = r;  // then r is empty too
    else factor_->cholesky.solve(r, z);
    return;
  }
  Eigen::VectorXd x = Eigen::VectorXd::Zero(Eigen::Index(factor_->freeDofs.size()));
  for (Eigen::Index k = 0; k < r.size(); ++k)
    if (const int j = toFactor_[size_t(k)]; j >= 0) x[j] = r[k] * inverseSqrtScale_[k];
  Eigen::VectorXd y;
  if (!empty) factor_->cholesky.solve(x, y);
  z.resize(r.size());
  if (!extension_.empty()) {
    Eigen::VectorXd rAdded(Eigen::Index(extendedDofs_.size())), xAdded;
    for (Eigen::Index k = 0; k < r.size(); ++k)
      if (const int i = toExtension_[size_t(k)]; i >= 0) rAdded[i] = r[k] * inverseSqrtScale_[k];
    extension_.finish(y, rAdded, xAdded);
    for (Eigen::Index k = 0; k < r.size(); ++k)
      if (const int i = toExtension_[size_t(k)]; i >= 0) z[k] = xAdded[i] * inverseSqrtScale_[k];
  }
  for (Eigen::Index k = 0; k < r.size(); ++k) {
    const int j = toFactor_[size_t(k)];
    if (j >= 0) z[k] = y[j] * inverseSqrtScale_[k];
    else if (extension_.empty()) z[k] = r[k] / currentDiagonal_[k];
  }
}

void SystemPreconditioner::reportIterations(int iterations) {
  if (!factor_) return;
  const int way = rotateThisSolve_ ? 1 : 0;
  // A probe (a solve the way not preferred) that took fewer iterations switches the way.
  if (rotationProbe_ && iterations < lastIterations_[1 - way])
    rotationPreferred_ = rotateThisSolve_;
  lastIterations_[way] = iterations;
  const bool fresh = inverseSqrtScale_.size() == 0;
  const bool drifting =
      freshIterations_ >= 0 && iterations > kDriftFactor * freshIterations_ + kDriftSlack;
  if (std::exchange(firstSolveBehind_, false) && !fresh && drifting) {
    // The new factor's first solve already misses the borrowed baseline: the solid's state, not
    // the factor's age, sets the iterations now (a collapse), and refactoring would not help.
    freshIterations_ = iterations;
  } else if (fresh) {
    if (freshIterations_ < 0 || iterations < freshIterations_) freshIterations_ = iterations;
    kindFreshIterations_[kindIndex(factor_->restStiffness)] = freshIterations_;
  } else if (drifting) {
    drifted_ = true;
  }
}

}  // namespace sculpt
