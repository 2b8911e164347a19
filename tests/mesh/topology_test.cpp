// Topology of a cell complex: unique faces and edges, adjacency in cyclic order, boundary
// classification, vertex incidences, findEdge and outward loops.

#include "mesh/topology.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <vector>

#include "support/mesh_builders.h"

namespace sculpt {
namespace {

using test::gridVertex;

std::set<uint32_t> asSet(std::span<const uint32_t> s) { return {s.begin(), s.end()}; }

/// Newell normal of a loop.
Eigen::Vector3d newell(const CellComplex& m, const std::vector<uint32_t>& loop) {
  Eigen::Vector3d n = Eigen::Vector3d::Zero();
  for (size_t i = 0; i < loop.size(); ++i)
    n += test::pos(m, loop[i]).cross(test::pos(m, loop[(i + 1) % loop.size()]));
  return n;
}

Eigen::Vector3d centroid(const CellComplex& m, const std::set<uint32_t>& vs) {
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (uint32_t v : vs) c += test::pos(m, v);
  return c / static_cast<double>(vs.size());
}

/// Structural invariants that hold for any valid complex.
void checkInvariants(const CellComplex& m, const Topology& t) {
  ASSERT_TRUE(t.problems.empty());
  ASSERT_EQ(t.numVertices, m.numVertices());
  ASSERT_EQ(t.numCells(), m.numCells());
  ASSERT_EQ(t.faceEdges.numRows(), t.numFaces());
  ASSERT_EQ(t.faceCells.size(), t.numFaces());
  ASSERT_EQ(t.edgeFaces.numRows(), t.numEdges());
  ASSERT_EQ(t.edgeCells.numRows(), t.numEdges());
  ASSERT_EQ(t.cellFaceReversed.size(), t.cellFaces.values.size());
  // Faces: edges follow the loop, the stored loop is outward for faceCells[f][0].
  for (uint32_t f = 0; f < t.numFaces(); ++f) {
    const auto fv = t.faceVertices.row(f);
    const auto fe = t.faceEdges.row(f);
    ASSERT_EQ(fv.size(), fe.size());
    for (size_t i = 0; i < fv.size(); ++i) {
      const auto [a, b] = t.edgeVertices[fe[i]];
      const uint32_t x = fv[i], y = fv[(i + 1) % fv.size()];
      EXPECT_EQ(std::min(x, y), a);
      EXPECT_EQ(std::max(x, y), b);
    }
    ASSERT_NE(t.faceCells[f][0], kNoCell);
    EXPECT_EQ(t.faceIsBoundary[f] != 0, t.faceCells[f][1] == kNoCell);
    const auto c0 = static_cast<uint32_t>(t.faceCells[f][0]);
    const std::vector<uint32_t> loop(fv.begin(), fv.end());
    const Eigen::Vector3d out = centroid(m, asSet(fv)) - centroid(m, test::cellVertexSet(m, c0));
    EXPECT_GT(newell(m, loop).dot(out), 0.0) << "face " << f << " stored loop not outward";
  }
  // Edges: a < b, faces in cyclic order, cell i between faces i and i+1.
  for (uint32_t e = 0; e < t.numEdges(); ++e) {
    const auto [a, b] = t.edgeVertices[e];
    EXPECT_LT(a, b);
    EXPECT_EQ(t.findEdge(a, b), e);
    EXPECT_EQ(t.findEdge(b, a), e);
    const auto faces = t.edgeFaces.row(e);
    const auto cells = t.edgeCells.row(e);
    const bool boundary = t.edgeIsBoundary[e] != 0;
    ASSERT_EQ(faces.size(), boundary ? cells.size() + 1 : cells.size()) << "edge " << e;
    for (size_t i = 0; i < cells.size(); ++i) {
      const uint32_t f0 = faces[i], f1 = faces[(i + 1) % faces.size()];
      for (uint32_t f : {f0, f1}) {
        const auto fc = t.faceCells[f];
        EXPECT_TRUE(fc[0] == static_cast<int32_t>(cells[i]) ||
                    fc[1] == static_cast<int32_t>(cells[i]))
            << "edge " << e << ": cell " << cells[i] << " is not between faces " << f0 << ", "
            << f1;
      }
    }
    for (uint32_t f : faces) {
      const auto fv = t.faceVertices.row(f);
      EXPECT_TRUE(std::count(fv.begin(), fv.end(), a) && std::count(fv.begin(), fv.end(), b));
    }
    if (boundary) {
      EXPECT_TRUE(t.faceIsBoundary[faces.front()]) << "edge " << e;
      EXPECT_TRUE(t.faceIsBoundary[faces.back()]) << "edge " << e;
      for (size_t i = 1; i + 1 < faces.size(); ++i) EXPECT_FALSE(t.faceIsBoundary[faces[i]]);
    } else {
      for (uint32_t f : faces) EXPECT_FALSE(t.faceIsBoundary[f]);
    }
  }
  // Cells: their faces, vertices and edges agree with the raw loops.
  for (uint32_t c = 0; c < t.numCells(); ++c) {
    EXPECT_EQ(asSet(t.cellVertices.row(c)), test::cellVertexSet(m, c));
    EXPECT_EQ(t.cellVertices.row(c).size(), test::cellVertexSet(m, c).size());
    std::set<std::pair<uint32_t, uint32_t>> edges;
    for (uint32_t e : t.cellEdges.row(c))
      edges.insert({t.edgeVertices[e][0], t.edgeVertices[e][1]});
    EXPECT_EQ(edges, test::cellEdgeSet(m, c));
    ASSERT_EQ(t.cellFaces.rowSize(c), m.numFacesOfCell(c));
    for (uint32_t j = 0; j < m.numFacesOfCell(c); ++j) {
      const uint32_t f = t.cellFaces.row(c)[j];
      const auto raw = m.cellFace(c, j);
      EXPECT_EQ(asSet(t.faceVertices.row(f)), asSet(raw));
      const auto fc = t.faceCells[f];
      EXPECT_TRUE(fc[0] == static_cast<int32_t>(c) || fc[1] == static_cast<int32_t>(c));
      const bool reversed = t.cellFaceReversed[t.cellFaces.offsets[c] + j] != 0;
      EXPECT_EQ(reversed, fc[0] != static_cast<int32_t>(c));
      // outwardLoop is the raw loop up to rotation.
      const auto out = t.outwardLoop(c, j);
      ASSERT_EQ(out.size(), raw.size());
      const auto start = std::find(out.begin(), out.end(), raw[0]) - out.begin();
      for (size_t i = 0; i < raw.size(); ++i)
        EXPECT_EQ(out[(static_cast<size_t>(start) + i) % out.size()], raw[i]);
      const Eigen::Vector3d dir = centroid(m, asSet(raw)) - centroid(m, test::cellVertexSet(m, c));
      EXPECT_GT(newell(m, out).dot(dir), 0.0) << "cell " << c << " face " << j;
    }
  }
  // Vertex incidences match a brute-force count.
  for (uint32_t v = 0; v < t.numVertices; ++v) {
    std::set<uint32_t> edges, faces, cells;
    for (uint32_t e = 0; e < t.numEdges(); ++e)
      if (t.edgeVertices[e][0] == v || t.edgeVertices[e][1] == v) edges.insert(e);
    for (uint32_t f = 0; f < t.numFaces(); ++f)
      if (asSet(t.faceVertices.row(f)).count(v)) faces.insert(f);
    for (uint32_t c = 0; c < t.numCells(); ++c)
      if (test::cellVertexSet(m, c).count(v)) cells.insert(c);
    EXPECT_EQ(asSet(t.vertexEdges.row(v)), edges) << "vertex " << v;
    EXPECT_EQ(asSet(t.vertexFaces.row(v)), faces) << "vertex " << v;
    EXPECT_EQ(asSet(t.vertexCells.row(v)), cells) << "vertex " << v;
    EXPECT_EQ(t.vertexEdges.rowSize(v), edges.size());
    EXPECT_EQ(t.vertexFaces.rowSize(v), faces.size());
    EXPECT_EQ(t.vertexCells.rowSize(v), cells.size());
    bool boundary = false;
    for (uint32_t f : faces) boundary = boundary || t.faceIsBoundary[f];
    EXPECT_EQ(t.vertexIsBoundary[v] != 0, boundary) << "vertex " << v;
  }
  for (uint32_t e = 0; e < t.numEdges(); ++e) {
    bool boundary = false;
    for (uint32_t f : t.edgeFaces.row(e)) boundary = boundary || t.faceIsBoundary[f];
    EXPECT_EQ(t.edgeIsBoundary[e] != 0, boundary);
  }
}

TEST(Topology, TwoByOneByOneBlock) {
  const CellComplex m = test::hexGrid(2, 1, 1);
  const Topology t = buildTopology(m);
  checkInvariants(m, t);
  EXPECT_EQ(t.numVertices, 12u);
  EXPECT_EQ(t.numFaces(), 11u);
  EXPECT_EQ(t.numEdges(), 20u);
  EXPECT_EQ(t.numCells(), 2u);
  auto g = [](int i, int j, int k) { return gridVertex(2, 1, i, j, k); };
  // The shared face x = 1 is the only interior face.
  const int64_t shared = test::findFace(t, {g(1, 0, 0), g(1, 1, 0), g(1, 1, 1), g(1, 0, 1)});
  ASSERT_GE(shared, 0);
  uint32_t boundaryFaces = 0;
  for (uint32_t f = 0; f < t.numFaces(); ++f) boundaryFaces += t.faceIsBoundary[f];
  EXPECT_EQ(boundaryFaces, 10u);
  EXPECT_FALSE(t.faceIsBoundary[static_cast<size_t>(shared)]);
  const auto fc = t.faceCells[static_cast<size_t>(shared)];
  EXPECT_EQ(std::set<int32_t>({fc[0], fc[1]}), std::set<int32_t>({0, 1}));
  // Every edge and vertex lies on the box surface.
  for (uint32_t e = 0; e < t.numEdges(); ++e) EXPECT_TRUE(t.edgeIsBoundary[e]);
  for (uint32_t v = 0; v < t.numVertices; ++v) EXPECT_TRUE(t.vertexIsBoundary[v]);
  // Edge (1,0,0)-(1,1,0): on the shared face; faces bottom-0, shared, bottom-1 in order.
  const int64_t e = t.findEdge(g(1, 0, 0), g(1, 1, 0));
  ASSERT_GE(e, 0);
  const auto faces = t.edgeFaces.row(static_cast<uint32_t>(e));
  ASSERT_EQ(faces.size(), 3u);
  EXPECT_EQ(faces[1], static_cast<uint32_t>(shared));
  EXPECT_EQ(t.edgeCells.rowSize(static_cast<uint32_t>(e)), 2u);
  // Box-corner edge: 2 faces, 1 cell.
  const int64_t corner = t.findEdge(g(0, 0, 0), g(1, 0, 0));
  ASSERT_GE(corner, 0);
  EXPECT_EQ(t.edgeFaces.rowSize(static_cast<uint32_t>(corner)), 2u);
  EXPECT_EQ(t.edgeCells.row(static_cast<uint32_t>(corner))[0], 0u);
  // Non-edges.
  EXPECT_EQ(t.findEdge(g(0, 0, 0), g(1, 1, 0)), -1);
  EXPECT_EQ(t.findEdge(g(0, 0, 0), g(2, 0, 0)), -1);
  EXPECT_EQ(t.findEdge(g(0, 0, 0), g(0, 0, 0)), -1);
  // Vertex incidences: a box corner and a vertex on the shared face.
  EXPECT_EQ(t.vertexEdges.rowSize(g(0, 0, 0)), 3u);
  EXPECT_EQ(t.vertexFaces.rowSize(g(0, 0, 0)), 3u);
  EXPECT_EQ(t.vertexCells.rowSize(g(0, 0, 0)), 1u);
  EXPECT_EQ(t.vertexEdges.rowSize(g(1, 0, 0)), 4u);
  EXPECT_EQ(t.vertexFaces.rowSize(g(1, 0, 0)), 5u);
  EXPECT_EQ(t.vertexCells.rowSize(g(1, 0, 0)), 2u);
  EXPECT_TRUE(t.isHexahedron(0));
  EXPECT_TRUE(t.isHexahedron(1));
  EXPECT_EQ(t.cellVertices.rowSize(0), 8u);
  EXPECT_EQ(t.cellEdges.rowSize(0), 12u);
  EXPECT_EQ(t.cellFaces.rowSize(0), 6u);
  // The shared face is reversed in exactly one of its cells.
  int reversed = 0;
  for (uint32_t c = 0; c < 2; ++c)
    for (uint32_t j = 0; j < 6; ++j)
      if (t.cellFaces.row(c)[j] == static_cast<uint32_t>(shared))
        reversed += t.cellFaceReversed[t.cellFaces.offsets[c] + j];
  EXPECT_EQ(reversed, 1);
}

TEST(Topology, InteriorEdgeCyclicOrder) {
  // 2x2x2 block: the edge (1,1,0)-(1,1,1) is interior, with 4 faces and 4 cells in cyclic order.
  const CellComplex m = test::hexGrid(2, 2, 2);
  const Topology t = buildTopology(m);
  checkInvariants(m, t);
  EXPECT_EQ(t.numFaces(), 36u);
  EXPECT_EQ(t.numEdges(), 54u);
  auto g = [](int i, int j, int k) { return gridVertex(2, 2, i, j, k); };
  const int64_t e = t.findEdge(g(1, 1, 0), g(1, 1, 1));
  ASSERT_GE(e, 0);
  const auto eu = static_cast<uint32_t>(e);
  EXPECT_FALSE(t.edgeIsBoundary[eu]);
  EXPECT_TRUE(t.vertexIsBoundary[g(1, 1, 0)]);
  EXPECT_FALSE(t.vertexIsBoundary[g(1, 1, 1)]);
  const auto faces = t.edgeFaces.row(eu);
  const auto cells = t.edgeCells.row(eu);
  ASSERT_EQ(faces.size(), 4u);
  ASSERT_EQ(cells.size(), 4u);
  EXPECT_EQ(asSet(cells), std::set<uint32_t>({0, 1, 2, 3}));
  // Consecutive cells around the edge share a face: opposite cells (0 and 3, 1 and 2) are not
  // neighbours in the cycle.
  for (size_t i = 0; i < 4; ++i) {
    const uint32_t a = cells[i], b = cells[(i + 1) % 4];
    EXPECT_NE(a ^ b, 3u) << "cells " << a << " and " << b << " are diagonal";
  }
  // Interior vertex: 6 edges, 12 faces, 8 cells.
  EXPECT_EQ(t.vertexEdges.rowSize(g(1, 1, 1)), 6u);
  EXPECT_EQ(t.vertexFaces.rowSize(g(1, 1, 1)), 12u);
  EXPECT_EQ(t.vertexCells.rowSize(g(1, 1, 1)), 8u);
}

TEST(Topology, Tetrahedron) {
  const CellComplex m = test::regularTet();
  const Topology t = buildTopology(m);
  checkInvariants(m, t);
  EXPECT_EQ(t.numFaces(), 4u);
  EXPECT_EQ(t.numEdges(), 6u);
  for (uint32_t e = 0; e < 6; ++e) {
    EXPECT_EQ(t.edgeFaces.rowSize(e), 2u);
    EXPECT_EQ(t.edgeCells.rowSize(e), 1u);
    EXPECT_TRUE(t.edgeIsBoundary[e]);
  }
  for (uint32_t v = 0; v < 4; ++v) {
    EXPECT_EQ(t.vertexEdges.rowSize(v), 3u);
    EXPECT_EQ(t.vertexFaces.rowSize(v), 3u);
    EXPECT_EQ(t.vertexCells.rowSize(v), 1u);
  }
  EXPECT_FALSE(t.isHexahedron(0));
  for (uint32_t a = 0; a < 4; ++a)
    for (uint32_t b = 0; b < 4; ++b) EXPECT_EQ(t.findEdge(a, b) >= 0, a != b);
}

TEST(Topology, MixedShapesAndTags) {
  for (const CellComplex& m : {test::kuhnCube(), test::pyramidCube({0.5, 0.5, 0.75}),
                               test::prismCube(), test::octahedron(), test::mixedMesh()}) {
    const Topology t = buildTopology(m);
    checkInvariants(m, t);
  }
  // Kuhn cube: the diagonal is interior with 6 faces and cells.
  const CellComplex kuhn = test::kuhnCube();
  const Topology tk = buildTopology(kuhn);
  const int64_t d = tk.findEdge(0, 7);
  ASSERT_GE(d, 0);
  EXPECT_FALSE(tk.edgeIsBoundary[static_cast<size_t>(d)]);
  EXPECT_EQ(tk.edgeFaces.rowSize(static_cast<uint32_t>(d)), 6u);
  EXPECT_EQ(tk.edgeCells.rowSize(static_cast<uint32_t>(d)), 6u);
  EXPECT_EQ(tk.numEdges(), 19u);  // 12 cube edges + 6 face diagonals + 1 body diagonal
  EXPECT_EQ(tk.numFaces(), 18u);  // 12 boundary triangles + 6 interior
  // Tags: a crease on a box edge and a corner.
  CellComplex tagged = test::hexGrid(2, 1, 1);
  auto g = [](int i, int j, int k) { return gridVertex(2, 1, i, j, k); };
  tagged.creases = {{g(1, 0, 0), g(0, 0, 0)}};
  tagged.corners = {g(2, 1, 1)};
  const Topology tt = buildTopology(tagged);
  uint32_t creases = 0, corners = 0;
  for (uint8_t c : tt.edgeIsCrease) creases += c;
  for (uint8_t c : tt.vertexIsCorner) corners += c;
  EXPECT_EQ(creases, 1u);
  EXPECT_EQ(corners, 1u);
  EXPECT_TRUE(tt.edgeIsCrease[static_cast<size_t>(tt.findEdge(g(0, 0, 0), g(1, 0, 0)))]);
  EXPECT_TRUE(tt.vertexIsCorner[g(2, 1, 1)]);
}

}  // namespace
}  // namespace sculpt
