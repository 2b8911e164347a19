// Local subdivision (McDonnell–Qin Fig. 7d): selected cells are split linearly, one cell per
// corner, so detail can be added where it is needed. The split is linear (midpoints and
// centroids), so the solid's shape is unchanged until MacCracken–Joy refines it; neighbours get
// the new vertices inserted into their faces so the complex stays conforming.

#include <map>
#include <numeric>

#include "edit/edit_support.h"
#include "edit/topology_edit.h"

namespace sculpt {
namespace {

using Loop = std::vector<uint32_t>;

// The new vertices: a midpoint per split edge, a centroid per split face and per split cell.
struct SplitPoints {
  std::vector<int64_t> edgePoint, facePoint, cellPoint;  // -1 where not split
  uint32_t mid(const Topology& t, uint32_t a, uint32_t b) const {
    return static_cast<uint32_t>(edgePoint[static_cast<size_t>(t.findEdge(a, b))]);
  }
  bool splits(const Topology& t, uint32_t a, uint32_t b) const {
    return edgePoint[static_cast<size_t>(t.findEdge(a, b))] >= 0;
  }
};

// The quads a split face falls into, one per vertex, wound like `loop`.
void appendFaceQuads(const Topology& t, const SplitPoints& split, std::span<const uint32_t> loop,
                     uint32_t centre, std::vector<Loop>& out) {
  const size_t n = loop.size();
  for (size_t i = 0; i < n; ++i) {
    const uint32_t p = loop[(i + n - 1) % n], v = loop[i], q = loop[(i + 1) % n];
    out.push_back({v, split.mid(t, v, q), centre, split.mid(t, p, v)});
  }
}

// The loop with the midpoints of its split edges inserted.
Loop withMidpoints(const Topology& t, const SplitPoints& split, std::span<const uint32_t> loop) {
  Loop out;
  for (size_t i = 0; i < loop.size(); ++i) {
    const uint32_t a = loop[i], b = loop[(i + 1) % loop.size()];
    out.push_back(a);
    if (split.splits(t, a, b)) out.push_back(split.mid(t, a, b));
  }
  return out;
}

// The part of split cell c at its corner v: the quads of c's faces at v, and one inner face
// per edge of c at v through the edge midpoint, the centroids of the edge's two faces and the
// cell centroid.
std::vector<Loop> cornerCell(const CellComplex& mesh, const Topology& t, const SplitPoints& split,
                             uint32_t c, uint32_t v) {
  const auto faces = t.cellFaces.row(c);
  // Which face of c holds each directed edge (each appears once in a closed, oriented cell).
  std::map<std::pair<uint32_t, uint32_t>, uint32_t> faceOfDirectedEdge;
  for (uint32_t j = 0; j < faces.size(); ++j) {
    const auto loop = mesh.cellFace(c, j);
    for (size_t i = 0; i < loop.size(); ++i)
      faceOfDirectedEdge[{loop[i], loop[(i + 1) % loop.size()]}] = j;
  }
  const auto centreOf = [&](uint32_t j) {
    return static_cast<uint32_t>(split.facePoint[faces[j]]);
  };
  const uint32_t cellCentre = static_cast<uint32_t>(split.cellPoint[c]);
  std::vector<Loop> out;
  for (uint32_t j = 0; j < faces.size(); ++j) {
    const auto loop = mesh.cellFace(c, j);
    const size_t n = loop.size();
    for (size_t i = 0; i < n; ++i) {
      if (loop[i] != v) continue;
      const uint32_t p = loop[(i + n - 1) % n], q = loop[(i + 1) % n];
      const uint32_t mid = split.mid(t, v, q);
      out.push_back({v, mid, centreOf(j), split.mid(t, p, v)});
      // Face j runs v -> q; the other face at edge (v, q) runs q -> v. Wound to face q.
      out.push_back({mid, centreOf(faceOfDirectedEdge.at({q, v})), cellCentre, centreOf(j)});
    }
  }
  return out;
}

}  // namespace

TopologyEdit subdivideCells(const CellComplex& mesh, std::span<const uint32_t> cells) {
  const Topology t = edit::checkedTopology(mesh);
  const std::vector<uint32_t> selected = edit::cellSelection(mesh, cells);
  std::vector<uint8_t> isSelected(mesh.numCells(), 0);
  for (uint32_t c : selected) isSelected[c] = 1;

  // New vertices after the old ones: edge midpoints, face centroids, cell centroids, each in
  // increasing id.
  SplitPoints split{std::vector<int64_t>(t.numEdges(), -1), std::vector<int64_t>(t.numFaces(), -1),
                    std::vector<int64_t>(mesh.numCells(), -1)};
  std::vector<uint8_t> edgeSplit(t.numEdges(), 0), faceSplit(t.numFaces(), 0);
  for (uint32_t c : selected) {
    for (uint32_t e : t.cellEdges.row(c)) edgeSplit[e] = 1;
    for (uint32_t f : t.cellFaces.row(c)) faceSplit[f] = 1;
  }
  std::vector<Eigen::Vector3d> added;
  const auto addPoint = [&](const Eigen::Vector3d& p) {
    added.push_back(p);
    return static_cast<int64_t>(mesh.numVertices() + added.size() - 1);
  };
  const auto mean = [&](std::span<const uint32_t> vertices) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (uint32_t v : vertices) sum += edit::position(mesh, v);
    return Eigen::Vector3d(sum / static_cast<double>(vertices.size()));
  };
  for (uint32_t e = 0; e < t.numEdges(); ++e)
    if (edgeSplit[e]) split.edgePoint[e] = addPoint(mean(t.edgeVertices[e]));
  for (uint32_t f = 0; f < t.numFaces(); ++f)
    if (faceSplit[f]) split.facePoint[f] = addPoint(mean(t.faceVertices.row(f)));
  for (uint32_t c : selected) split.cellPoint[c] = addPoint(mean(t.cellVertices.row(c)));

