#pragma once
// Small cell complexes for tests, built by hand (not through any library helper), plus
// independent geometric and combinatorial checks (signed volume, closedness, orientation) and
// lookups of MJ child vertices by the numbering of mj_refiner.h:
//   [vertex points | edge points | face points | cell points].

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <map>
#include <ostream>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "mesh/cell_complex.h"
#include "mesh/topology.h"
#include "subdiv/mj_refiner.h"
#include "subdiv/stencil_table.h"

namespace sculpt::test {

using Loops = std::vector<std::vector<uint32_t>>;

inline uint32_t u32(size_t n) { return static_cast<uint32_t>(n); }

/// Outward face loops of a hexahedron in VTK order (0-3 bottom counter-clockwise seen from
/// above, 4-7 the top above them).
inline Loops hexLoops(const std::array<uint32_t, 8>& v) {
  return {{v[0], v[3], v[2], v[1]}, {v[4], v[5], v[6], v[7]}, {v[0], v[1], v[5], v[4]},
          {v[1], v[2], v[6], v[5]}, {v[2], v[3], v[7], v[6]}, {v[3], v[0], v[4], v[7]}};
}
/// Tetrahedron (v1-v0, v2-v0, v3-v0 right-handed).
inline Loops tetLoops(const std::array<uint32_t, 4>& v) {
  return {{v[0], v[2], v[1]}, {v[0], v[1], v[3]}, {v[1], v[2], v[3]}, {v[2], v[0], v[3]}};
}
/// Prism: triangle (0,1,2) with outward normal (pointing away from 3,4,5), 3-5 above 0-2.
inline Loops prismLoops(const std::array<uint32_t, 6>& v) {
  return {{v[0], v[1], v[2]},
          {v[3], v[5], v[4]},
          {v[0], v[3], v[4], v[1]},
          {v[1], v[4], v[5], v[2]},
          {v[2], v[5], v[3], v[0]}};
}
/// Pyramid: base (0,1,2,3) counter-clockwise seen from the apex 4.
inline Loops pyramidLoops(const std::array<uint32_t, 5>& v) {
  return {{v[0], v[3], v[2], v[1]},
          {v[0], v[1], v[4]},
          {v[1], v[2], v[4]},
          {v[2], v[3], v[4]},
          {v[3], v[0], v[4]}};
}

inline CellComplex makeComplex(const std::vector<Eigen::Vector3d>& points,
                               const std::vector<Loops>& cells) {
  CellComplex m;
  m.positions.resize(static_cast<Eigen::Index>(points.size()), 3);
  for (size_t i = 0; i < points.size(); ++i)
    m.positions.row(static_cast<Eigen::Index>(i)) = points[i].transpose();
  for (const Loops& c : cells) m.addCell(c);
  return m;
}

inline Eigen::Vector3d pos(const CellComplex& m, uint32_t v) {
  return m.positions.row(static_cast<Eigen::Index>(v)).transpose();
}
inline Eigen::Vector3d pos(const Points& p, uint32_t v) {
  return p.row(static_cast<Eigen::Index>(v)).transpose();
}

/// Id of grid vertex (i, j, k) in an nx by ny by nz hex grid.
inline uint32_t gridVertex(int nx, int ny, int i, int j, int k) {
  return static_cast<uint32_t>(i + (nx + 1) * (j + (ny + 1) * k));
}

/// nx by ny by nz unit hexes (edge length h) on [0, nx h] x [0, ny h] x [0, nz h]. Vertex id
/// gridVertex(i, j, k); cell id i + nx (j + ny k).
inline CellComplex hexGrid(int nx, int ny, int nz, double h = 1.0) {
  std::vector<Eigen::Vector3d> points;
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i) points.emplace_back(i * h, j * h, k * h);
  std::vector<Loops> cells;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        auto g = [&](int a, int b, int c) { return gridVertex(nx, ny, i + a, j + b, k + c); };
        cells.push_back(hexLoops({g(0, 0, 0), g(1, 0, 0), g(1, 1, 0), g(0, 1, 0), g(0, 0, 1),
                                  g(1, 0, 1), g(1, 1, 1), g(0, 1, 1)}));
      }
  return makeComplex(points, cells);
}

