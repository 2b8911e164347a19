#pragma once
// Consistent scalar mass and damping matrices (paper section 3.2.1): M = integral mu N^T N dV on
// the nodes, and their reduction to the control points M~ = A^T M A (eq. 18). The x, y and z
// blocks share one scalar matrix.

#include <Eigen/SparseCore>
#include <cstdint>
#include <span>
#include <vector>

#include "fem/fem_mesh.h"

namespace sculpt {

using SparseMatrix = Eigen::SparseMatrix<double>;  // column-major, symmetric use

enum class MassField { Density, Damping };

/// Node-level integral of `field` N^T N over every element (#nodes square; elements where the
/// field vanishes add no entries).
SparseMatrix assembleNodeMatrix(const FemMesh& mesh, MassField field);

/// A as a sparse matrix (#rows by #columns of the stencil table).
SparseMatrix stencilMatrix(const StencilTable& stencils);

/// A^T M A for the node matrix M of `field` (assembleNodeMatrix), with A the stencil matrix.
SparseMatrix reducedNodeMatrix(const FemMesh& mesh, const SparseMatrix& A, MassField field);

/// The Gauss-point weights of `field`: its value times the Gauss volume.
std::vector<double> fieldWeights(const FemMesh& mesh, MassField field);
/// A^T M A for the node matrix M of per-Gauss-point `weights` (a field times the Gauss volume),
/// over the elements marked in `included` only (every element when empty). Linear in the
/// weights: the change of weights on a few elements gives the change of the reduced matrix.
SparseMatrix reducedWeightedMatrix(const FemMesh& mesh, const SparseMatrix& A,
                                   std::span<const double> weights,
                                   std::span<const uint8_t> included = {});

}  // namespace sculpt
