#pragma once
// What the stand-in and the elements' own rest stiffness share: a node matrix kept as 3x3
// blocks row by row, its reduction to the control points, and a linear element's rest stiffness.

#include <Eigen/Core>
#include <cstdint>
#include <span>
#include <vector>

#include "fem/fem_mesh.h"
#include "fem/mass_matrix.h"

namespace sculpt {

/// A symmetric node matrix as 3x3 blocks: row n couples node n's coordinates with node
/// column[k]'s through block[k], for k in [begin[n], begin[n + 1]).
struct NodeBlockRows {
  std::vector<uint32_t> begin{0};
  std::vector<uint32_t> column;
  std::vector<Eigen::Matrix3d> block;
  uint32_t numNodes() const { return uint32_t(begin.size() - 1); }
};

/// S = (A x I3)^T K (A x I3), 3N by 3N (control point i, coordinate c at row 3i + c).
SparseMatrix reduceNodeBlocks(const NodeBlockRows& K, const SparseMatrix& A);

/// A trilinear or pyramid element's rest stiffness from its own Gauss points: 24 x 24, node a's
/// coordinate c at row 3a + c.
Eigen::Matrix<double, 24, 24> linearElementStiffness(const FemMesh& mesh,
                                                     std::span<const LameParameters> lame,
                                                     uint32_t e);

}  // namespace sculpt