inline CellComplex unitCube() { return hexGrid(1, 1, 1); }

/// Vertex id of (i, j, k) (taken modulo n) in the n^3 3-torus.
inline uint32_t torusVertex(int n, int i, int j, int k) {
  auto m = [n](int a) { return ((a % n) + n) % n; };
  return static_cast<uint32_t>(m(i) + n * (m(j) + n * m(k)));
}

/// The n by n by n periodic hex lattice (3-torus) with random positions in [-1, 1]^3. Cell id
/// i + n (j + n k) has corners (i..i+1, j..j+1, k..k+1) modulo n.
inline CellComplex periodicTorus(int n, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> uni(-1.0, 1.0);
  std::vector<Eigen::Vector3d> points(static_cast<size_t>(n * n * n));
  for (auto& p : points) p = Eigen::Vector3d(uni(rng), uni(rng), uni(rng));
  std::vector<Loops> cells;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        auto g = [&](int a, int b, int c) { return torusVertex(n, i + a, j + b, k + c); };
        cells.push_back(hexLoops({g(0, 0, 0), g(1, 0, 0), g(1, 1, 0), g(0, 1, 0), g(0, 0, 1),
                                  g(1, 0, 1), g(1, 1, 1), g(0, 1, 1)}));
      }
  return makeComplex(points, cells);
}

/// The 8 unit-cube corners with id x + 2y + 4z.
inline std::vector<Eigen::Vector3d> cubeCorners() {
  std::vector<Eigen::Vector3d> p;
  for (int id = 0; id < 8; ++id) p.emplace_back(id & 1, (id >> 1) & 1, (id >> 2) & 1);
  return p;
}

/// Signed volume of a closed cell by the divergence theorem (faces fanned from their vertex
/// average; exact for planar faces, a consistent value otherwise).
inline double signedVolume(const CellComplex& m, uint32_t c) {
  double vol = 0.0;
  for (uint32_t j = 0; j < m.numFacesOfCell(c); ++j) {
    auto loop = m.cellFace(c, j);
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    for (uint32_t v : loop) centre += pos(m, v);
    centre /= static_cast<double>(loop.size());
    for (size_t i = 0; i < loop.size(); ++i) {
      const Eigen::Vector3d a = pos(m, loop[i]);
      const Eigen::Vector3d b = pos(m, loop[(i + 1) % loop.size()]);
      vol += centre.dot(a.cross(b)) / 6.0;
    }
  }
  return vol;
}

/// Reverses every loop of cell c when its signed volume is negative (for builders).
inline Loops orient(const std::vector<Eigen::Vector3d>& points, Loops loops) {
  CellComplex probe = makeComplex(points, {loops});
  if (signedVolume(probe, 0) < 0)
    for (auto& l : loops) std::reverse(l.begin(), l.end());
  return loops;
}

/// Kuhn split of the unit cube into 6 tets along the diagonal (0,0,0)-(1,1,1): tets are the
/// monotone paths 0 -> e_a -> e_a + e_b -> 7. Corner ids x + 2y + 4z.
inline CellComplex kuhnCube() {
  const auto p = cubeCorners();
  std::vector<Loops> cells;
  std::array<int, 3> axes = {0, 1, 2};
  do {
    const uint32_t a = 1u << axes[0];
    const uint32_t b = a | (1u << axes[1]);
    cells.push_back(orient(p, tetLoops({0u, a, b, 7u})));
  } while (std::next_permutation(axes.begin(), axes.end()));
  return makeComplex(p, cells);
}

