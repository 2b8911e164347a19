#pragma once
// Cell-to-node weights that turn per-cell deformation gradients into per-node gradients
// (Phong Deformation, section 4): a modified Shepard average whose weights reproduce linear
// functions where the node has neighbours on all sides (second-order accurate node gradients),
// regularised by eps where it has not (boundary nodes, slivers).

#include <cstdint>

#include "mesh/volume_mesh.h"
#include "util/compressed_rows.h"

namespace sculpt {

struct CellWeight {
  uint32_t cell = 0;
  double weight = 0.0;
};

/// Row i: the cells around node i with normalised weights w'_k (summing to 1). For node i with
/// adjacent cells k, r_k = centroid_k - X_i, rhat_k = r_k / |r_k|; (A + eps I) lambda = b with
/// A = sum rhat rhat^T, b = -sum rhat; w_k = 1 + lambda . rhat_k; w'_k = (w_k/|r_k|) / sum_j
/// (w_j/|r_j|). A node in no cell gets an empty row. Throws std::invalid_argument for eps < 0 or
/// non-finite eps.
CompressedRows<CellWeight> cellToNodeWeights(const VolumeMesh& mesh, double eps = 1.0);

}  // namespace sculpt
