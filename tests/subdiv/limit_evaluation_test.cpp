// (docs/design/mj-subdivision.md §6.1): regular-cell limit evaluation is
// consistent with refinement. The tricubic patch of a regular cell at its children's corner
// parameters equals those vertices' limit positions, and each child's patch equals the parent's
// patch on the child's parameter box. Also: the limit mask, the convergence of iterated MJ to it,
// and the regular / extraordinary / irregular classification.

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "mesh/topology.h"
#include "subdiv/mj_refiner.h"
#include "subdiv/regularity.h"
#include "subdiv/tricubic_patch.h"
#include "support/mesh_builders.h"

namespace sculpt {
namespace {

inline int blockIndex(int a, int b, int g) { return a * 16 + b * 4 + g; }

/// Two consecutive levels of a refinement.
struct TwoLevels {
  CellComplex coarse, fine;
  Topology coarseTopology, fineTopology;
};

TwoLevels refineTorus(int n, uint64_t seed) {
  TwoLevels l;
  l.coarse = test::periodicTorus(n, seed);
  l.coarseTopology = buildTopology(l.coarse);
  l.fine = test::refineWithPositions(l.coarse, l.coarseTopology);
  l.fineTopology = buildTopology(l.fine);
  return l;
}

/// Levels k and k+1 of the refinement of m.
TwoLevels levelsOf(const CellComplex& m, int k) {
  auto s = subdivide(m, k + 1);
  EXPECT_TRUE(s.has_value());
  TwoLevels l;
  if (!s) return l;
  l.coarse = s->levels[static_cast<size_t>(k)];
  l.fine = s->levels[static_cast<size_t>(k + 1)];
  l.coarseTopology = s->topologies[static_cast<size_t>(k)];
  l.fineTopology = s->topologies[static_cast<size_t>(k + 1)];
  return l;
}

TwoLevels refineBlock(int n, double jitter, uint64_t seed) {
  CellComplex m = test::hexGrid(n, n, n);
  test::jitter(m, jitter, seed);
  return levelsOf(m, 0);
}

double scaleOf(const Points& p) { return 1.0 + p.cwiseAbs().maxCoeff(); }

/// Checks (a) and (b) of the brief for one regular level-k cell c. Returns the number of
/// comparisons made.
int checkRegularCell(const TwoLevels& l, uint32_t c, std::mt19937_64& rng) {
  const Topology& t = l.coarseTopology;
  const Topology& u = l.fineTopology;
  const double tol = 1e-12 * scaleOf(l.coarse.positions);
  const auto block = regularControlBlock(t, c);
  EXPECT_TRUE(block.has_value()) << "cell " << c;
  if (!block) return 0;
  // The cell is [1,2]^3 of the block: corner (1+i, 1+j, 1+k) has parameter (i, j, k).
  std::map<uint32_t, Eigen::Vector3d> param;
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j)
      for (int k = 0; k < 2; ++k)
        param[(*block)[static_cast<size_t>(blockIndex(1 + i, 1 + j, 1 + k))]] =
            Eigen::Vector3d(i, j, k);
  const auto cellVerts = t.cellVertices.row(c);
  EXPECT_EQ(param.size(), 8u);
  EXPECT_EQ(std::set<uint32_t>(cellVerts.begin(), cellVerts.end()).size(), 8u);
  for (uint32_t v : cellVerts) EXPECT_TRUE(param.count(v)) << "cell vertex " << v;
  if (param.size() != 8) return 0;

  // Parameters of the 27 child vertices of c.
  std::map<uint32_t, Eigen::Vector3d> childParam;
  for (const auto& [v, p] : param) childParam[v] = p;
  for (uint32_t e : t.cellEdges.row(c)) {
    const auto [a, b] = t.edgeVertices[e];
    EXPECT_NEAR((param[a] - param[b]).lpNorm<1>(), 1.0, 0.0) << "edge " << e << " of the cube";
    childParam[t.numVertices + e] = 0.5 * (param[a] + param[b]);
  }
  for (uint32_t f : t.cellFaces.row(c)) {
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (uint32_t v : t.faceVertices.row(f)) mean += param[v];
    childParam[t.numVertices + t.numEdges() + f] = mean / 4.0;
  }
  const uint32_t cellPoint = test::cellPointId(t, c);
  childParam[cellPoint] = Eigen::Vector3d::Constant(0.5);
  EXPECT_EQ(childParam.size(), 27u);