/// The unit cube split into 6 pyramids, one per cube face, with the common apex (id 8).
inline CellComplex pyramidCube(const Eigen::Vector3d& apex) {
  auto p = cubeCorners();
  p.push_back(apex);
  // Outward cube faces (corner ids x + 2y + 4z).
  const std::vector<std::array<uint32_t, 4>> faces = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                                      {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  std::vector<Loops> cells;
  for (const auto& f : faces) {
    Loops loops = {{f[0], f[1], f[2], f[3]}};
    for (int i = 0; i < 4; ++i) loops.push_back({f[(i + 1) % 4], f[i], 8u});
    cells.push_back(loops);
  }
  return makeComplex(p, cells);
}

/// The unit cube split by the plane x = y into two triangular prisms.
inline CellComplex prismCube() {
  const auto p = cubeCorners();
  // ids: (0,0,0)=0 (1,0,0)=1 (0,1,0)=2 (1,1,0)=3, +4 on top.
  std::vector<Loops> cells = {orient(p, prismLoops({0, 3, 1, 4, 7, 5})),
                              orient(p, prismLoops({0, 2, 3, 4, 6, 7}))};
  return makeComplex(p, cells);
}

/// The regular tetrahedron (1,1,1), (1,-1,-1), (-1,1,-1), (-1,-1,1) (ids 0..3).
inline CellComplex regularTet() {
  std::vector<Eigen::Vector3d> p = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
  return makeComplex(p, {orient(p, tetLoops({0, 1, 2, 3}))});
}

inline CellComplex singlePrism() {
  std::vector<Eigen::Vector3d> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0},
                                    {0, 0, 1}, {1, 0, 1}, {0, 1, 1}};
  return makeComplex(p, {orient(p, prismLoops({0, 1, 2, 3, 4, 5}))});
}

/// One prism over a regular n-gon of unit radius, z in [0, 1]: 2n vertices (0..n-1 below,
/// n..2n-1 above), two n-gon faces and n quads. A cell and faces this wide are what makes
/// stencils grow quadratically.
inline CellComplex ngonPrism(uint32_t n) {
  std::vector<Eigen::Vector3d> p;
  for (int z = 0; z <= 1; ++z)
    for (uint32_t i = 0; i < n; ++i) {
      const double a = 2.0 * 3.14159265358979323846 * i / n;
      p.emplace_back(std::cos(a), std::sin(a), double(z));
    }
  Loops faces(2);
  for (uint32_t i = 0; i < n; ++i) {
    faces[0].push_back(n - 1 - i);  // seen from below
    faces[1].push_back(n + i);
    faces.push_back({i, (i + 1) % n, n + (i + 1) % n, n + i});
  }
  return makeComplex(p, {faces});
}

inline CellComplex singlePyramid() {
  std::vector<Eigen::Vector3d> p = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0.5, 0.8}};
  return makeComplex(p, {orient(p, pyramidLoops({0, 1, 2, 3, 4}))});
}

