#pragma once
// An assembled stand-in for the stiffness, used to precondition the matrix-free solves: the
// exact rest stiffness of every trilinear and pyramid element, and for each tricubic element the
// trilinear hexahedron on its cell's 8 corner nodes (spectrally close: both discretise the same
// elasticity on the same lattice), integrated at points near the cell centre, where it is closest
// to the smoother B-spline element. Reduced to the control points as (A x I3)^T K (A x I3),
// computed on 3x3 node blocks.

#include <array>
#include <cstdint>
#include <span>

#include "fem/fem_model.h"
#include "fem/mass_matrix.h"

namespace sculpt {

/// 3N by 3N (control point i, coordinate c at row 3i + c), rest geometry, current materials.
SparseMatrix reducedLinearStiffness(const FemModel& model);
/// The same for the Gauss-point materials `lame` (one per Gauss point of `mesh`), with A the
/// control-to-node stencil matrix: usable on a copy of the materials away from the model.
/// Elements with skip[e] are left out (none when skip is empty).
SparseMatrix reducedLinearStiffness(const FemMesh& mesh, std::span<const LameParameters> lame,
                                    const SparseMatrix& A, std::span<const uint8_t> skip = {});

/// The 8 nodes of element e's stand-in: a trilinear or pyramid element's own, a tricubic
/// element's cell corners (block [1,2]^3 of its 4^3 nodes), in trilinear order.
std::array<uint32_t, 8> elementCorners(const FemMesh& mesh, uint32_t e);

/// Per control point, A^T v with v_n the sum, over the stand-in elements with corner node n, of
/// their mean P-wave modulus lambda + 2 mu: how strongly the materials around the point weigh in
/// the stand-in's diagonal. Its ratio between two material states rescales a factor.
Eigen::VectorXd controlPointModulus(const FemMesh& mesh, std::span<const LameParameters> lame,
                                    const SparseMatrix& A);

}  // namespace sculpt