  // (a) Patch at the child vertices' parameters == their limit positions at level k+1.
  int checks = 0;
  for (const auto& [id, uvw] : childParam) {
    EXPECT_TRUE(isRegularVertex(u, id)) << "child vertex " << id;
    const Eigen::Vector3d limit = regularVertexLimit(u, l.fine.positions, id);
    const Eigen::Vector3d patch =
        evaluateTricubic(l.coarse.positions, *block, uvw.x(), uvw.y(), uvw.z());
    EXPECT_LE((limit - patch).norm(), tol)
        << "cell " << c << " child vertex " << id << " at (" << uvw.transpose() << ")";
    ++checks;
  }

  // (b) Each of the 8 children: its patch equals the parent's patch on its parameter box.
  const auto children = u.vertexCells.row(cellPoint);
  EXPECT_EQ(children.size(), 8u);
  std::set<std::array<int, 3>> boxes;
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  for (uint32_t child : children) {
    const auto cblock = regularControlBlock(u, child);
    EXPECT_TRUE(cblock.has_value()) << "child cell " << child;
    if (!cblock) continue;
    std::array<Eigen::Vector3d, 8> corner;
    bool known = true;
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j)
        for (int k = 0; k < 2; ++k) {
          const uint32_t id = (*cblock)[static_cast<size_t>(blockIndex(1 + i, 1 + j, 1 + k))];
          const auto it = childParam.find(id);
          known = known && it != childParam.end();
          if (it != childParam.end()) corner[static_cast<size_t>(i * 4 + j * 2 + k)] = it->second;
        }
    EXPECT_TRUE(known) << "child cell " << child << " has a corner outside the parent's children";
    if (!known) continue;
    const Eigen::Vector3d origin = corner[0];
    const Eigen::Vector3d du = corner[4] - origin, dv = corner[2] - origin, dw = corner[1] - origin;
    // Axis-aligned box of side 1/2 in the parent's parameters.
    for (const Eigen::Vector3d& d : {du, dv, dw}) {
      EXPECT_NEAR(d.cwiseAbs().maxCoeff(), 0.5, 1e-15);
      EXPECT_NEAR(d.lpNorm<1>(), 0.5, 1e-15);
    }
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j)
        for (int k = 0; k < 2; ++k)
          EXPECT_LE(
              (corner[static_cast<size_t>(i * 4 + j * 2 + k)] - (origin + i * du + j * dv + k * dw))
                  .norm(),
              1e-15);
    const Eigen::Vector3d lo = origin.cwiseMin(origin + du + dv + dw);
    boxes.insert({static_cast<int>(std::lround(2 * lo.x())),
                  static_cast<int>(std::lround(2 * lo.y())),
                  static_cast<int>(std::lround(2 * lo.z()))});
    for (int sample = 0; sample < 6; ++sample) {
      const double s = uni(rng), r = uni(rng), q = uni(rng);
      const Eigen::Vector3d childPatch = evaluateTricubic(l.fine.positions, *cblock, s, r, q);
      const Eigen::Vector3d at = origin + s * du + r * dv + q * dw;
      const Eigen::Vector3d parentPatch =
          evaluateTricubic(l.coarse.positions, *block, at.x(), at.y(), at.z());
      EXPECT_LE((childPatch - parentPatch).norm(), tol)
          << "cell " << c << " child " << child << " at (" << s << "," << r << "," << q << ")";
      ++checks;
    }
  }
  EXPECT_EQ(boxes.size(), 8u) << "the children's boxes tile the parent's parameter cube";
  return checks;
}

