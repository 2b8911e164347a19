#pragma once
// Per-frame deformation gradients: one per cell (at its centre), then one per node as the
// cell-to-node weighted average (gradient_weights.h).

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "embed/gradient_weights.h"
#include "mesh/volume_mesh.h"

namespace sculpt {

/// Rest-state operator giving each cell's gradient at its centre from its deformed nodes:
/// F_c = sum_a x_a g_a^T, with g_a the gradient of node a's shape function in rest space
/// (a tetrahedron's rows of V^-1; a hexahedron's trilinear shape gradients at xi = 1/2).
struct CellGradientOperator {
  std::vector<Eigen::Vector3d> shapeGradients;  ///< indexed like mesh.cells.values
};

CellGradientOperator cellGradientOperator(const VolumeMesh& rest);

/// F_c for every cell from deformed node positions (#nodes by 3). Parallel over cells.
void computeCellGradients(const VolumeMesh& rest, const CellGradientOperator& op,
                          const Points& deformedNodes, std::vector<Eigen::Matrix3d>& cellGradients);

/// F_i = sum_k w'_k F_k for every node. Parallel over nodes.
void computeNodeGradients(const CompressedRows<CellWeight>& weights,
                          const std::vector<Eigen::Matrix3d>& cellGradients,
                          std::vector<Eigen::Matrix3d>& nodeGradients);

/// The two steps above folded into one linear map from node positions to node gradients:
/// F_i = sum_j x_j G_ij^T with G_ij = sum_k w'_ik g_kj over the cells k around node i. It touches
/// each neighbour node once instead of each adjacent cell's gradient (a tet lattice node has 24
/// cells but 15 neighbours), and needs no per-cell storage per frame.
struct NodeGradientStencil {
  std::vector<uint32_t> offsets{0};  ///< #nodes+1: node i owns terms offsets[i] .. offsets[i+1]-1
  std::vector<uint32_t> nodes;       ///< per term: the neighbour j
  std::vector<double> g;             ///< per term: G_ij, 3 values (structure of arrays: the
                                     ///< per-frame loop streams these 28 bytes per term)
  uint32_t numNodes() const { return static_cast<uint32_t>(offsets.size() - 1); }
};

NodeGradientStencil nodeGradientStencil(const VolumeMesh& rest, const CellGradientOperator& op,
                                        const CompressedRows<CellWeight>& weights);

/// F_i for every node through the stencil. Parallel over nodes.
void applyNodeGradientStencil(const NodeGradientStencil& stencil, const Points& deformedNodes,
                              std::vector<Eigen::Matrix3d>& nodeGradients);

}  // namespace sculpt
