#pragma once
// The baseline of Houdini's Point Deform ("attribute transfer"): each embedded point moves by the
// normalised metaball-weighted average of the displacements of the nodes within radius r,
// kernel (1 - d^2/r^2)^2. First-order accurate; kept for comparison with Phong Deformation.

#include <cstdint>

#include "mesh/cell_complex.h"
#include "util/compressed_rows.h"

namespace sculpt {

struct NodeWeight {
  uint32_t node = 0;
  double weight = 0.0;
};

/// Row p: the nodes within `radius` of point p with normalised kernel weights. A point with no
/// node within the radius takes its nearest node with weight 1 (never left unmoved).
/// Throws std::invalid_argument for a non-positive or non-finite radius or an empty node set.
CompressedRows<NodeWeight> attributeTransferWeights(const Points& restNodes, const Points& points,
                                                    double radius);

/// The default radius: 1.5 times the mean length of the cells' distinct edges.
double defaultAttributeRadius(double meanEdgeLength);

}  // namespace sculpt
