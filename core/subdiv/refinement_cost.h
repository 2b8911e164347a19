#pragma once
// What refining a control mesh K times will cost, estimated from the control topology alone so
// that work which cannot fit is refused with one sentence before anything is allocated.
//
// The counts follow exactly from the MJ rules (one vertex per vertex, edge, face and cell; one
// cell per corner; hexahedra from level 1 on). The memory is a model of what subdivide() keeps
// (every level's complex and topology, the per-level stencils S_k, and the composed table A,
// built beside the previous one), calibrated on hexahedral blocks and n-gon prisms. Its one
// non-linear term comes from wide elements: a face point depends on all the face's vertices and
// a cell point on all the cell's, and composing levels hands that whole support to every
// level-K point near them, so an element of k vertices costs about k^2 8^(K-2) entries of A.

#include <cstdint>
#include <string>

#include "mesh/topology.h"

namespace sculpt {

/// Most level-K cells any command builds (vertex ids are 32-bit, and far fewer fit anyway).
inline constexpr uint64_t kMaxRefinedCells = 50'000'000;

/// What is built on the level-K cells besides the refinement: bytes per level-K cell, and bytes
/// per entry of the composed stencil table A (an element keeps its nodes' stencils, so its data
/// grows with the control points it depends on: 64 for a tricubic element, all of a wide
/// cell's near it). Fitted to the peak resident memory (`/usr/bin/time -f %M`) of
/// assets/block3.json and block10.json at levels 2 and 3 and of n-gon prisms (n = 300, 600).
struct LevelWork {
  double bytesPerCell = 0.0;
  double bytesPerStencilEntry = 0.0;
};
/// The refinement alone (subdivide, bench subdivide).
inline constexpr LevelWork kRefinementOnly{0.0, 0.0};
/// The finite elements of a FemModel, as info builds them.
inline constexpr LevelWork kFiniteElements{10'500.0, 43.0};
/// A FemModel and a Simulator with the implicit solver's matrices (simulate, static, scenes).
inline constexpr LevelWork kSimulation{28'500.0, 380.0};

struct RefinementCost {
  int levels = 0;
  uint64_t cells = 0;           ///< level-K cells
  uint64_t vertices = 0;        ///< level-K vertices
  uint64_t stencilEntries = 0;  ///< entries of A (level-K vertices by control points)
  uint64_t bytes = 0;           ///< peak memory of the refinement and the work on it
  /// The control cell whose vertices and faces cost the most stencil entries through the
  /// quadratic term above, and what those entries take (0 when no element is wide).
  uint32_t widestCell = 0;
  uint32_t widestCellFaces = 0, widestCellVertices = 0;
  uint64_t widestCellBytes = 0;
};

/// Estimates refining the complex of `control` `levels` times and doing `work` on the result.
/// Linear in the size of the control topology; saturates instead of overflowing.
RefinementCost estimateRefinementCost(const Topology& control, int levels,
                                      LevelWork work = kRefinementOnly);

/// Empty when the cost fits; otherwise one sentence naming `name`, the level and what it would
/// need, e.g. "level 4 of block10.json needs about 5.4 GB (4,096,000 cells); this machine has
/// 2.1 GB available; use fewer levels". A count above kMaxRefinedCells is refused whatever the
/// memory.
std::string refinementRefusal(const RefinementCost& cost, const std::string& name,
                              uint64_t availableBytes);

/// estimateRefinementCost and refinementRefusal against availableMemoryBytes(): the check every
/// command and the scene builder make before they refine.
std::string refinementRefusal(const Topology& control, int levels, const std::string& name,
                              LevelWork work = kRefinementOnly);

}  // namespace sculpt
