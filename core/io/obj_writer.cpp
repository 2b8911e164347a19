#include "io/obj_writer.h"

#include <vector>

#include "io/atomic_file.h"
#include "io/number_text.h"

namespace sculpt {

std::string boundaryObj(const CellComplex& complex, const Topology& topology,
                        BoundarySurfaceCounts* counts) {
  // Number the vertices the boundary uses, in increasing original order, from 1.
  constexpr uint32_t kUnused = 0;
  std::vector<uint32_t> objIndex(complex.numVertices(), kUnused);
  uint32_t numFaces = 0;
  for (uint32_t f = 0; f < topology.numFaces(); ++f) {
    if (!topology.faceIsBoundary[f]) continue;
    ++numFaces;
    for (uint32_t v : topology.faceVertices.row(f)) objIndex[v] = 1;
  }
  uint32_t numVertices = 0;
  for (uint32_t& index : objIndex) {
    if (index != kUnused) index = ++numVertices;
  }

  std::string out = "# sculpt boundary surface: ";
  appendNumber(out, numVertices);
  out += " vertices, ";
  appendNumber(out, numFaces);
  out += " faces\n";
  for (uint32_t v = 0; v < complex.numVertices(); ++v) {
    if (objIndex[v] == kUnused) continue;
    out += 'v';
    for (Eigen::Index k = 0; k < 3; ++k) {
      out += ' ';
      appendNumber(out, complex.positions(v, k));
    }
    out += '\n';
  }
  // A boundary face has one cell, faceCells[f][0], and the stored loop is outward for it.
  for (uint32_t f = 0; f < topology.numFaces(); ++f) {
    if (!topology.faceIsBoundary[f]) continue;
    out += 'f';
    for (uint32_t v : topology.faceVertices.row(f)) {
      out += ' ';
      appendNumber(out, objIndex[v]);
    }
    out += '\n';
  }
  if (counts != nullptr) *counts = {numVertices, numFaces};
  return out;
}

BoundarySurfaceCounts writeBoundaryObj(const CellComplex& complex, const Topology& topology,
                                       const std::filesystem::path& path) {
  BoundarySurfaceCounts counts;
  writeFileAtomically(path, boundaryObj(complex, topology, &counts));
  return counts;
}

}  // namespace sculpt
