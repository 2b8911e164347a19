#pragma once
// MacCracken–Joy refinement of a cell complex (docs/design/mj-subdivision.md): interior rules from
// old positions, Catmull–Clark rules on the boundary surface, crease and corner tags inherited.
//
// Child vertex numbering of one step (level k -> k+1), with V, E, F, C the level-k counts:
//   [0, V)            vertex point of level-k vertex v
//   [V, V+E)          edge point of edge e
//   [V+E, V+E+F)      face point of face f
//   [V+E+F, V+E+F+C)  cell point of cell c
// Child cells are emitted cell by cell and, within a cell, corner by corner in the order of
// Topology::cellVertices.

#include <cstdint>
#include <optional>
#include <vector>

#include "mesh/cell_complex.h"
#include "mesh/topology.h"
#include "subdiv/stencil_table.h"
#include "util/progress.h"

namespace sculpt {

/// One refinement step: the child complex (tags set, positions sized but not computed: apply
/// the stencils to the parent positions) and the stencils
/// S (#child vertices by #parent vertices) with child positions = S parent positions.
struct RefinementStep {
  CellComplex child;
  StencilTable stencils;
};

/// Refines one level. `parent` must be the topology of a valid complex.
RefinementStep refineOnce(const Topology& parent);

/// Levels 0..K of a refinement: complexes (with positions), topologies, per-level stencils and
/// the composed stencil table A from control points to level-K vertices.
struct Subdivision {
  std::vector<CellComplex> levels;       ///< levels[0] is the control mesh
  std::vector<Topology> topologies;      ///< topology of each level
  StencilChain chain;                    ///< S_1 .. S_K
  StencilTable stencils;                 ///< A = S_K ... S_1 (#level-K vertices by #control)

  int numLevels() const { return static_cast<int>(levels.size()) - 1; }
  const CellComplex& finest() const { return levels.back(); }
  const Topology& finestTopology() const { return topologies.back(); }
};

/// Refines `control` K times. Reports progress per level; returns nullopt when cancelled.
/// The control mesh must be valid (see validate()).
std::optional<Subdivision> subdivide(const CellComplex& control, int levels,
                                     ProgressReporter* progress = nullptr);

}  // namespace sculpt
