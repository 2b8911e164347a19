#pragma once
// The matrix-free tricubic B-spline element (docs/design/local-frame-fem.md, "Making it fast"):
// parametric gradients at the 4x4x4 Gauss points by sum factorisation (three successive 4x4
// contractions), co-rotated linear stress, and the transposed contractions back onto the 64 nodes.
// Gauss points are processed four at a time (the k direction) so that the compiler can vectorise.

#include <Eigen/Core>
#include <cstdint>

#include "fem/barrier_stress.h"
#include "fem/material.h"

namespace sculpt {

/// Rest data of one tricubic element, packed for the kernel.
struct TricubicPacked {
  const double* inverseJacobian;  ///< [i*4 + j][row*3 + col][k]: (dX/dxi)^-1, 16*9*4 values
  int jacobianStride;             ///< 36; 0 when all i*4 + j share the first block (affine)
  const double* volumeLambda;     ///< [i*16 + j*4 + k]: Gauss volume times lambda
  const double* volumeMu;         ///< [i*16 + j*4 + k]: Gauss volume times mu
  const double* prefetch;         ///< data the next call will read (fetched into the cache)
  int prefetchCount;              ///< its length in doubles
  /// An affine element whose inverse Jacobian has one nonzero per column (a box aligned with
  /// the axes, in any order: the cells of a cage or block): for each column, the row of that
  /// entry. The kernel then scales instead of multiplying by the 3x3 matrix. Null otherwise.
  const int8_t* axisRows = nullptr;
};

/// True when an element's 64 inverse Jacobians (q = i*16 + j*4 + k) agree to rounding (1e-13 of
/// the first's largest entry): its rest map is affine, and one block of them is stored.
bool affineInverseJacobians(const Eigen::Matrix3d* inverseJacobian);
/// For an affine element's inverse Jacobian: the row of each column's one nonzero entry, when
/// every other entry is zero to rounding (1e-13 of the largest); false otherwise.
bool axisAlignedRows(const Eigen::Matrix3d& inverseJacobian, int8_t rows[3]);

/// One element's rest data as one block of doubles: its inverse Jacobians in the kernel's layout
/// [i*4 + j][row*3 + col][k] (a single [row*3 + col][k] block for an affine element, whose 64
/// inverse Jacobians agree), then 64 Gauss volume * lambda, then 64 Gauss volume * mu.
int tricubicRestSize(bool affine);
/// Writes the inverse-Jacobian part of the block from the 64 Gauss points' (dX/dxi)^-1
/// (q = i*16 + j*4 + k); an affine element stores the first.
void packTricubicInverseJacobians(const Eigen::Matrix3d* inverseJacobian, bool affine,
                                  double* block);
/// Writes the material part of the block from the 64 Gauss volumes and Lame parameters.
void packTricubicMaterial(const double* volume, const LameParameters* lame, bool affine,
                          double* block);
/// The kernel's view of a block, with the data to prefetch for the next call.
TricubicPacked tricubicPackedView(const double* block, bool affine, const double* prefetch,
                                  int prefetchCount, const int8_t* axisRows = nullptr);

/// u: 64 node values (displacements or a direction), coordinate-major: coordinate c of node
/// a*16+b*4+g at u[c*64 + a*16+b*4+g]. Writes the node gradient to `gradient` (same layout)
/// when non-null and returns the energy contribution when `withEnergy`. `withRestTerm` adds
/// sym(R) - I to the strain (gradient mode). `barrier` (null: none) adds the inversion barrier;
/// its record and state hold 16 blocks of [9][4] values (A[r][c] at the four Gauss points k).
double tricubicElementKernel(const double* u, const TricubicPacked& element,
                             const Eigen::Matrix3d& R, bool withRestTerm, bool withEnergy,
                             double* gradient, BarrierArgs* barrier = nullptr);

/// The element's rest stiffness, its Hessian at rotation I, into K (192 x 192, column-major,
/// rows and columns in u's layout): column c*64 + n is the kernel's Hessian product with the
/// unit vector of coordinate c of node n, found at half the cost of 192 such products.
void tricubicRestStiffness(const TricubicPacked& element, double* K);

}  // namespace sculpt