/// Octahedron with vertices +-e_x (0, 1), +-e_y (2, 3), +-e_z (4, 5).
inline CellComplex octahedron() {
  std::vector<Eigen::Vector3d> p = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                    {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
  Loops loops;
  for (int sx = 0; sx < 2; ++sx)
    for (int sy = 0; sy < 2; ++sy)
      for (int sz = 0; sz < 2; ++sz) {
        const auto x = static_cast<uint32_t>(sx), y = static_cast<uint32_t>(2 + sy),
                   z = static_cast<uint32_t>(4 + sz);
        const bool positive = ((sx + sy + sz) % 2) == 0;  // sign product +1
        loops.push_back(positive ? std::vector<uint32_t>{x, y, z} : std::vector<uint32_t>{x, z, y});
      }
  return makeComplex(p, {loops});
}

/// Mixed mesh: two unit hexes along x on [0,2] x [0,1]^2, the cube [2,3] x [0,1]^2 split into
/// two prisms by the plane x - 2 = y, and a pyramid on top of each hex (apices at z = 1.6).
inline CellComplex mixedMesh() {
  std::vector<Eigen::Vector3d> p;
  // Grid vertices (i, j, k), i in 0..3, j, k in 0..1: id i + 4 (j + 2 k).
  for (int k = 0; k <= 1; ++k)
    for (int j = 0; j <= 1; ++j)
      for (int i = 0; i <= 3; ++i) p.emplace_back(i, j, k);
  auto g = [](uint32_t i, uint32_t j, uint32_t k) { return i + 4 * (j + 2 * k); };
  p.emplace_back(0.5, 0.5, 1.6);  // apex 16
  p.emplace_back(1.5, 0.5, 1.7);  // apex 17
  std::vector<Loops> cells;
  for (uint32_t i = 0; i < 2; ++i)
    cells.push_back(hexLoops({g(i, 0, 0), g(i + 1, 0, 0), g(i + 1, 1, 0), g(i, 1, 0), g(i, 0, 1),
                              g(i + 1, 0, 1), g(i + 1, 1, 1), g(i, 1, 1)}));
  // Prisms in [2,3]: triangles in z = 0 / z = 1.
  cells.push_back(orient(
      p, prismLoops({g(2, 0, 0), g(3, 1, 0), g(2, 1, 0), g(2, 0, 1), g(3, 1, 1), g(2, 1, 1)})));
  cells.push_back(orient(
      p, prismLoops({g(2, 0, 0), g(3, 0, 0), g(3, 1, 0), g(2, 0, 1), g(3, 0, 1), g(3, 1, 1)})));
  for (uint32_t i = 0; i < 2; ++i)
    cells.push_back(
        orient(p, pyramidLoops({g(i, 0, 1), g(i + 1, 0, 1), g(i + 1, 1, 1), g(i, 1, 1), 16 + i})));
  return makeComplex(p, cells);
}

/// Adds uniform noise in [-amplitude, amplitude] to every coordinate.
inline void jitter(CellComplex& m, double amplitude, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> uni(-amplitude, amplitude);
  for (Eigen::Index i = 0; i < m.positions.rows(); ++i)
    for (Eigen::Index d = 0; d < 3; ++d) m.positions(i, d) += uni(rng);
}

/// A copy of m with every coordinate moved by a uniform random amount in [-amplitude, amplitude].
inline CellComplex jittered(CellComplex m, double amplitude, uint64_t seed) {
  jitter(m, amplitude, seed);
  return m;
}

/// A mesh builder with a name, for value-parameterised tests.
struct NamedMesh {
  std::string name;
  std::function<CellComplex()> build;
};
inline void PrintTo(const NamedMesh& m, std::ostream* os) { *os << m.name; }

/// The mixed mesh (2 hexes, 2 prisms, 2 pyramids) with creases along the bottom front edge
/// chain y = 0, z = 0 from x = 0 to x = 3 (a crease chain whose ends are smooth: darts), and the
/// box edge x = 3, y = 0 (vertical), plus two corners.
inline CellComplex taggedMixed() {
  CellComplex m = jittered(mixedMesh(), 0.05, 21);
  auto g = [](uint32_t i, uint32_t j, uint32_t k) { return i + 4 * (j + 2 * k); };
  m.creases = {{g(0, 0, 0), g(1, 0, 0)},
               {g(1, 0, 0), g(2, 0, 0)},
               {g(2, 0, 0), g(3, 0, 0)},
               {g(3, 0, 0), g(3, 0, 1)},
               {g(3, 1, 0), g(3, 1, 1)}};
  m.corners = {g(0, 1, 0), g(3, 1, 1)};
  return m;
}

/// Independent check that every cell is closed and consistently oriented (each directed edge
/// of its loops appears once and its reverse once), that every face is used by at most two
/// cells, and, when two cells share a face, that they see it with opposite orientations.
/// Returns an empty string when all is well, else a description of the first problem.
inline std::string closedOrientedCheck(const CellComplex& m) {
  std::map<std::vector<uint32_t>, std::vector<std::pair<uint32_t, std::vector<uint32_t>>>> faces;
  for (uint32_t c = 0; c < m.numCells(); ++c) {
    std::map<std::pair<uint32_t, uint32_t>, int> directed;
    for (uint32_t j = 0; j < m.numFacesOfCell(c); ++j) {
      auto loop = m.cellFace(c, j);
      for (size_t i = 0; i < loop.size(); ++i) ++directed[{loop[i], loop[(i + 1) % loop.size()]}];
      std::vector<uint32_t> key(loop.begin(), loop.end());
      std::sort(key.begin(), key.end());
      faces[key].push_back({c, std::vector<uint32_t>(loop.begin(), loop.end())});
    }
    for (const auto& [e, count] : directed) {
      auto it = directed.find({e.second, e.first});
      if (count != 1 || it == directed.end() || it->second != 1) {
        std::ostringstream s;
        s << "cell " << c << " not closed/oriented at directed edge " << e.first << "->"
          << e.second;
        return s.str();
      }
    }
  }
  for (const auto& [key, users] : faces) {
    if (users.size() > 2) return "a face is used by more than two cells";
    if (users.size() == 2) {
      // Opposite orientation: the second loop is a rotation of the reversed first loop.
      std::vector<uint32_t> rev(users[0].second.rbegin(), users[0].second.rend());
      const auto& other = users[1].second;
      bool match = false;
      for (size_t s = 0; s < rev.size() && !match; ++s) {
        std::vector<uint32_t> rot(rev.begin() + static_cast<std::ptrdiff_t>(s), rev.end());
        rot.insert(rot.end(), rev.begin(), rev.begin() + static_cast<std::ptrdiff_t>(s));
        match = rot == other;
      }
      if (!match) {
        std::ostringstream s;
        s << "cells " << users[0].first << " and " << users[1].first
          << " see a shared face with the same orientation";
        return s.str();
      }
    }
  }
  return {};
}

/// Distinct vertices of a cell of a complex, and its distinct edges, from the raw loops.
inline std::set<uint32_t> cellVertexSet(const CellComplex& m, uint32_t c) {
  std::set<uint32_t> s;
  for (uint32_t j = 0; j < m.numFacesOfCell(c); ++j)
    for (uint32_t v : m.cellFace(c, j)) s.insert(v);
  return s;
}
inline std::set<std::pair<uint32_t, uint32_t>> cellEdgeSet(const CellComplex& m, uint32_t c) {
  std::set<std::pair<uint32_t, uint32_t>> s;
  for (uint32_t j = 0; j < m.numFacesOfCell(c); ++j) {
    auto loop = m.cellFace(c, j);
    for (size_t i = 0; i < loop.size(); ++i) {
      uint32_t a = loop[i], b = loop[(i + 1) % loop.size()];
      s.insert({std::min(a, b), std::max(a, b)});
    }
  }
  return s;
}

/// Counts straight from the face loops, independent of buildTopology.
struct RawCounts {
  uint32_t vertices = 0, edges = 0, faces = 0, cells = 0;
  uint64_t sumFaceSizes = 0;  ///< sum over unique faces of |f|
  uint64_t sumCellFaces = 0;  ///< sum over cells of F(c)
  uint64_t sumCellEdges = 0;  ///< sum over cells of E(c)
  uint64_t sumCellVerts = 0;  ///< sum over cells of V(c)
};
inline RawCounts rawCounts(const CellComplex& m) {
  RawCounts r;
  r.vertices = m.numVertices();
  r.cells = m.numCells();
  std::set<std::vector<uint32_t>> faces;
  std::set<std::pair<uint32_t, uint32_t>> edges;
  for (uint32_t c = 0; c < m.numCells(); ++c) {
    r.sumCellFaces += m.numFacesOfCell(c);
    const auto ce = cellEdgeSet(m, c);
    r.sumCellEdges += ce.size();
    r.sumCellVerts += cellVertexSet(m, c).size();
    edges.insert(ce.begin(), ce.end());
    for (uint32_t j = 0; j < m.numFacesOfCell(c); ++j) {
      auto loop = m.cellFace(c, j);
      std::vector<uint32_t> key(loop.begin(), loop.end());
      std::sort(key.begin(), key.end());
      if (faces.insert(key).second) r.sumFaceSizes += key.size();
    }
  }
  r.edges = u32(edges.size());
  r.faces = u32(faces.size());
  return r;
}

// ---------------------------------------------------------------------------------------------
// Child-vertex lookups (mj_refiner.h numbering).

/// Face id of the topology face with exactly this vertex set, or -1.
inline int64_t findFace(const Topology& t, std::vector<uint32_t> vertices) {
  std::sort(vertices.begin(), vertices.end());
  if (vertices.empty()) return -1;
  for (uint32_t f = 0; f < t.numFaces(); ++f) {
    auto row = t.faceVertices.row(f);
    if (row.size() != vertices.size()) continue;
    std::vector<uint32_t> key(row.begin(), row.end());
    std::sort(key.begin(), key.end());
    if (key == vertices) return f;
  }
  return -1;
}

inline uint32_t vertexPointId(uint32_t v) { return v; }
inline uint32_t edgePointId(const Topology& t, uint32_t a, uint32_t b) {
  const int64_t e = t.findEdge(a, b);
  return e < 0 ? UINT32_MAX : t.numVertices + static_cast<uint32_t>(e);
}
inline uint32_t facePointId(const Topology& t, std::vector<uint32_t> vertices) {
  const int64_t f = findFace(t, std::move(vertices));
  return f < 0 ? UINT32_MAX : t.numVertices + t.numEdges() + static_cast<uint32_t>(f);
}
inline uint32_t cellPointId(const Topology& t, uint32_t c) {
  return t.numVertices + t.numEdges() + t.numFaces() + c;
}

/// A cell of a topology whose distinct vertices are 8 and whose 6 faces are quads.
inline bool rawIsHex(const CellComplex& m, uint32_t c) {
  if (m.numFacesOfCell(c) != 6 || cellVertexSet(m, c).size() != 8) return false;
  for (uint32_t j = 0; j < 6; ++j)
    if (m.cellFace(c, j).size() != 4) return false;
  return true;
}
/// A square trapezohedron as MJ makes it at a valence-4 corner: 10 vertices, 8 quads.
inline bool rawIsTrapezohedron4(const CellComplex& m, uint32_t c) {
  if (m.numFacesOfCell(c) != 8 || cellVertexSet(m, c).size() != 10) return false;
  for (uint32_t j = 0; j < 8; ++j)
    if (m.cellFace(c, j).size() != 4) return false;
  return true;
}

/// A random proper rotation.
inline Eigen::Matrix3d randomRotation(std::mt19937_64& rng) {
  std::normal_distribution<double> n01;
  Eigen::Quaterniond q(n01(rng), n01(rng), n01(rng), n01(rng));
  q.normalize();
  return q.toRotationMatrix();
}

// ---------------------------------------------------------------------------------------------
// Refinement without subdivide() (e.g. for the 3-torus, whose random positions are not a valid
// embedding).

/// One MJ step of a complex with positions: the child complex with positions filled in.
inline CellComplex refineWithPositions(const CellComplex& m, const Topology& t) {
  RefinementStep step = refineOnce(t);
  step.child.positions.resize(static_cast<Eigen::Index>(step.stencils.numRows()), 3);
  step.stencils.apply(m.positions, step.child.positions);
  return step.child;
}

/// Row r of a stencil table as a column -> weight map (repeated columns added up).
inline std::map<uint32_t, double> stencilRow(const StencilTable& s, uint32_t r) {
  std::map<uint32_t, double> row;
  for (uint32_t i = s.offsets()[r]; i < s.offsets()[r + 1]; ++i)
    row[s.indices()[i]] += s.weights()[i];
  return row;
}

/// A session script (JSON text) of three topology events that subdivide every cell of block3
/// in turn: 27, then 216, then 1728 cells in, 13824 out.
inline std::string block3SubdividedThreeTimesScript() {
  std::string events;
  for (uint32_t cells : {27u, 216u, 1728u}) {
    std::string ids;
    for (uint32_t c = 0; c < cells; ++c) ids += (c ? "," : "") + std::to_string(c);
    events += std::string(events.empty() ? "" : ",\n") +
              R"({"t": 0, "type": "topology", "op": "subdivide", "cells": [)" + ids + "]}";
  }
  return R"({"format": "sculpt-session", "version": 1, "events": [)" + events + "]}";
}

}  // namespace sculpt::test