TEST(LimitEvaluation, JitteredBlockRegularCellsAreConsistentWithRefinement) {
  const TwoLevels l = refineBlock(6, 0.15, 42);
  const auto classes = classifyCells(l.coarseTopology);
  std::mt19937_64 rng(3);
  int regular = 0, checks = 0;
  for (uint32_t c = 0; c < l.coarseTopology.numCells(); ++c) {
    if (classes[c] != CellRegularity::Regular) continue;
    ++regular;
    checks += checkRegularCell(l, c, rng);
  }
  // Cells whose 8 corners are all interior (indices 1..5): cells [1,4]^3 -> 4^3.
  EXPECT_EQ(regular, 64);
  EXPECT_GT(checks, 64 * 27);
}

// Regular cells that appear only after refinement, in unstructured meshes (levels 1 -> 2 and
// 2 -> 3), next to extraordinary edges, pyramids' trapezohedra and creases.
TEST(LimitEvaluation, RegularCellsOfRefinedMeshesAreConsistent) {
  struct Case {
    const char* name;
    CellComplex mesh;
    int level;
    int minRegular;
  };
  CellComplex block = test::hexGrid(3, 3, 3);
  test::jitter(block, 0.1, 8);
  CellComplex mixed = test::mixedMesh();
  test::jitter(mixed, 0.04, 9);
  mixed.creases = {{0, 1}, {1, 2}};
  mixed.corners = {3};
  CellComplex kuhn = test::kuhnCube();
  test::jitter(kuhn, 0.03, 10);
  const Case cases[] = {{"3x3x3 block, level 1", block, 1, 64},
                        {"Kuhn cube, level 3", kuhn, 3, 1},
                        {"mixed, level 2", mixed, 2, 1},
                        {"pyramid cube, level 3", test::pyramidCube({0.5, 0.5, 0.75}), 3, 1}};
  std::mt19937_64 rng(5);
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    const TwoLevels l = levelsOf(c.mesh, c.level);
    const auto classes = classifyCells(l.coarseTopology);
    int regular = 0;
    for (uint32_t cell = 0; cell < l.coarseTopology.numCells(); ++cell) {
      if (classes[cell] != CellRegularity::Regular) continue;
      ++regular;
      checkRegularCell(l, cell, rng);
    }
    EXPECT_GE(regular, c.minRegular);
    RecordProperty(std::string("regular cells: ") + c.name, regular);
  }
}

TEST(LimitEvaluation, TorusRegularCellsAreConsistentWithRefinement) {
  const TwoLevels l = refineTorus(4, 8);
  const auto classes = classifyCells(l.coarseTopology);
  std::mt19937_64 rng(4);
  for (uint32_t c = 0; c < l.coarseTopology.numCells(); ++c) {
    ASSERT_EQ(classes[c], CellRegularity::Regular) << "torus cell " << c;
    checkRegularCell(l, c, rng);
  }
}

// The limit of a regular vertex is the (1,4,1)/6 tensor mask on its 3x3x3 neighbourhood.
TEST(LimitEvaluation, RegularVertexLimitIsTheTensorMask) {
  const int n = 5;
  const CellComplex torus = test::periodicTorus(n, 17);
  const Topology t = buildTopology(torus);
  const double w[3] = {1.0 / 6.0, 4.0 / 6.0, 1.0 / 6.0};
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const uint32_t v = test::torusVertex(n, i, j, k);
        ASSERT_TRUE(isRegularVertex(t, v));
        Eigen::Vector3d expected = Eigen::Vector3d::Zero();
        for (int c = -1; c <= 1; ++c)
          for (int b = -1; b <= 1; ++b)
            for (int a = -1; a <= 1; ++a)
              expected += w[a + 1] * w[b + 1] * w[c + 1] *
                          test::pos(torus, test::torusVertex(n, i + a, j + b, k + c));
        EXPECT_LE((regularVertexLimit(t, torus.positions, v) - expected).norm(), 1e-14);
      }
  // Equivalently, on a regular lattice the limit of a corner is the patch at that corner.
  const TwoLevels l = refineTorus(4, 21);
  const auto block = regularControlBlock(l.coarseTopology, 0);
  ASSERT_TRUE(block.has_value());
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j)
      for (int k = 0; k < 2; ++k) {
        const uint32_t v = (*block)[static_cast<size_t>(blockIndex(1 + i, 1 + j, 1 + k))];
        EXPECT_LE((regularVertexLimit(l.coarseTopology, l.coarse.positions, v) -
                   evaluateTricubic(l.coarse.positions, *block, i, j, k))
                      .norm(),
                  1e-14);
      }
}

