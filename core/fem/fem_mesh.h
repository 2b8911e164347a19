#pragma once
// The finite elements of a subdivision solid at its simulation level (paper section 3.4): one
// element per level-K cell, chosen by regularity, with the rest-state data of every Gauss point.
//
// Node numbering: the level-K vertices ("lattice nodes"), then one virtual centre node per
// irregular cell. Every node is a fixed linear combination of the control points, so
// `nodeStencils` (= A with the centre rows appended) maps control points to all nodes and the
// virtual nodes add no unknowns.

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "fem/material.h"
#include "mesh/cell_complex.h"
#include "mesh/topology.h"
#include "subdiv/stencil_table.h"

namespace sculpt {

/// Frozen values (reports, files and the renderer's colours).
enum class ElementType : uint8_t {
  Tricubic = 0,   ///< regular cell: uniform tricubic B-spline on its 4x4x4 block, 4x4x4 Gauss
  Trilinear = 1,  ///< extraordinary cell: 8-node hexahedron, 2x2x2 Gauss
  Pyramid = 2,    ///< one face of an irregular cell joined to its virtual centre: a degenerate
                  ///< trilinear hexahedron (top face collapsed), conical 2x2x2 rule
};
const char* elementTypeName(ElementType type);

struct ElementCounts {
  uint32_t tricubic = 0, trilinear = 0, pyramid = 0;
  uint32_t total() const { return tricubic + trilinear + pyramid; }
};

inline constexpr int kTricubicNodes = 64;
inline constexpr int kTricubicGaussPoints = 64;
inline constexpr int kLinearNodes = 8;
inline constexpr int kLinearGaussPoints = 8;

using LinearShapeGradient = Eigen::Matrix<double, kLinearNodes, 3>;

struct FemMesh {
  StencilTable nodeStencils;     ///< #nodes by #control points
  uint32_t numLatticeNodes = 0;  ///< rows before the virtual centre nodes
  Points restNodes;              ///< nodeStencils applied to the rest control points
  /// #virtual centre nodes by numLatticeNodes: each centre is the mean of its cell's vertices
  /// (nodeStencils' last rows are these rows composed with the lattice's stencils).
  StencilTable centreStencils;

  // Tricubic elements come first in the element numbering, then the linear ones (trilinear
  // hexahedra and pyramids in cell order).
  std::vector<ElementType> elementType;  ///< per element
  std::vector<uint32_t> elementCell;     ///< level-K cell of each element

  /// Block node ids, index a*16 + b*4 + g with a along u (see regularControlBlock).
  std::vector<std::array<uint32_t, kTricubicNodes>> tricubicNodes;
  /// Per tricubic element and Gauss point (q = i*16 + j*4 + k): rest (dX/dxi)^-1.
  std::vector<Eigen::Matrix3d> tricubicInverseJacobian;
  std::vector<Eigen::Matrix3d> tricubicCentreInverseJacobian;  ///< per element, at (1/2)^3

  /// Trilinear reference order (VTK hexahedron); a pyramid repeats its apex in slots 4-7.
  std::vector<std::array<uint32_t, kLinearNodes>> linearNodes;
  /// Per linear element and Gauss point: rest-space shape function gradients dN/dX.
  std::vector<LinearShapeGradient> linearShapeGradient;
  std::vector<LinearShapeGradient> linearCentreShapeGradient;  ///< per element, at (1/2)^3

  // Per Gauss point of every element (tricubic ones first, 64 each, then 8 per linear one).
  std::vector<double> gaussVolume;               ///< Gauss weight times det J (m^3)
  std::vector<Eigen::Vector3d> gaussRestPosition;
  std::vector<Material> gaussMaterial;
  std::vector<LameParameters> gaussLame;

  uint32_t numNodes() const { return nodeStencils.numRows(); }
  uint32_t numControlPoints() const { return nodeStencils.numColumns(); }
  uint32_t numElements() const { return static_cast<uint32_t>(elementType.size()); }
  uint32_t numTricubic() const { return static_cast<uint32_t>(tricubicNodes.size()); }
  uint32_t numLinear() const { return static_cast<uint32_t>(linearNodes.size()); }
  uint32_t numGaussPoints() const { return static_cast<uint32_t>(gaussVolume.size()); }
  uint32_t gaussBegin(uint32_t element) const;
  uint32_t gaussCount(uint32_t element) const;
  /// The element's nodes: its 64 tricubic block nodes, or its 8 linear ones.
  std::span<const uint32_t> elementNodes(uint32_t element) const {
    if (element < numTricubic()) return tricubicNodes[element];
    return linearNodes[element - numTricubic()];
  }
  ElementCounts counts() const;
  double restVolume() const;
};

struct FemMeshOptions {
  bool allowTricubic = true;  ///< false: every hexahedron is trilinear (the --trilinear mode)
  Material material;          ///< initial uniform material
};

/// Builds the elements of `cells` (a level of a subdivision, with its topology) whose vertices
/// are `stencils` applied to the control points (`cells.positions` must equal that product at
/// rest). Returns nullopt and a sentence in *error when an element is inverted or degenerate at
/// rest, or when a face of a non-hexahedral cell has more than four vertices.
std::optional<FemMesh> buildFemMesh(const CellComplex& cells, const Topology& topology,
                                    const StencilTable& stencils, const FemMeshOptions& options,
                                    std::string* error);

}  // namespace sculpt