  TopologyEdit edit;
  CellComplex& out = edit.mesh;
  out.positions.resize(mesh.numVertices() + static_cast<Eigen::Index>(added.size()), 3);
  out.positions.topRows(mesh.numVertices()) = mesh.positions;
  for (size_t i = 0; i < added.size(); ++i)
    out.positions.row(mesh.numVertices() + static_cast<Eigen::Index>(i)) = added[i].transpose();

  // Cells in order; a split cell's first corner part takes its place, the others go last.
  std::vector<std::vector<Loop>> appended;
  for (uint32_t c = 0; c < mesh.numCells(); ++c) {
    if (isSelected[c]) {
      const auto corners = t.cellVertices.row(c);
      out.addCell(cornerCell(mesh, t, split, c, corners[0]));
      for (size_t k = 1; k < corners.size(); ++k)
        appended.push_back(cornerCell(mesh, t, split, c, corners[k]));
      continue;
    }
    std::vector<Loop> loops;
    for (uint32_t j = 0; j < mesh.numFacesOfCell(c); ++j) {
      const uint32_t f = t.cellFaces.row(c)[j];
      if (faceSplit[f])
        appendFaceQuads(t, split, mesh.cellFace(c, j), static_cast<uint32_t>(split.facePoint[f]),
                        loops);
      else
        loops.push_back(withMidpoints(t, split, mesh.cellFace(c, j)));
    }
    out.addCell(loops);
  }
  for (const auto& cell : appended) out.addCell(cell);

  // A creased edge stays creased in both halves; corners stay.
  for (const auto& [a, b] : mesh.creases) {
    if (t.findEdge(a, b) >= 0 && split.splits(t, a, b)) {
      out.creases.push_back({a, split.mid(t, a, b)});
      out.creases.push_back({split.mid(t, a, b), b});
    } else {
      out.creases.push_back({a, b});
    }
  }
  out.corners = mesh.corners;
  edit.newVertexOfOld = edit::identityVertexMap(mesh.numVertices());
  return edit::finishEdit(std::move(edit),
                          selected.size() == 1 ? "Subdivide cell" : "Subdivide cells");
}

}  // namespace sculpt