// Iterating MJ on a 3-torus converges to the limit: the limit itself is invariant under
// refinement, and the distance of a vertex from it shrinks by about 4 per level.
TEST(LimitEvaluation, IteratedRefinementConvergesToTheLimit) {
  const int n = 4;
  const uint32_t n3 = static_cast<uint32_t>(n * n * n);
  CellComplex m = test::periodicTorus(n, 5);
  Topology t = buildTopology(m);
  std::vector<Eigen::Vector3d> limit(n3);
  for (uint32_t v = 0; v < n3; ++v) limit[v] = regularVertexLimit(t, m.positions, v);
  std::vector<double> error;
  for (int level = 0; level <= 3; ++level) {
    double sum = 0.0;
    for (uint32_t v = 0; v < n3; ++v) {
      // Vertex v's vertex point keeps the id v at every level.
      sum += (test::pos(m, v) - limit[v]).squaredNorm();
      EXPECT_LE((regularVertexLimit(t, m.positions, v) - limit[v]).norm(), 1e-12)
          << "limit of vertex " << v << " at level " << level;
    }
    error.push_back(std::sqrt(sum / n3));
    if (level == 3) break;
    m = test::refineWithPositions(m, t);
    t = buildTopology(m);
  }
  for (size_t k = 1; k < error.size(); ++k) {
    const double ratio = error[k] / error[k - 1];
    EXPECT_GT(ratio, 0.1) << "level " << k;
    EXPECT_LT(ratio, 0.4) << "level " << k;
  }
}

// §6.1: centre weights of the composed vertex mask on a 3-torus: 0.4219, 0.3250, 0.3033 -> 8/27,
// and the face-neighbour weights -> 2/27. Checked against a 1D cubic B-spline iteration (the
// composed mask is its tensor cube).
TEST(LimitEvaluation, ComposedVertexMaskApproachesLimitMask) {
  const int n = 5;
  CellComplex m = test::periodicTorus(n, 1);
  m.positions.setZero();
  const uint32_t centre = test::torusVertex(n, 2, 2, 2);
  const uint32_t neighbour = test::torusVertex(n, 3, 2, 2);
  m.positions(static_cast<Eigen::Index>(centre), 0) = 1.0;
  const double spec[] = {0.4219, 0.3250, 0.3033};
  // 1D response to an impulse at index 16 of a periodic line of 33 points.
  std::vector<double> line(33, 0.0);
  line[16] = 1.0;
  Topology t = buildTopology(m);
  for (int level = 1; level <= 3; ++level) {
    m = test::refineWithPositions(m, t);
    t = buildTopology(m);
    std::vector<double> fine(2 * line.size(), 0.0);
    const size_t z = line.size();
    for (size_t i = 0; i < z; ++i) {
      fine[2 * i] = (line[(i + z - 1) % z] + 6 * line[i] + line[(i + 1) % z]) / 8;
      fine[2 * i + 1] = (line[i] + line[(i + 1) % z]) / 2;
    }
    line = fine;
    // Coarse vertex i is fine index i * 2^level; its vertex point keeps its id in MJ.
    const double c1 = line[size_t{16} << level];
    const double n1 = line[size_t{17} << level];
    const double x = m.positions(static_cast<Eigen::Index>(centre), 0);
    const double xn = m.positions(static_cast<Eigen::Index>(neighbour), 0);
    EXPECT_NEAR(x, c1 * c1 * c1, 1e-14) << "level " << level;
    EXPECT_NEAR(xn, n1 * c1 * c1, 1e-14) << "level " << level;
    EXPECT_NEAR(x, spec[level - 1], 5e-5) << "level " << level;
  }
  const double x = m.positions(static_cast<Eigen::Index>(centre), 0);
  const double xn = m.positions(static_cast<Eigen::Index>(neighbour), 0);
  EXPECT_GT(x, 8.0 / 27.0);
  EXPECT_LT(x - 8.0 / 27.0, 0.01);
  EXPECT_LT(std::abs(xn - 2.0 / 27.0), 0.01);
}

