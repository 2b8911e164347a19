#include "mesh/boundary_surface.h"

namespace sculpt {

BoundarySurface boundarySurface(const CellComplex& complex, const Topology& topology) {
  // Number the vertices the boundary uses, in increasing complex order.
  constexpr uint32_t kUnused = SurfaceCorner::kNoIndex;
  std::vector<uint32_t> surfaceIndex(complex.numVertices(), kUnused);
  for (uint32_t f = 0; f < topology.numFaces(); ++f) {
    if (!topology.faceIsBoundary[f]) continue;
    for (uint32_t v : topology.faceVertices.row(f)) surfaceIndex[v] = 0;
  }
  BoundarySurface out;
  for (uint32_t v = 0; v < complex.numVertices(); ++v) {
    if (surfaceIndex[v] == kUnused) continue;
    surfaceIndex[v] = static_cast<uint32_t>(out.complexVertex.size());
    out.complexVertex.push_back(v);
  }
  out.surface.positions.resize(static_cast<Eigen::Index>(out.complexVertex.size()), 3);
  for (size_t i = 0; i < out.complexVertex.size(); ++i)
    out.surface.positions.row(static_cast<Eigen::Index>(i)) =
        complex.positions.row(out.complexVertex[i]);

  // A boundary face has one cell, faceCells[f][0], and the stored loop is outward for it.
  for (uint32_t f = 0; f < topology.numFaces(); ++f) {
    if (!topology.faceIsBoundary[f]) continue;
    for (uint32_t v : topology.faceVertices.row(f)) {
      SurfaceCorner corner;
      corner.position = surfaceIndex[v];
      out.surface.faces.values.push_back(corner);
    }
    out.surface.faces.closeRow();
  }

  // Sharp tags on the boundary (validation keeps them there; others are dropped).
  for (const auto& [a, b] : complex.creases) {
    if (a >= surfaceIndex.size() || b >= surfaceIndex.size()) continue;
    const int64_t e = topology.findEdge(a, b);
    if (e >= 0 && topology.edgeIsBoundary[static_cast<size_t>(e)])
      out.creases.push_back({surfaceIndex[a], surfaceIndex[b]});
  }
  for (uint32_t v : complex.corners)
    if (v < surfaceIndex.size() && surfaceIndex[v] != kUnused)
      out.corners.push_back(surfaceIndex[v]);
  return out;
}

}  // namespace sculpt
