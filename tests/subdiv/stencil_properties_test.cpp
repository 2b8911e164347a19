// Properties of the stencil table A = S_K ... S_1 of a subdivision: rows sum to 1, A p equals
// the refined positions and the factored chain, A^T is the transpose, the map is affine
// invariant (creases and corners included), and progress reporting can cancel.

#include <gtest/gtest.h>

#include <functional>
#include <random>
#include <string>
#include <vector>

#include "mesh/topology.h"
#include "subdiv/mj_refiner.h"
#include "subdiv/stencil_table.h"
#include "support/mesh_builders.h"
#include "util/progress.h"

namespace sculpt {
namespace {

using test::jittered;
using test::NamedMesh;
using test::taggedMixed;

const NamedMesh kMeshes[] = {
    {"UnitCube", test::unitCube},
    {"Block3x2x2Jittered", [] { return jittered(test::hexGrid(3, 2, 2), 0.1, 3); }},
    {"KuhnCube", test::kuhnCube},
    {"PyramidCube",
     [] {
       return test::pyramidCube({0.5, 0.5, 0.75});
     }},
    {"PrismCube", test::prismCube},
    {"Octahedron", test::octahedron},
    {"MixedJittered", [] { return jittered(test::mixedMesh(), 0.05, 13); }},
    {"MixedTagged", taggedMixed},
};

class StencilMeshes : public ::testing::TestWithParam<NamedMesh> {};

Points randomPoints(uint32_t rows, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> uni(-1.0, 1.0);
  Points p(static_cast<Eigen::Index>(rows), 3);
  for (Eigen::Index i = 0; i < p.rows(); ++i)
    for (Eigen::Index d = 0; d < 3; ++d) p(i, d) = uni(rng);
  return p;
}

TEST_P(StencilMeshes, RowsSumToOneAndReproduceLevels) {
  const CellComplex control = GetParam().build();
  for (int levels = 1; levels <= 3; ++levels) {
    SCOPED_TRACE("levels " + std::to_string(levels));
    const auto s = subdivide(control, levels);
    ASSERT_TRUE(s.has_value());
    const StencilTable& A = s->stencils;
    ASSERT_EQ(A.numColumns(), control.numVertices());
    ASSERT_EQ(A.numRows(), s->finest().numVertices());
    ASSERT_EQ(s->levels.size(), static_cast<size_t>(levels + 1));
    ASSERT_EQ(s->topologies.size(), static_cast<size_t>(levels + 1));
    ASSERT_EQ(s->chain.levels().size(), static_cast<size_t>(levels));
    EXPECT_EQ(s->chain.numRows(), A.numRows());
    EXPECT_EQ(s->chain.numColumns(), A.numColumns());
    EXPECT_EQ(s->levels[0].positions, control.positions);

    // Row sums, by rowSums() and by hand.
    const auto sums = A.rowSums();
    ASSERT_EQ(sums.size(), A.numRows());
    for (uint32_t r = 0; r < A.numRows(); ++r) {
      double own = 0.0;
      for (uint32_t i = A.offsets()[r]; i < A.offsets()[r + 1]; ++i) {
        own += A.weights()[i];
        ASSERT_LT(A.indices()[i], A.numColumns());
      }
      EXPECT_NEAR(own, 1.0, 1e-12) << "row " << r;
      EXPECT_NEAR(sums[r], own, 1e-14) << "row " << r;
    }
    // Each per-level table also has unit row sums.
    for (const StencilTable& S : s->chain.levels())
      for (double sum : S.rowSums()) ASSERT_NEAR(sum, 1.0, 1e-12);

    // A p == level-K positions == chain apply == per-level application.
    Points viaA(static_cast<Eigen::Index>(A.numRows()), 3);
    A.apply(control.positions, viaA);
    Points viaChain(static_cast<Eigen::Index>(A.numRows()), 3);
    s->chain.apply(control.positions, viaChain);
    Points stepwise = control.positions;
    for (const StencilTable& S : s->chain.levels()) {
      Points next(static_cast<Eigen::Index>(S.numRows()), 3);
      S.apply(stepwise, next);
      stepwise = next;
    }
    const Points& finest = s->finest().positions;
    ASSERT_EQ(finest.rows(), viaA.rows());
    const double scale = 1.0 + control.positions.cwiseAbs().maxCoeff();
    EXPECT_LE((viaA - finest).cwiseAbs().maxCoeff(), 1e-12 * scale);
    EXPECT_LE((viaChain - finest).cwiseAbs().maxCoeff(), 1e-12 * scale);
    EXPECT_LE((stepwise - finest).cwiseAbs().maxCoeff(), 1e-12 * scale);
    // Intermediate levels are the partial products.
    Points partial = control.positions;
    for (int k = 1; k <= levels; ++k) {
      const StencilTable& S = s->chain.levels()[static_cast<size_t>(k - 1)];
      Points next(static_cast<Eigen::Index>(S.numRows()), 3);
      S.apply(partial, next);
      partial = next;
      EXPECT_LE((partial - s->levels[static_cast<size_t>(k)].positions).cwiseAbs().maxCoeff(),
                1e-12 * scale)
          << "level " << k;
    }
  }
}

TEST_P(StencilMeshes, TransposeIsTheAdjoint) {
  const auto s = subdivide(GetParam().build(), 2);
  ASSERT_TRUE(s.has_value());
  const StencilTable& A = s->stencils;
  const Points x = randomPoints(A.numColumns(), 1);
  const Points y = randomPoints(A.numRows(), 2);
  Points Ax(static_cast<Eigen::Index>(A.numRows()), 3);
  A.apply(x, Ax);
  Points Aty(static_cast<Eigen::Index>(A.numColumns()), 3);
  A.applyTranspose(y, Aty);
  ASSERT_EQ(Aty.rows(), static_cast<Eigen::Index>(A.numColumns()));
  // Component-wise: <A x_d, y_d> = <x_d, A^T y_d> for each coordinate d.
  for (Eigen::Index d = 0; d < 3; ++d) {
    const double lhs = Ax.col(d).dot(y.col(d));
    const double rhs = x.col(d).dot(Aty.col(d));
    EXPECT_NEAR(lhs, rhs, 1e-10 * (1.0 + std::abs(lhs))) << "coordinate " << d;
  }
  // And explicitly against a dense transpose built from the rows.
  Points dense = Points::Zero(static_cast<Eigen::Index>(A.numColumns()), 3);
  for (uint32_t r = 0; r < A.numRows(); ++r)
    for (uint32_t i = A.offsets()[r]; i < A.offsets()[r + 1]; ++i)
      dense.row(A.indices()[i]) += A.weights()[i] * y.row(static_cast<Eigen::Index>(r));
  EXPECT_LE((dense - Aty).cwiseAbs().maxCoeff(), 1e-11);
}

// refine(T p) == T refine(p) for an affine T (rotation, anisotropic scale, translation).
TEST_P(StencilMeshes, AffineInvariance) {
  const CellComplex control = GetParam().build();
  std::mt19937_64 rng(77);
  const Eigen::Matrix3d R = test::randomRotation(rng);
  const Eigen::Matrix3d S = Eigen::Vector3d(1.7, 0.6, 2.3).asDiagonal();
  const Eigen::Matrix3d L = R * S * test::randomRotation(rng);
  ASSERT_GT(L.determinant(), 0.0);  // keeps cells positively oriented
  const Eigen::RowVector3d t(3.5, -2.25, 10.0);
  CellComplex moved = control;
  moved.positions = (control.positions * L.transpose()).rowwise() + t;
  const auto a = subdivide(control, 2);
  const auto b = subdivide(moved, 2);
  ASSERT_TRUE(a.has_value());
  ASSERT_TRUE(b.has_value());
  const Points expected = (a->finest().positions * L.transpose()).rowwise() + t;
  ASSERT_EQ(expected.rows(), b->finest().positions.rows());
  const double scale = 1.0 + expected.cwiseAbs().maxCoeff();
  EXPECT_LE((b->finest().positions - expected).cwiseAbs().maxCoeff(), 1e-12 * scale);
  // The stencils themselves do not depend on positions.
  EXPECT_EQ(a->stencils.indices(), b->stencils.indices());
  ASSERT_EQ(a->stencils.weights().size(), b->stencils.weights().size());
  for (size_t i = 0; i < a->stencils.weights().size(); ++i)
    ASSERT_EQ(a->stencils.weights()[i], b->stencils.weights()[i]);
}

INSTANTIATE_TEST_SUITE_P(Meshes, StencilMeshes, ::testing::ValuesIn(kMeshes),
                         [](const auto& p) { return p.param.name; });

// Tags change the result (so the tagged affine test exercises the crease rules) and tags are
// inherited by the children (§3.2).
TEST(StencilTags, CreasesAreInheritedAndPinCorners) {
  const CellComplex tagged = taggedMixed();
  CellComplex plain = tagged;
  plain.creases.clear();
  plain.corners.clear();
  const auto a = subdivide(tagged, 2);
  const auto b = subdivide(plain, 2);
  ASSERT_TRUE(a.has_value() && b.has_value());
  EXPECT_GT((a->finest().positions - b->finest().positions).cwiseAbs().maxCoeff(), 1e-3);
  // Corners are pinned at every level.
  for (uint32_t corner : tagged.corners)
    for (const CellComplex& level : a->levels)
      EXPECT_LE((test::pos(level, corner) - test::pos(tagged, corner)).norm(), 1e-14);
  // Level 1: the two halves of every crease are creases, 2 per crease edge; the corners remain.
  const Topology& t0 = a->topologies[0];
  const Topology& t1 = a->topologies[1];
  for (const auto& [x, y] : tagged.creases) {
    const uint32_t ep = test::edgePointId(t0, x, y);
    ASSERT_NE(ep, UINT32_MAX);
    for (uint32_t end : {x, y}) {
      const int64_t half = t1.findEdge(end, ep);
      ASSERT_GE(half, 0);
      EXPECT_TRUE(t1.edgeIsCrease[static_cast<size_t>(half)]);
    }
  }
  uint32_t creases0 = 0, creases1 = 0, creases2 = 0;
  for (uint8_t c : t0.edgeIsCrease) creases0 += c ? 1u : 0u;
  for (uint8_t c : t1.edgeIsCrease) creases1 += c ? 1u : 0u;
  for (uint8_t c : a->topologies[2].edgeIsCrease) creases2 += c ? 1u : 0u;
  EXPECT_EQ(creases0, 5u);
  EXPECT_EQ(creases1, 10u);
  EXPECT_EQ(creases2, 20u);
  EXPECT_EQ(a->levels[1].creases.size(), 10u);
  EXPECT_EQ(a->levels[2].creases.size(), 20u);
  for (const CellComplex& level : a->levels) EXPECT_EQ(level.corners.size(), 2u);
  for (const Topology& t : a->topologies) {
    uint32_t corners = 0;
    for (uint8_t c : t.vertexIsCorner) corners += c ? 1u : 0u;
    EXPECT_EQ(corners, 2u);
  }
  // Crease edge points are midpoints (§3.2).
  const Points& p1 = a->levels[1].positions;
  for (const auto& [x, y] : tagged.creases) {
    const Eigen::Vector3d mid = 0.5 * (test::pos(tagged, x) + test::pos(tagged, y));
    EXPECT_LE((test::pos(p1, test::edgePointId(t0, x, y)) - mid).norm(), 1e-14);
  }
}

TEST(StencilTable, IdentityComposeAndSums) {
  const StencilTable I = StencilTable::identity(5);
  EXPECT_EQ(I.numRows(), 5u);
  EXPECT_EQ(I.numColumns(), 5u);
  const Points p = randomPoints(5, 9);
  Points q(5, 3);
  I.apply(p, q);
  EXPECT_EQ(p, q);
  // A 3 x 2 table and a 2 x 4 table, composed, equal applying both in turn.
  const StencilTable inner(4, {0, 2, 5}, {0, 3, 1, 2, 3}, {0.25, 0.75, 0.5, 0.25, 0.25});
  const StencilTable outer(2, {0, 1, 3, 5}, {1, 0, 1, 1, 0}, {1.0, 0.5, 0.5, 0.375, 0.625});
  const StencilTable both = StencilTable::compose(outer, inner);
  EXPECT_EQ(both.numRows(), 3u);
  EXPECT_EQ(both.numColumns(), 4u);
  const Points x = randomPoints(4, 10);
  Points mid(2, 3), twoSteps(3, 3), oneStep(3, 3);
  inner.apply(x, mid);
  outer.apply(mid, twoSteps);
  both.apply(x, oneStep);
  EXPECT_LE((twoSteps - oneStep).cwiseAbs().maxCoeff(), 1e-15);
  // Rows merged and sorted by column: no duplicates.
  for (uint32_t r = 0; r < both.numRows(); ++r)
    for (uint32_t i = both.offsets()[r] + 1; i < both.offsets()[r + 1]; ++i)
      EXPECT_LT(both.indices()[i - 1], both.indices()[i]);
  for (double s : both.rowSums()) EXPECT_NEAR(s, 1.0, 1e-15);
}

TEST(Progress, CallbackIsCalledAndCanCancel) {
  const CellComplex control = test::hexGrid(2, 2, 2);
  int calls = 0;
  bool inRange = true;
  ProgressReporter reporter([&](double fraction, std::string_view) {
    ++calls;
    inRange = inRange && fraction >= 0.0 && fraction <= 1.0;
    return true;
  });
  const auto s = subdivide(control, 3, &reporter);
  ASSERT_TRUE(s.has_value());
  EXPECT_GE(calls, 3);  // at least once per level
  EXPECT_TRUE(inRange);
  EXPECT_FALSE(reporter.cancelled());

  // Returning false at the first call cancels.
  int cancelCalls = 0;
  ProgressReporter cancelFirst([&](double, std::string_view) {
    ++cancelCalls;
    return false;
  });
  EXPECT_FALSE(subdivide(control, 3, &cancelFirst).has_value());
  EXPECT_GE(cancelCalls, 1);
  EXPECT_TRUE(cancelFirst.cancelled());

  // Cancelling later (after the first report) also gives nullopt.
  int lateCalls = 0;
  ProgressReporter cancelLate([&](double, std::string_view) { return ++lateCalls < 2; });
  EXPECT_FALSE(subdivide(control, 3, &cancelLate).has_value());
  EXPECT_EQ(lateCalls, 2);

  // No reporter: never cancelled.
  EXPECT_TRUE(subdivide(control, 1, nullptr).has_value());
}

}  // namespace
}  // namespace sculpt
