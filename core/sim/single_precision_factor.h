#pragma once
// A single-precision copy of CHOLMOD's supernodal factor L L^T = P S P^T, and its solve. The
// preconditioner's solves read all of L twice per CG iteration: in single precision they move
// half the bytes and use twice the vector lanes, and the dense blocks of each supernode are
// solved in place instead of through CHOLMOD's per-call workspace (docs/BENCHMARKS.md, "The
// preconditioner's solve in single precision"). The preconditioner need only be close to
// S^-1: CG's own vectors and products stay in double precision.

#include <Eigen/Core>
#include <cholmod.h>
#include <vector>

namespace sculpt {

class SinglePrecisionFactor {
 public:
  /// Copies a supernodal LL^T factor of real doubles; anything else, or a factor whose entries
  /// span more than single precision's range, leaves this empty.
  void copy(const cholmod_factor& L);
  bool empty() const { return n_ == 0; }
  /// z = (L L^T)^-1 r in the original ordering, computed in single precision. False (z then
  /// undefined) when a value left single precision's range: the caller solves in double.
  /// Not reentrant: it works in the object's own vectors.
  bool solve(const Eigen::VectorXd& r, Eigen::VectorXd& z) const;
  /// Z = (L L^T)^-1 R for many right-hand sides at once, likewise (the columns share one
  /// scaling). Reentrant.
  bool solve(const Eigen::MatrixXd& R, Eigen::MatrixXd& Z) const;

 private:
  template <typename Work>
  void solveInPlace(Work& y, Work& below) const;
  template <typename Dense, typename Work>
  bool solveScaled(const Dense& r, Dense& z, Work& y, Work& below) const;

  Eigen::Index n_ = 0;
  int exponent_ = 0;              // values_ hold L / 2^exponent_
  std::vector<int> permutation_;  // row k of P S P^T is row permutation_[k] of S
  std::vector<int> firstColumn_;  // per supernode, and one past the last
  std::vector<int> rowsBegin_;    // per supernode: its rows in rows_, and one past the last
  std::vector<long> valuesBegin_;  // per supernode: its column-major block in values_
  std::vector<int> rows_;
  std::vector<float> values_;
  mutable Eigen::VectorXf work_, below_;
};

}  // namespace sculpt
