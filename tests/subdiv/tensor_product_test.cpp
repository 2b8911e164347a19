// docs/design/mj-subdivision.md §7.1.1 and §7.1.2: on a periodic hex lattice (3-torus) one MJ step
// is exactly periodic tensor-product cubic B-spline refinement, and the stencils are the masks of
// §5.3. The expected values come from an independent 1D B-spline refinement, not from the
// refiner.

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>
#include <sstream>
#include <vector>

#include "mesh/topology.h"
#include "subdiv/mj_refiner.h"
#include "support/mesh_builders.h"

namespace sculpt {
namespace {

using test::periodicTorus;

/// Lattice coordinates (i, j, k) of torus vertex id.
std::array<int, 3> latticeOf(int n, uint32_t id) {
  const int v = static_cast<int>(id);
  return {v % n, (v / n) % n, v / (n * n)};
}

/// Refined (level k+1) lattice index along one axis of an element whose vertices have the given
/// coarse coordinates along that axis (§7.1.1 index map): one value i -> 2i, two values
/// {i, i+1 mod n} -> 2i+1.
int fineIndex(int n, const std::set<int>& coords) {
  if (coords.size() == 1) return 2 * *coords.begin();
  EXPECT_EQ(coords.size(), 2u);
  const int a = *coords.begin();
  const int b = *coords.rbegin();
  if ((a + 1) % n == b) return 2 * a + 1;
  EXPECT_EQ((b + 1) % n, a);
  return 2 * b + 1;
}

/// Fine lattice index (I, J, K) of an element given by its vertices.
template <typename Range>
std::array<int, 3> fineIndexOf(int n, const Range& vertices) {
  std::array<std::set<int>, 3> coords;
  for (uint32_t v : vertices) {
    const auto l = latticeOf(n, v);
    for (int d = 0; d < 3; ++d) coords[static_cast<size_t>(d)].insert(l[static_cast<size_t>(d)]);
  }
  return {fineIndex(n, coords[0]), fineIndex(n, coords[1]), fineIndex(n, coords[2])};
}

/// Fine index of every child vertex of one step on the n^3 torus, by the child numbering of
/// mj_refiner.h.
std::vector<std::array<int, 3>> childFineIndices(int n, const Topology& t) {
  std::vector<std::array<int, 3>> out;
  for (uint32_t v = 0; v < t.numVertices; ++v) out.push_back(fineIndexOf(n, std::vector{v}));
  for (uint32_t e = 0; e < t.numEdges(); ++e) out.push_back(fineIndexOf(n, t.edgeVertices[e]));
  for (uint32_t f = 0; f < t.numFaces(); ++f) out.push_back(fineIndexOf(n, t.faceVertices.row(f)));
  for (uint32_t c = 0; c < t.numCells(); ++c) out.push_back(fineIndexOf(n, t.cellVertices.row(c)));
  return out;
}

/// Periodic cubic B-spline midpoint refinement of an n^3 net along x, then y, then z.
/// Input index i + n (j + n k); output index I + 2n (J + 2n K).
std::vector<Eigen::Vector3d> bsplineRefine(int n, const Points& p) {
  std::vector<Eigen::Vector3d> cur(static_cast<size_t>(n * n * n));
  for (int i = 0; i < n * n * n; ++i)
    cur[static_cast<size_t>(i)] = test::pos(p, static_cast<uint32_t>(i));
  std::array<int, 3> dims = {n, n, n};
  for (int axis = 0; axis < 3; ++axis) {
    std::array<int, 3> out = dims;
    out[static_cast<size_t>(axis)] *= 2;
    std::vector<Eigen::Vector3d> next(static_cast<size_t>(out[0] * out[1] * out[2]));
    auto inIdx = [&](std::array<int, 3> q) {
      return static_cast<size_t>(q[0] + dims[0] * (q[1] + dims[1] * q[2]));
    };
    auto outIdx = [&](std::array<int, 3> q) {
      return static_cast<size_t>(q[0] + out[0] * (q[1] + out[1] * q[2]));
    };
    for (int k = 0; k < out[2]; ++k)
      for (int j = 0; j < out[1]; ++j)
        for (int i = 0; i < out[0]; ++i) {
          std::array<int, 3> q = {i, j, k};
          const int fine = q[static_cast<size_t>(axis)];
          const int a = fine / 2;
          auto at = [&](int offset) {
            std::array<int, 3> r = q;
            r[static_cast<size_t>(axis)] = ((a + offset) % n + n) % n;
            return cur[inIdx(r)];
          };
          next[outIdx(q)] = (fine % 2 == 0) ? Eigen::Vector3d((at(-1) + 6.0 * at(0) + at(1)) / 8.0)
                                            : Eigen::Vector3d((at(0) + at(1)) / 2.0);
        }
    cur = std::move(next);
    dims = out;
  }
  return cur;
}

class TorusTensorProduct : public ::testing::TestWithParam<int> {};

TEST_P(TorusTensorProduct, OneStepEqualsPeriodicTricubicRefinement) {
  const int n = GetParam();
  const CellComplex torus = periodicTorus(n, 1234u + static_cast<uint64_t>(n));
  const Topology t = buildTopology(torus);
  ASSERT_TRUE(t.problems.empty());
  const uint32_t n3 = static_cast<uint32_t>(n * n * n);
  // Sanity of the periodic topology: 3 edges, 3 faces, 1 cell per vertex, no boundary.
  ASSERT_EQ(t.numVertices, n3);
  ASSERT_EQ(t.numEdges(), 3 * n3);
  ASSERT_EQ(t.numFaces(), 3 * n3);
  ASSERT_EQ(t.numCells(), n3);
  for (uint32_t v = 0; v < n3; ++v) ASSERT_FALSE(t.vertexIsBoundary[v]);

  const RefinementStep step = refineOnce(t);
  ASSERT_EQ(step.stencils.numRows(), 8 * n3);
  ASSERT_EQ(step.stencils.numColumns(), n3);
  ASSERT_EQ(step.child.numCells(), 8 * n3);
  Points fine(static_cast<Eigen::Index>(8 * n3), 3);
  step.stencils.apply(torus.positions, fine);

  const auto reference = bsplineRefine(n, torus.positions);
  const auto index = childFineIndices(n, t);
  ASSERT_EQ(index.size(), 8 * n3);
  // Every fine lattice point is produced exactly once.
  std::set<std::array<int, 3>> seen(index.begin(), index.end());
  EXPECT_EQ(seen.size(), 8 * n3);

  double maxError = 0.0;
  for (uint32_t id = 0; id < 8 * n3; ++id) {
    const auto& q = index[id];
    const Eigen::Vector3d expected =
        reference[static_cast<size_t>(q[0] + 2 * n * (q[1] + 2 * n * q[2]))];
    const double err = (test::pos(fine, id) - expected).norm();
    maxError = std::max(maxError, err);
    EXPECT_LE(err, 1e-12) << "child vertex " << id << " (fine index " << q[0] << "," << q[1] << ","
                          << q[2] << ")";
  }
  std::ostringstream text;
  text << std::scientific << maxError;
  RecordProperty("max_error", text.str());
  EXPECT_LE(maxError, 1e-12);
}

INSTANTIATE_TEST_SUITE_P(N, TorusTensorProduct, ::testing::Values(4, 5));

/// 1D cubic B-spline refinement weight of coarse vertex i for fine index F on a periodic line
/// of n vertices.
double weight1d(int n, int fine, int i) {
  const int a = fine / 2;
  int d = ((i - a) % n + n) % n;
  if (d > n / 2) d -= n;
  if (fine % 2 == 0) {
    if (d == 0) return 6.0 / 8.0;
    if (d == 1 || d == -1) return 1.0 / 8.0;
    return 0.0;
  }
  return (d == 0 || d == 1) ? 0.5 : 0.0;
}

// §5.3 / §7.1.2: every stencil row of one step on the 5^3 torus equals the tensor product of
// the 1D masks, exactly.
TEST(TorusMasks, EveryStencilRowIsTheTensorMask) {
  const int n = 5;
  const CellComplex torus = periodicTorus(n, 99u);
  const Topology t = buildTopology(torus);
  const RefinementStep step = refineOnce(t);
  const auto index = childFineIndices(n, t);
  const auto& s = step.stencils;
  ASSERT_EQ(s.numRows(), index.size());
  for (uint32_t r = 0; r < s.numRows(); ++r) {
    const auto row = test::stencilRow(s, r);
    const auto& q = index[r];
    for (uint32_t col = 0; col < static_cast<uint32_t>(n * n * n); ++col) {
      const auto l = latticeOf(n, col);
      const double expected =
          weight1d(n, q[0], l[0]) * weight1d(n, q[1], l[1]) * weight1d(n, q[2], l[2]);
      const auto it = row.find(col);
      const double got = it == row.end() ? 0.0 : it->second;
      ASSERT_NEAR(got, expected, 1e-15) << "row " << r << " column " << col;
    }
  }
}

/// Histogram of the nonzero weights of a row: weight -> count (weights rounded to 1e-12).
std::map<double, int> histogram(const std::map<uint32_t, double>& row) {
  std::map<double, int> h;
  for (const auto& [col, w] : row)
    if (std::abs(w) > 1e-15) ++h[std::round(w * 1e12) / 1e12];
  return h;
}
std::map<double, int> expectedHistogram(std::initializer_list<std::pair<double, int>> items) {
  std::map<double, int> h;
  for (const auto& [w, c] : items) h[std::round(w * 1e12) / 1e12] += c;
  return h;
}

// §5.3 masks read off the impulse response: unit impulse at vertex (2,2,2) of the 5^3 torus,
// applied through the stencils, and the rows of the vertex / edge / face / cell points.
TEST(TorusMasks, ImpulseResponseMatchesSection53) {
  const int n = 5;
  CellComplex torus = periodicTorus(n, 7u);
  const uint32_t centre = test::torusVertex(n, 2, 2, 2);
  torus.positions.setZero();
  torus.positions(static_cast<Eigen::Index>(centre), 0) = 1.0;  // impulse in x
  const Topology t = buildTopology(torus);
  const RefinementStep step = refineOnce(t);
  Points fine(static_cast<Eigen::Index>(step.stencils.numRows()), 3);
  step.stencils.apply(torus.positions, fine);

  auto g = [&](int i, int j, int k) { return test::torusVertex(n, i, j, k); };
  // Vertex point of the impulse vertex and of its neighbours.
  const auto x = [&](uint32_t id) { return fine(static_cast<Eigen::Index>(id), 0); };
  EXPECT_NEAR(x(centre), 27.0 / 64.0, 1e-15);
  EXPECT_NEAR(x(g(3, 2, 2)), 9.0 / 128.0, 1e-15);
  EXPECT_NEAR(x(g(2, 1, 2)), 9.0 / 128.0, 1e-15);
  EXPECT_NEAR(x(g(3, 3, 2)), 3.0 / 256.0, 1e-15);
  EXPECT_NEAR(x(g(1, 2, 3)), 3.0 / 256.0, 1e-15);
  EXPECT_NEAR(x(g(3, 3, 3)), 1.0 / 512.0, 1e-15);
  EXPECT_NEAR(x(g(1, 1, 1)), 1.0 / 512.0, 1e-15);
  EXPECT_NEAR(x(g(4, 2, 2)), 0.0, 1e-15);
  // Edge points: x-edges (i,j,k)-(i+1,j,k) at the impulse vertex and next to it.
  EXPECT_NEAR(x(test::edgePointId(t, centre, g(3, 2, 2))), 9.0 / 32.0, 1e-15);
  EXPECT_NEAR(x(test::edgePointId(t, g(2, 3, 2), g(3, 3, 2))), 3.0 / 64.0, 1e-15);
  EXPECT_NEAR(x(test::edgePointId(t, g(1, 2, 1), g(2, 2, 1))), 3.0 / 64.0, 1e-15);
  EXPECT_NEAR(x(test::edgePointId(t, g(2, 3, 3), g(3, 3, 3))), 1.0 / 128.0, 1e-15);
  // Face points: xy-face with the impulse as a corner, and one a layer away.
  EXPECT_NEAR(x(test::facePointId(t, {centre, g(3, 2, 2), g(3, 3, 2), g(2, 3, 2)})), 3.0 / 16.0,
              1e-15);
  EXPECT_NEAR(x(test::facePointId(t, {g(2, 2, 3), g(3, 2, 3), g(3, 3, 3), g(2, 3, 3)})), 1.0 / 32.0,
              1e-15);
  // Cell point of a cell at the impulse vertex.
  const uint32_t cell = static_cast<uint32_t>(2 + n * (2 + n * 2));  // corners (2..3)^3
  EXPECT_NEAR(x(test::cellPointId(t, cell)), 1.0 / 8.0, 1e-15);

  // Full masks from stencil rows (weights of old vertices), with their supports.
  const auto& s = step.stencils;
  EXPECT_EQ(histogram(test::stencilRow(s, centre)),
            expectedHistogram({{27.0 / 64, 1}, {9.0 / 128, 6}, {3.0 / 256, 12}, {1.0 / 512, 8}}));
  EXPECT_EQ(histogram(test::stencilRow(s, test::edgePointId(t, centre, g(3, 2, 2)))),
            expectedHistogram({{9.0 / 32, 2}, {3.0 / 64, 8}, {1.0 / 128, 8}}));
  EXPECT_EQ(histogram(test::stencilRow(
                s, test::facePointId(t, {centre, g(3, 2, 2), g(3, 3, 2), g(2, 3, 2)}))),
            expectedHistogram({{3.0 / 16, 4}, {1.0 / 32, 8}}));
  EXPECT_EQ(histogram(test::stencilRow(s, test::cellPointId(t, cell))),
            expectedHistogram({{1.0 / 8, 8}}));
  // Exact values on the support, e.g. the vertex mask's centre 27/64 and corners 1/512.
  const auto vrow = test::stencilRow(s, centre);
  EXPECT_NEAR(vrow.at(centre), 27.0 / 64.0, 1e-15);
  EXPECT_NEAR(vrow.at(g(1, 2, 2)), 9.0 / 128.0, 1e-15);
  EXPECT_NEAR(vrow.at(g(1, 3, 2)), 3.0 / 256.0, 1e-15);
  EXPECT_NEAR(vrow.at(g(1, 3, 1)), 1.0 / 512.0, 1e-15);
}

}  // namespace
}  // namespace sculpt
