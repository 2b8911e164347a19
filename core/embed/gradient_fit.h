#pragma once
// Node gradients from a quadratic least-squares fit of the deformed nodes around each node.
//
// Node i's ring R_k holds the nodes within k steps of it, a step joining two nodes of a common
// cell. Over R_k \ {i} the deformed positions are fitted by
//   x_j - x_i ~ F d_j + Q(d_j),   d_j = X_j - X_i,
// with Q a quadratic form (9 unknowns per component), least squares with equal weights. F is the
// node gradient. It is a fixed linear map of the node positions, so it is stored as the same
// node-to-node stencil as the paper's averaging (deformation_gradients.h). A quadratic model makes
// F second-order accurate wherever the ring determines it, on the boundary too, where the
// averaging of one-sided cell gradients is only first-order (docs/phong.md, "Surface cells").
//
// The ring starts at k = 1 and grows until it has at least kMinFitNodes nodes and the normal
// matrix of the fit (on d_j scaled to the ring's radius) has a condition number of at most
// kGoodFitCondition, up to k = kMaxFitRing. Where no ring is that good, the best-conditioned one
// is taken if its condition is at most kMaxFitCondition; a node where none qualifies keeps its row
// of `fallback`. Measured on TetGen meshes (docs/phong.md): rings of condition between 1e3 and 1e4
// give noisy gradients at a curved boundary, and the next ring is better conditioned there.

#include <cstdint>

#include "embed/deformation_gradients.h"
#include "mesh/volume_mesh.h"

namespace sculpt {

inline constexpr uint32_t kMinFitNodes = 10;      ///< the node and 9 others: one per unknown
inline constexpr double kGoodFitCondition = 1e3;  ///< of the 9 x 9 normal matrix: stop growing
inline constexpr double kMaxFitCondition = 1e4;   ///< the most a fit may have
inline constexpr uint32_t kMaxFitRing = 3;

struct GradientFitReport {
  uint32_t ringCounts[kMaxFitRing + 1] = {};  ///< nodes fitted over ring k (index 0 unused)
  uint32_t fallbacks = 0;                     ///< nodes that kept the fallback's row
};

NodeGradientStencil quadraticFitStencil(const VolumeMesh& rest, const NodeGradientStencil& fallback,
                                        GradientFitReport* report = nullptr);

}  // namespace sculpt
