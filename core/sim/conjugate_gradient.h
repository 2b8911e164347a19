#pragma once
// Preconditioned conjugate gradients on flat vectors, with a warm start.

#include <Eigen/Core>
#include <functional>

namespace sculpt {

struct CgResult {
  int iterations = 0;
  double relativeResidual = 0;  ///< |b - A x| / |b| at exit (0 when b = 0)
  bool converged = false;
  bool indefinite = false;      ///< stopped at a direction with p^T A p <= 0: A is not definite
};

using LinearOperator = std::function<void(const Eigen::VectorXd& in, Eigen::VectorXd& out)>;

/// Solves A x = b for symmetric positive (semi)definite A, starting from x (scaled to the least
/// energy along it, which may make it zero). Stops when |r| <= tolerance |b| or after
/// maxIterations; stops early (not converged) on a breakdown (p^T A p <= 0, reported as
/// `indefinite`, or non-finite values), leaving the last good x.
CgResult conjugateGradient(const LinearOperator& A, const LinearOperator& preconditioner,
                           const Eigen::VectorXd& b, Eigen::VectorXd& x, double tolerance,
                           int maxIterations);

}  // namespace sculpt
