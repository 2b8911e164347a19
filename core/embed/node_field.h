#pragma once
// A field given per cell of a VolumeMesh (one value per level-K cell: an element's painted
// material, its strain energy density) carried to the nodes, so that the cell interpolant
// sum_a beta_a v_a that the deformer evaluates at each embedded vertex shows it smoothly
// instead of as one flat patch per cell.
//
// Node i's value is the lumped L2 projection of the piecewise-constant field,
//   v_i = sum_c w_ci v_c / sum_c w_ci,   w_ci = integral over cell c of N_i dV (rest shape),
// N_i being node i's shape function in cell c. w_ci is node i's share of the cell's volume:
// V_c / 8 for a parallelepiped, V_c / 4 for a tetrahedron. So a node takes the volume-weighted
// mean of its incident cells, a node of a single cell takes that cell's value, and a constant
// field stays constant exactly.
//
// Values are averaged as they are, not as logarithms: the colour map is linear in the value
// (shaders/phong_surface.frag, app/sculpt/colour_bar.cpp), so a node between a 3e6 Pa and a
// 3e8 Pa cell gets the colour halfway along the map, as a value halfway between them should.
// Averaging the logarithms would pull the stripe's border toward the low end of a linear map.

#include <cstdint>
#include <span>
#include <vector>

#include "mesh/volume_mesh.h"
#include "util/compressed_rows.h"

namespace sculpt {

struct NodeFieldWeight {
  uint32_t cell = 0;
  double weight = 0.0;  ///< w_ci over sum_c w_ci: a node's weights sum to 1
};

/// Per node of `mesh`: its cells with their normalised weights (from the rest shape; once per
/// mesh, O(cells)). A node in no cell has an empty row (its value is 0).
CompressedRows<NodeFieldWeight> nodeFieldWeights(const VolumeMesh& mesh);

/// Per node, the weighted mean of `cellValues` (one per cell); O(cells). Throws
/// std::invalid_argument when a weight names a cell beyond `cellValues`.
void nodeFieldFromCells(const CompressedRows<NodeFieldWeight>& weights,
                        std::span<const float> cellValues, std::vector<float>& nodeValues);

}  // namespace sculpt
