#pragma once
// An assembled stand-in for the stiffness, used to precondition the matrix-free solves: the
// exact rest stiffness of every trilinear and pyramid element, and for each tricubic element the
// trilinear hexahedron on its cell's 8 corner nodes (spectrally close: both discretise the same
// elasticity on the same lattice). Reduced to the control points as (A x I3)^T K (A x I3).

#include "fem/fem_model.h"
#include "fem/mass_matrix.h"

namespace sculpt {

/// 3N by 3N (control point i, coordinate c at row 3i + c), rest geometry, current materials.
SparseMatrix reducedLinearStiffness(const FemModel& model);

/// The scalar matrix S acting on each coordinate: S x I3 in the interleaved numbering.
SparseMatrix kroneckerIdentity3(const SparseMatrix& scalar);

}  // namespace sculpt
