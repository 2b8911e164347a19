#pragma once
// The co-rotated 8-node trilinear element (pyramids are the same element with a collapsed top),
// its 8 Gauss points processed together so that the compiler vectorises across them.

#include <Eigen/Core>

#include "fem/barrier_stress.h"

namespace sculpt {

/// Rest data of one linear element, packed for the kernel.
struct LinearPacked {
  const double* shapeGradient;  ///< [a*3 + c][q]: dN_a/dX_c at Gauss point q, 8*3*8 values
  const double* volumeLambda;   ///< [q]
  const double* volumeMu;       ///< [q]
};

/// u: 8 node values, coordinate-major: coordinate c of node a at u[c*8 + a]. Same contract as
/// tricubicElementKernel; the barrier's record and state hold [9][8] values (A[r][c] at the 8
/// Gauss points).
double linearElementKernel(const double* u, const LinearPacked& element, const Eigen::Matrix3d& R,
                           bool withRestTerm, bool withEnergy, double* gradient,
                           BarrierArgs* barrier = nullptr);

}  // namespace sculpt
