#include "io/obj_writer.h"

#include "io/atomic_file.h"
#include "io/number_text.h"
#include "mesh/boundary_surface.h"

namespace sculpt {

std::string boundaryObj(const CellComplex& complex, const Topology& topology,
                        BoundarySurfaceCounts* counts) {
  const BoundarySurface boundary = boundarySurface(complex, topology);
  const SurfaceMesh& surface = boundary.surface;
  std::string out = "# sculpt boundary surface: ";
  appendNumber(out, surface.numVertices());
  out += " vertices, ";
  appendNumber(out, surface.numFaces());
  out += " faces\n";
  for (uint32_t v = 0; v < surface.numVertices(); ++v) {
    out += 'v';
    for (Eigen::Index k = 0; k < 3; ++k) {
      out += ' ';
      appendNumber(out, surface.positions(v, k));
    }
    out += '\n';
  }
  // OBJ numbers vertices from 1.
  for (uint32_t f = 0; f < surface.numFaces(); ++f) {
    out += 'f';
    for (const SurfaceCorner& corner : surface.faces.row(f)) {
      out += ' ';
      appendNumber(out, corner.position + 1);
    }
    out += '\n';
  }
  if (counts != nullptr) *counts = {surface.numVertices(), surface.numFaces()};
  return out;
}

BoundarySurfaceCounts writeBoundaryObj(const CellComplex& complex, const Topology& topology,
                                       const std::filesystem::path& path) {
  BoundarySurfaceCounts counts;
  writeFileAtomically(path, boundaryObj(complex, topology, &counts));
  return counts;
}

}  // namespace sculpt
