#pragma once
// The elements' own rest stiffness reduced to the control points: what the implicit solver's
// preconditioner factors once the materials and pins stay put (docs/fem.md, "The implicit
// solver's preconditioner").

#include <atomic>
#include <span>

#include "fem/fem_mesh.h"
#include "fem/mass_matrix.h"

namespace sculpt {

/// The elements' own rest stiffness reduced to the control points, A^T K A: each tricubic
/// element with its B-spline shape functions at its 4^3 Gauss points (what the elastic kernel's
/// Hessian product gives at rotation I), each trilinear or pyramid one at its own Gauss points.
/// It couples each control point with 7^3 others inside a regular lattice at K = 1 where the
/// stand-in couples 5^3, so its factor is denser and slower to make; preconditioned with it, CG
/// takes fewer iterations.
/// Once `stop` (when given) is set, returns an empty matrix soon. Elements with skip[e] are left
/// out (none when skip is empty): the share of the others, on the same pattern as theirs in
/// the whole matrix.
SparseMatrix reducedRestStiffness(const FemMesh& mesh, std::span<const LameParameters> lame,
                                  const SparseMatrix& A, const std::atomic<bool>* stop = nullptr,
                                  std::span<const uint8_t> skip = {});

}  // namespace sculpt