TEST(Regularity, FourCubedBlockClassification) {
  const CellComplex m = test::hexGrid(4, 4, 4);
  const Topology t = buildTopology(m);
  const auto classes = classifyCells(t);
  ASSERT_EQ(classes.size(), 64u);
  int regular = 0, extraordinary = 0, irregular = 0;
  for (int k = 0; k < 4; ++k)
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 4; ++i) {
        const auto c = static_cast<size_t>(i + 4 * (j + 4 * k));
        const bool inside = i >= 1 && i <= 2 && j >= 1 && j <= 2 && k >= 1 && k <= 2;
        EXPECT_EQ(classes[c], inside ? CellRegularity::Regular : CellRegularity::Extraordinary)
            << "cell " << c;
        EXPECT_EQ(regularControlBlock(t, static_cast<uint32_t>(c)).has_value(), inside);
        regular += classes[c] == CellRegularity::Regular;
        extraordinary += classes[c] == CellRegularity::Extraordinary;
        irregular += classes[c] == CellRegularity::Irregular;
      }
  EXPECT_EQ(regular, 8);
  EXPECT_EQ(extraordinary, 56);
  EXPECT_EQ(irregular, 0);
  int regularVertices = 0;
  for (int k = 0; k <= 4; ++k)
    for (int j = 0; j <= 4; ++j)
      for (int i = 0; i <= 4; ++i) {
        const bool interior = i >= 1 && i <= 3 && j >= 1 && j <= 3 && k >= 1 && k <= 3;
        const bool regularVertex = isRegularVertex(t, test::gridVertex(4, 4, i, j, k));
        EXPECT_EQ(regularVertex, interior) << i << "," << j << "," << k;
        regularVertices += regularVertex;
      }
  EXPECT_EQ(regularVertices, 27);
}

TEST(Regularity, NonHexCellsAreIrregular) {
  // Mixed mesh: 2 hexes (extraordinary: on the boundary), 2 prisms and 2 pyramids (irregular).
  const Topology mixed = buildTopology(test::mixedMesh());
  const auto classes = classifyCells(mixed);
  ASSERT_EQ(classes.size(), 6u);
  EXPECT_EQ(classes[0], CellRegularity::Extraordinary);
  EXPECT_EQ(classes[1], CellRegularity::Extraordinary);
  for (size_t c = 2; c < 6; ++c) EXPECT_EQ(classes[c], CellRegularity::Irregular) << c;

  // Pyramid cube after one step: 24 hexes (all touch the boundary or the apex) + 6 trapezohedra.
  const auto s = subdivide(test::pyramidCube({0.5, 0.5, 0.75}), 1);
  ASSERT_TRUE(s.has_value());
  const auto levelOne = classifyCells(s->finestTopology());
  int hexes = 0, traps = 0;
  for (uint32_t c = 0; c < s->finest().numCells(); ++c) {
    if (test::rawIsHex(s->finest(), c)) {
      ++hexes;
      EXPECT_EQ(levelOne[c], CellRegularity::Extraordinary);
    } else {
      ++traps;
      EXPECT_EQ(levelOne[c], CellRegularity::Irregular);
      EXPECT_FALSE(regularControlBlock(s->finestTopology(), c).has_value());
    }
  }
  EXPECT_EQ(hexes, 24);
  EXPECT_EQ(traps, 6);

  // Kuhn cube: the diagonal's edge point has 12 cells around it: not regular.
  const auto kuhn = subdivide(test::kuhnCube(), 2);
  ASSERT_TRUE(kuhn.has_value());
  const uint32_t diag = test::edgePointId(kuhn->topologies[0], 0, 7);
  EXPECT_FALSE(isRegularVertex(kuhn->topologies[1], diag));
  EXPECT_FALSE(isRegularVertex(kuhn->topologies[2], diag));
}

