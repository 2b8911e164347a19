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
//    adopted a fixed number of solves later (waiting if it is late): same inputs, same bits, in
//    the window as in the CLI.

#include <cstdint>
#include <future>
#include <memory>
#include <vector>

#include "fem/fem_model.h"
#include "sim/sparse_cholesky.h"

namespace sculpt {

struct PreconditionerStats {
  int factorizations = 0;      ///< numeric factorisations
  int backgroundFactorizations = 0;  ///< of these, made on the worker thread
  int rescalings = 0;          ///< material edits absorbed by rescaling the factor
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
  /// coordinates, made now (a factor pending on the worker is dropped). Nothing before the
  /// first update().
  void refactor(const FemModel& model);
  /// z ~ S^-1 r on the free coordinates given to the last update().
  void apply(const Eigen::VectorXd& r, Eigen::VectorXd& z) const;
  /// The CG iterations the solve after the last update() took: the measure of the rescaled
  /// factor's drift.
  void reportIterations(int iterations);
  const PreconditionerStats& stats() const { return stats_; }

  /// One factor and what it was made for, and what making one needs (copied from the model).
  struct Factor;
  struct Request;

 private:
  std::unique_ptr<Factor> makeFactor(const FemModel& model, double a, double b, double c,
                                     const std::vector<int>& freeDofs);
  void adopt(std::unique_ptr<Factor> factor);
  // A factor made and adopted on the spot.
  void factorNow(const FemModel& model, double a, double b, double c,
                 const std::vector<int>& freeDofs);
  void rescale(const FemModel& model, const std::vector<int>& freeDofs);
  void startBackground(const FemModel& model, double a, double b, double c,
                       const std::vector<int>& freeDofs);
  void adoptBackground();

  SparseCholesky::Method method_;
  std::unique_ptr<Factor> factor_;
  // Applying the factor to the current free coordinates: position in the factor's numbering
  // (-1: not in it, served by the diagonal), and D^-1/2 (empty: no rescaling).
  std::vector<int> toFactor_;
  Eigen::VectorXd inverseSqrtScale_, currentDiagonal_;
  std::vector<int> freeDofs_;
  uint64_t appliedMaterialVersion_ = ~uint64_t(0);
  bool mapped_ = false;  // the free set differs from the factor's
  // Drift: the fewest iterations a solve took since the last factorisation.
  int freshIterations_ = -1;
  bool drifted_ = false;
  std::future<std::unique_ptr<Factor>> pending_;
  struct FirstFactor {
    uint64_t materialVersion = 0;
    SparseMatrix stiffness;
    Eigen::VectorXd modulus;
    std::unique_ptr<Factor> analysed;  // ordered and analysed, not yet factored
  };
  std::future<FirstFactor> firstFactor_;  // prepareFirstFactor's work
  int solvesSinceStart_ = 0;
  PreconditionerStats stats_;
  static constexpr double kDriftFactor = 1.5;
  static constexpr int kDriftSlack = 4;
  // A factor started on the worker is adopted this many solves later.
  static constexpr int kDeterministicDelay = 8;
};

}  // namespace sculpt
