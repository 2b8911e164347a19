#pragma once
// Cholesky factor of S = a M~ + b D~ + c K~lin on the free coordinates, the preconditioner of
// the implicit and static solves (docs/fem.md, "The implicit solver's preconditioner").
//  - Refactored when a, b, c or the set of free coordinates change. The ordering and symbolic
//    analysis are kept while the pattern stays (sparse_cholesky.h).
//  - Material edits (painting, many per second) never refactor on the spot: the factor is
//    rescaled, P = D^1/2 S0 D^1/2 with D the ratio of the current diagonal of S to the factored
//    one, which is exact for a uniform change of the materials and close for a local one.
//  - After a pin edit, or once the rescaled factor costs CG noticeably more iterations than a
//    fresh one did, a new factor is made on a worker thread while the old one keeps serving, and
//    adopted a fixed number of solves later (waiting if it is late): same inputs, same bits.
//    The window instead adopts it at the first solve that finds it ready, and never waits.
//  - Each solve may turn the residual into the control points' frames first (r' = R^T r, then
//    z = R S0^-1 r', R a rotation per point from the elements' co-rotation frames): exact for a
//    solid turned rigidly, and close while it bends. Tried only where the stiffness makes up a
//    third of S's diagonal or more (turning the inertia with the points costs more than it
//    saves where the inertia dominates); there, now and then a solve is made the other way, and
//    the way that took fewer CG iterations is kept.
//  - Those factors use the cheap stand-in for the stiffness (linear_stiffness.h). Once the
//    materials and pins have stayed put for a while (from the start on), a time-stepping solve
//    also has a factor with the elements' own rest stiffness made on a worker, adopted as the
//    others are: denser and slower to make, it saves CG iterations in every step after it.
//    Materials that drift from it are followed by another factor of that kind, and one that
//    came behind the materials (painting went on) is replaced once they stay put.
//  - A factor keeps its stiffness with the materials it was assembled for; the next of its kind
//    assembles only the elements painted since (assembled_stiffness.h).

#include <cstdint>
#include <future>
#include <limits>
#include <memory>
#include <vector>

#include "fem/fem_model.h"
#include "sim/control_point_rotations.h"
#include "sim/factor_extension.h"
#include "sim/sparse_cholesky.h"

namespace sculpt {

struct AssembledStiffness;

struct PreconditionerStats {
  int factorizations = 0;      ///< numeric factorisations
  int backgroundFactorizations = 0;  ///< of these, made on the worker thread
  int rescalings = 0;          ///< material edits absorbed by rescaling the factor
  int restStiffnessFactorizations = 0;  ///< of these, with the elements' own rest stiffness
  int rotatedSolves = 0;       ///< solves made in the control points' rotated frames
  int extensions = 0;          ///< factors extended to coordinates released from a pin
  int givenUp = 0;             ///< rest-stiffness factors given up on the worker at a pin edit
  bool restStiffness = false;  ///< the factor in use has the elements' own rest stiffness
  double lastFactorMs = 0;     ///< wall time of the last factorisation, assembly included
  long long factorNonZeros = 0;
};

class SystemPreconditioner {
 public:
  explicit SystemPreconditioner(SparseCholesky::Method method = SparseCholesky::defaultMethod());
  ~SystemPreconditioner();
  SystemPreconditioner(const SystemPreconditioner&) = delete;
  SystemPreconditioner& operator=(const SystemPreconditioner&) = delete;

  /// Makes the preconditioner usable for S at the current materials, on the free coordinates
  /// `freeDofs` (increasing). Returns false when S cannot be factored even with a small diagonal
  /// shift (then apply() is the identity).
  bool update(const FemModel& model, double massScale, double dampingScale, double stiffnessScale,
              const std::vector<int>& freeDofs);
  /// Before the first update(): starts the first factor's stand-in stiffness, and the ordering
  /// and symbolic analysis of S for `freeDofs`, on a worker thread, so that they overlap what
  /// the step computes before it needs the factor (the mass matrices at their first use take
  /// as long). update() takes them if the materials (and, for the analysis, the free
  /// coordinates) have not changed since.
  void prepareFirstFactor(const FemModel& model, const std::vector<int>& freeDofs);
  /// A new factor for the model's current materials and the last update()'s scales and free
  /// coordinates, of the kind in use (stand-in or rest stiffness), made now (a factor pending on
  /// the worker is dropped). Nothing before the first update().
  void refactor(const FemModel& model);
  /// z ~ S^-1 r on the free coordinates given to the last update().
  void apply(const Eigen::VectorXd& r, Eigen::VectorXd& z) const;
  /// The CG iterations the solve after the last update() took: the measure of the rescaled
  /// factor's drift.
  void reportIterations(int iterations);
  const PreconditionerStats& stats() const { return stats_; }
  /// True (the default): factors made on the worker are adopted a fixed number of solves after
  /// their start, waiting for them if they are late, so that the same inputs give the same bits.
  /// False: adopted at the first solve that finds them ready, never waited for (the window).
  void setReproducible(bool reproducible) { reproducible_ = reproducible; }

  /// One factor and what it was made for, and what making one needs (copied from the model).
  struct Factor;
  struct Request;
  /// A factor being made on a worker thread, and when its turn comes.
  class WorkerFactor;