/// The star of one interior vertex v (id 0) made of 8 hexahedra whose corners at v are the
/// triangles of `link` (a triangulated sphere on the 6 edge-neighbours 1..6 of v, consistently
/// oriented). Positions are arbitrary: only the topology matters here.
CellComplex vertexStar(const std::vector<std::array<uint32_t, 3>>& link) {
  std::vector<Eigen::Vector3d> p(7, Eigen::Vector3d::Zero());
  const Eigen::Vector3d axes[6] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                   {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
  for (uint32_t i = 0; i < 6; ++i) p[1 + i] = axes[i];
  std::map<std::pair<uint32_t, uint32_t>, uint32_t> diagonal;  // link edge -> face vertex
  auto diag = [&](uint32_t a, uint32_t b) {
    const auto key = std::make_pair(std::min(a, b), std::max(a, b));
    auto it = diagonal.find(key);
    if (it != diagonal.end()) return it->second;
    p.push_back(0.7 * (p[a] + p[b]) + Eigen::Vector3d(0.01, 0.02, 0.03) * double(p.size()));
    return diagonal[key] = static_cast<uint32_t>(p.size() - 1);
  };
  std::vector<test::Loops> cells;
  for (const auto& [a, b, c] : link) {
    // VTK hex: 0 = v, edge-neighbours 1, 3, 4; face diagonals 2 (1,3), 5 (1,4), 7 (3,4).
    const uint32_t dab = diag(a, b), dac = diag(a, c), dbc = diag(b, c);
    p.push_back(p[a] + p[b] + p[c]);
    const auto o = static_cast<uint32_t>(p.size() - 1);
    cells.push_back(test::hexLoops({0, a, dab, b, c, dac, o, dbc}));
  }
  return test::makeComplex(p, cells);
}

// §6.1: 6 edges and 8 hexahedra at an interior vertex are not enough; the link must be the
// octahedron (all edge valences 4), not the (3,3,4,4,5,5) triangulation.
TEST(Regularity, LinkWithValences334455IsNotRegular) {
  // Link vertices: +x = 1, -x = 2, +y = 3, -y = 4, +z = 5, -z = 6. Octahedron, outward CCW.
  std::vector<std::array<uint32_t, 3>> octahedron;
  for (uint32_t x : {1u, 2u})
    for (uint32_t y : {3u, 4u})
      for (uint32_t z : {5u, 6u}) {
        const bool positive = ((x == 2) + (y == 4) + (z == 6)) % 2 == 0;
        octahedron.push_back(positive ? std::array<uint32_t, 3>{x, y, z}
                                      : std::array<uint32_t, 3>{x, z, y});
      }
  const CellComplex regular = vertexStar(octahedron);
  const Topology tr = buildTopology(regular);
  ASSERT_TRUE(tr.problems.empty());
  ASSERT_EQ(test::closedOrientedCheck(regular), "");
  EXPECT_FALSE(tr.vertexIsBoundary[0]);
  EXPECT_TRUE(isRegularVertex(tr, 0));

  // Flip the link edge (+x, +y): triangles (+x,+y,+z) and (+x,+y,-z) become (+x,-z,+z) and
  // (+y,+z,-z) with the same orientation. Degrees: +x, +y 3; -x, -y 4; +z, -z 5.
  std::vector<std::array<uint32_t, 3>> flipped;
  for (const auto& t : octahedron) {
    const std::set<uint32_t> s(t.begin(), t.end());
    if (s.count(1) && s.count(3)) continue;
    flipped.push_back(t);
  }
  ASSERT_EQ(flipped.size(), 6u);
  flipped.push_back({1, 6, 5});  // +x, -z, +z
  flipped.push_back({3, 5, 6});  // +y, +z, -z
  const CellComplex star = vertexStar(flipped);
  ASSERT_EQ(test::closedOrientedCheck(star), "");
  const Topology t = buildTopology(star);
  ASSERT_TRUE(t.problems.empty());
  EXPECT_FALSE(t.vertexIsBoundary[0]);
  EXPECT_EQ(t.vertexEdges.rowSize(0), 6u);
  EXPECT_EQ(t.vertexFaces.rowSize(0), 12u);
  EXPECT_EQ(t.vertexCells.rowSize(0), 8u);
  std::multiset<uint32_t> valences;
  for (uint32_t e : t.vertexEdges.row(0)) valences.insert(t.edgeFaces.rowSize(e));
  EXPECT_EQ(valences, std::multiset<uint32_t>({3, 3, 4, 4, 5, 5}));
  EXPECT_FALSE(isRegularVertex(t, 0));
}

// The (u, v, w) frame of regularControlBlock: on an undistorted grid the 64 points are an
// affine lattice, right-handed, with u / v along the first face's loop as the header says.
TEST(Regularity, ControlBlockFrame) {
  const CellComplex m = test::hexGrid(6, 6, 6);
  const Topology t = buildTopology(m);
  const auto classes = classifyCells(t);
  int regular = 0;
  for (uint32_t c = 0; c < t.numCells(); ++c) {
    if (classes[c] != CellRegularity::Regular) continue;
    ++regular;
    const auto block = regularControlBlock(t, c);
    ASSERT_TRUE(block.has_value());
    auto P = [&](int a, int b, int g) {
      return test::pos(m, (*block)[static_cast<size_t>(blockIndex(a, b, g))]);
    };
    const Eigen::Vector3d o = P(1, 1, 1);
    const Eigen::Vector3d U = P(2, 1, 1) - o, V = P(1, 2, 1) - o, W = P(1, 1, 2) - o;
    EXPECT_NEAR(U.cross(V).dot(W), 1.0, 1e-14) << "right-handed unit frame, cell " << c;
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b)
        for (int g = 0; g < 4; ++g)
          ASSERT_LE((P(a, b, g) - (o + (a - 1) * U + (b - 1) * V + (g - 1) * W)).norm(), 1e-14)
              << "cell " << c << " block (" << a << "," << b << "," << g << ")";
    // The frame described in regularity.h.
    const auto loop = t.outwardLoop(c, 0);
    ASSERT_EQ(loop.size(), 4u);
    EXPECT_EQ((*block)[static_cast<size_t>(blockIndex(1, 1, 1))], loop[0]);
    EXPECT_EQ((*block)[static_cast<size_t>(blockIndex(2, 1, 1))], loop[3]);
    EXPECT_EQ((*block)[static_cast<size_t>(blockIndex(1, 2, 1))], loop[1]);
  }
  EXPECT_EQ(regular, 64);
}

