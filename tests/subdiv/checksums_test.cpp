// docs/design/mj-subdivision.md §7.3: order-independent checksums over all vertices of the refined
// lattice.

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>

#include "mesh/topology.h"
#include "subdiv/mj_refiner.h"
#include "support/mesh_builders.h"

namespace sculpt {
namespace {

struct ChecksumRow {
  std::string name;
  std::function<CellComplex()> build;
  int steps;
  uint32_t vertices;
  uint32_t cells;
  uint32_t boundaryVertices;
  Eigen::Vector3d sum;
  double sumSquares;
  double sumSquaresTolerance;  ///< absolute (the spec gives some values only to 1e-10)
};

void PrintTo(const ChecksumRow& row, std::ostream* os) { *os << row.name; }

class Checksums : public ::testing::TestWithParam<ChecksumRow> {};

/// |got - expected| <= 1e-10 relative (absolute near 0).
void expectRelative(double got, double expected, const std::string& what) {
  EXPECT_NEAR(got, expected, 1e-10 * std::max(1.0, std::abs(expected))) << what;
}

TEST_P(Checksums, MatchesSection73) {
  const ChecksumRow& row = GetParam();
  const auto s = subdivide(row.build(), row.steps);
  ASSERT_TRUE(s.has_value());
  const CellComplex& fine = s->finest();
  const Topology& t = s->finestTopology();
  EXPECT_EQ(fine.numVertices(), row.vertices);
  EXPECT_EQ(fine.numCells(), row.cells);
  EXPECT_EQ(t.numVertices, row.vertices);
  EXPECT_EQ(t.numCells(), row.cells);
  uint32_t boundary = 0;
  for (uint32_t v = 0; v < t.numVertices; ++v) boundary += t.vertexIsBoundary[v] ? 1u : 0u;
  EXPECT_EQ(boundary, row.boundaryVertices);

  const Eigen::Vector3d sum = fine.positions.colwise().sum().transpose();
  const double squares = fine.positions.squaredNorm();
  expectRelative(sum.x(), row.sum.x(), "sum x");
  expectRelative(sum.y(), row.sum.y(), "sum y");
  expectRelative(sum.z(), row.sum.z(), "sum z");
  EXPECT_NEAR(squares, row.sumSquares, row.sumSquaresTolerance) << "sum of |p|^2";
  // The composed stencils give the same level-K positions.
  Points viaA(static_cast<Eigen::Index>(s->stencils.numRows()), 3);
  s->stencils.apply(s->levels[0].positions, viaA);
  EXPECT_NEAR(viaA.squaredNorm(), row.sumSquares, row.sumSquaresTolerance);
}

Eigen::Vector3d all(double a) { return {a, a, a}; }

const ChecksumRow kRows[] = {
    {"UnitCube1", test::unitCube, 1, 27, 8, 26, all(27.0 / 2), 5827.0 / 216, 1e-10 * 27},
    {"UnitCube2", test::unitCube, 2, 125, 64, 98, all(125.0 / 2), 114977231.0 / 995328,
     1e-10 * 116},
    {"UnitCube3", test::unitCube, 3, 729, 512, 386, all(729.0 / 2), 655.2514101659, 1e-9},
    {"Block2x2x2", [] { return test::hexGrid(2, 2, 2); }, 1, 125, 64, 98, all(125.0),
     115807.0 / 216, 1e-10 * 537},
    {"KuhnCube", test::kuhnCube, 1, 51, 24, 38, all(51.0 / 2), 178447.0 / 3456, 1e-10 * 52},
    {"PrismCube", test::prismCube, 1, 33, 12, 30, all(33.0 / 2), 3120577.0 / 93312, 1e-10 * 34},
    {"PyramidCube",
     [] {
       return test::pyramidCube({0.5, 0.5, 0.75});
     },
     1, 53, 30, 26, Eigen::Vector3d(53.0 / 2, 53.0 / 2, 16297.0 / 576), 51.9505579266, 1e-9},
    {"Tetrahedron", test::regularTet, 1, 15, 4, 14, all(0.0), 1168.0 / 243, 1e-10 * 5},
};

INSTANTIATE_TEST_SUITE_P(Section73, Checksums, ::testing::ValuesIn(kRows),
                         [](const auto& param) { return param.param.name; });

}  // namespace
}  // namespace sculpt
