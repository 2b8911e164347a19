#pragma once
// The boundary surface of a cell complex as a Wavefront OBJ: every boundary face as a polygon
// wound counter-clockwise seen from outside, over only the vertices the boundary uses.

#include <cstdint>
#include <filesystem>
#include <string>

#include "mesh/cell_complex.h"
#include "mesh/topology.h"

namespace sculpt {

/// Counts of what boundaryObj writes.
struct BoundarySurfaceCounts {
  uint32_t vertices = 0;
  uint32_t faces = 0;
};

/// The OBJ text. Vertices are the boundary vertices in increasing original index, numbered from
/// 1; faces follow the topology's face order. A header comment gives the counts.
std::string boundaryObj(const CellComplex& complex, const Topology& topology,
                        BoundarySurfaceCounts* counts = nullptr);

/// Writes boundaryObj(...) atomically. Throws FileError.
BoundarySurfaceCounts writeBoundaryObj(const CellComplex& complex, const Topology& topology,
                                       const std::filesystem::path& path);

}  // namespace sculpt