TEST(Tricubic, BasisMatchesSection61) {
  for (double t : {0.0, 0.1, 0.37, 0.5, 0.9, 1.0}) {
    double b[4], d[4];
    cubicBSplineBasis(t, b, d);
    EXPECT_NEAR(b[0], std::pow(1 - t, 3) / 6, 1e-15);
    EXPECT_NEAR(b[1], (3 * t * t * t - 6 * t * t + 4) / 6, 1e-15);
    EXPECT_NEAR(b[2], (-3 * t * t * t + 3 * t * t + 3 * t + 1) / 6, 1e-15);
    EXPECT_NEAR(b[3], t * t * t / 6, 1e-15);
    EXPECT_NEAR(d[0], -0.5 * (1 - t) * (1 - t), 1e-15);
    EXPECT_NEAR(d[1], (9 * t * t - 12 * t) / 6, 1e-15);
    EXPECT_NEAR(d[2], (-9 * t * t + 6 * t + 3) / 6, 1e-15);
    EXPECT_NEAR(d[3], 0.5 * t * t, 1e-15);
    double only[4];
    cubicBSplineBasis(t, only);
    for (int i = 0; i < 4; ++i) EXPECT_EQ(only[i], b[i]);
  }
}

}  // namespace
}  // namespace sculpt