 private:
  std::unique_ptr<Factor> makeFactor(const FemModel& model, double a, double b, double c,
                                     const std::vector<int>& freeDofs);
  // What a factor of the kind asked for needs, starting from the last stiffness of that kind.
  Request requestOfKind(const FemModel& model, double a, double b, double c,
                        const std::vector<int>& freeDofs, bool restStiffness) const;
  void adopt(std::unique_ptr<Factor> factor);
  // Counts the solves at the model's current materials (a change starts the count again, as a
  // pin edit does: giveUpRestStiffness).
  void countQuietSolves(const FemModel& model);
  // Starts the rest-stiffness factor on a worker when the time has come; adopts one whose
  // time has come if it still fits the scales and the free coordinates.
  void upgradeToRestStiffness(const FemModel& model, const std::vector<int>& freeDofs);
  // A pin edit: the quiet count starts again, and a rest-stiffness factor being made for the
  // old pins is given up at once.
  void giveUpRestStiffness();
  // Whether this solve turns the residual into the control points' frames (and their
  // rotations, when it does).
  void chooseRotation(const FemModel& model);
  // z = D^-1/2 S0^-1 D^-1/2 r, without the rotations.
  void solve(const Eigen::VectorXd& r, Eigen::VectorXd& z) const;
  // x_p = R_p^T x_p (or R_p x_p) at every point whose three coordinates are free.
  void rotate(Eigen::VectorXd& x, bool transposed) const;
  // A factor made and adopted on the spot.
  void factorNow(const FemModel& model, double a, double b, double c,
                 const std::vector<int>& freeDofs);
  void rescale(const FemModel& model, const std::vector<int>& freeDofs);
  // Serves the free coordinates the factor lacks (`added`, increasing: points released from a
  // pin since it was made) exactly through its Schur complement where that costs little, and
  // by a factor of their own block otherwise (factor_extension.h); by their diagonal if that
  // fails. Nothing to do when `added` and the factor are those of the last call.
  void extendFactor(const std::vector<int>& added);
  void startBackground(const FemModel& model, double a, double b, double c,
                       const std::vector<int>& freeDofs);
  // Adopts a factor from the worker, unless it is of no use any more.
  void adoptFromWorker(std::unique_ptr<Factor> factor, const std::vector<int>& freeDofs);

  SparseCholesky::Method method_;
  bool reproducible_ = true;
  std::unique_ptr<Factor> factor_;
  // The last stiffness assembled of each kind (stand-in, rest), kept for the next factor.
  std::shared_ptr<const AssembledStiffness> assembled_[2];
  // The materials of the last update() or refactor().
  uint64_t materialVersion_ = 0;
  // Applying the factor to the current free coordinates: position in the factor's numbering
  // (-1: not in it, served by the diagonal), and D^-1/2 (empty: no rescaling).
  std::vector<int> toFactor_;
  Eigen::VectorXd inverseSqrtScale_, currentDiagonal_;
  std::vector<int> freeDofs_;
  uint64_t appliedMaterialVersion_ = ~uint64_t(0);
  bool mapped_ = false;  // the free set differs from the factor's
  // The free coordinates the factor lacks, served through its Schur complement, and each free
  // coordinate's position among them (-1: not one of them); the factor (its number among the
  // factorisations) and the coordinates the extension was, or was not, made for.
  FactorExtension extension_;
  std::vector<int> toExtension_;
  int extendedFactor_ = -1;
  std::vector<int> extendedDofs_;
  // Drift: the fewest iterations an unrescaled solve took since the last factorisation, and of
  // each kind (stand-in, rest) the last such count, for a factor adopted behind the materials.
  int freshIterations_ = -1;
  int kindFreshIterations_[2] = {-1, -1};
  bool firstSolveBehind_ = false;  // the next solve is the first of a factor adopted behind
  bool drifted_ = false;
  // After pin edits (the stand-in) or drift (the kind in use), and the rest-stiffness upgrade.
  std::unique_ptr<WorkerFactor> pending_, upgrade_;
  // Given up and told to stop, not yet finished: destroying one would wait for it.
  std::vector<std::unique_ptr<WorkerFactor>> abandoned_;
  uint64_t quietMaterialVersion_ = ~uint64_t(0);
  int quietSolves_ = kQuietSolves;  // the start counts as quiet
  int solves_ = 0;
  // The rotated solves: the points' rotations, the free-vector position of each point whose
  // three coordinates are free, the way this solve goes and the way preferred, and the
  // iterations each way took last.
  std::unique_ptr<ControlPointRotations> pointRotations_;
  const FemModel* rotationsModel_ = nullptr;
  std::vector<std::pair<Eigen::Index, uint32_t>> rotatedPoints_;
  bool rotateThisSolve_ = false, rotationPreferred_ = true, rotationProbe_ = false;
  int lastIterations_[2] = {std::numeric_limits<int>::max(), std::numeric_limits<int>::max()};
  int solvesSinceRotationProbe_ = 0;

  struct FirstFactor {
    uint64_t materialVersion = 0;
    SparseMatrix stiffness;
    Eigen::VectorXd modulus;
    std::unique_ptr<Factor> analysed;  // ordered and analysed, not yet factored
  };
  std::future<FirstFactor> firstFactor_;  // prepareFirstFactor's work
  PreconditionerStats stats_;
  static constexpr double kDriftFactor = 1.5;
  static constexpr int kDriftSlack = 4;
  // A factor started on the worker is adopted this many solves later.
  static constexpr int kDeterministicDelay = 8;
  // The rest-stiffness factor is started after this many solves without a material or pin edit.
  static constexpr int kQuietSolves = 30;
  // Extending the factor through the Schur complement: at most this many coordinates, and
  // this many multiply-adds for its solves (the bunny's top quarter released, 360 coordinates
  // and a factor of 1,233: 2.6e8, 15-21 ms); beyond, the extension is uncoupled.
  static constexpr size_t kMostCoupledCoordinates = 1500;
  static constexpr double kMostCouplingCost = 4e8;
  // Every this many solves, one goes the way not preferred.
  static constexpr int kRotationProbeEvery = 16;
};

}  // namespace sculpt
