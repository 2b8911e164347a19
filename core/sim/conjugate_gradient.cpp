#include "sim/conjugate_gradient.h"

#include <algorithm>
#include <cmath>

namespace sculpt {

namespace {

CgResult solve(const LinearOperator& A, const LinearOperator& preconditioner,
               const Eigen::VectorXd& b, Eigen::VectorXd& x, double tolerance, int maxIterations) {
  CgResult result;
  const double bNorm = b.norm();
  if (!std::isfinite(bNorm)) return result;
  if (bNorm == 0.0) {
    x.setZero();
    result.converged = true;
    return result;
  }
  if (x.size() != b.size() || !x.allFinite()) x.setZero(b.size());
  Eigen::VectorXd r, z(b.size()), p, Ap(b.size());
  // A product costs about an elastic pass: none for a zero start.
  if (x.isZero(0.0)) {
    r = b;
  } else {
    // The start scaled to the least energy 1/2 x^T A x - b^T x along it, with the product its
    // residual needs anyway: never further from the solution (in A's norm) than the start or
    // zero. A start that points away from the solution becomes zero.
    A(x, Ap);
    const double xAx = x.dot(Ap), scale = xAx > 0 ? std::max(0.0, b.dot(x) / xAx) : 0.0;
    if (!std::isfinite(scale)) {
      x.setZero();
      r = b;
    } else {
      x *= scale;
      r = b - scale * Ap;
    }
  }
  result.relativeResidual = r.norm() / bNorm;
  if (result.relativeResidual <= tolerance) {
    result.converged = true;
    return result;
  }
  preconditioner(r, z);
  p = z;
  double rz = r.dot(z);
  for (int it = 0; it < maxIterations; ++it) {
    A(p, Ap);
    const double pAp = p.dot(Ap);
    if (!(pAp > 0) || !std::isfinite(pAp)) {
      result.indefinite = std::isfinite(pAp);
      break;
    }
    const double alpha = rz / pAp;
    x += alpha * p;
    r -= alpha * Ap;
    result.iterations = it + 1;
    result.relativeResidual = r.norm() / bNorm;
    if (result.relativeResidual <= tolerance) {
      result.converged = true;
      break;
    }
    preconditioner(r, z);
    const double rzNext = r.dot(z);
    if (!std::isfinite(rzNext)) break;
    p = z + (rzNext / rz) * p;
    rz = rzNext;
  }
  return result;
}

}  // namespace

CgResult conjugateGradient(const LinearOperator& A, const LinearOperator& preconditioner,
                           const Eigen::VectorXd& b, Eigen::VectorXd& x, double tolerance,
                           int maxIterations) {
  // Solved for b / 2^k with 2^k near max |b|: |b|^2 cannot overflow (forces of 1e200 N), and a
  // power-of-two scale changes no bit of the iterates, so results are those of the plain solve.
  const double largest = b.size() ? b.cwiseAbs().maxCoeff() : 0.0;
  if (!std::isfinite(largest) || largest == 0.0)
    return solve(A, preconditioner, b, x, tolerance, maxIterations);
  int exponent = 0;
  std::frexp(largest, &exponent);
  if (x.size() == b.size()) x = std::ldexp(1.0, -exponent) * x;
  const CgResult result =
      solve(A, preconditioner, std::ldexp(1.0, -exponent) * b, x, tolerance, maxIterations);
  x *= std::ldexp(1.0, exponent);
  return result;
}

}  // namespace sculpt
