// The cost estimate that commands check before they refine: exact counts, stencil entries close
// to what subdivide() builds (the quadratic growth of wide cells included), and the refusal
// sentence against a given or an injected amount of memory.

#include "subdiv/refinement_cost.h"

#include <gtest/gtest.h>

#include <string>

#include "mesh/topology.h"
#include "subdiv/mj_refiner.h"
#include "support/mesh_builders.h"
#include "support/scoped_environment.h"
#include "util/available_memory.h"

namespace sculpt {
namespace {

constexpr uint64_t kGB = 1'000'000'000;

using test::ScopedEnvironment;

TEST(RefinementCost, CountsMatchTheRefinementExactly) {
  for (const CellComplex& mesh :
       {test::hexGrid(3, 2, 2), test::ngonPrism(12), test::singlePyramid(), test::regularTet()}) {
    const Topology topology = buildTopology(mesh);
    for (int levels = 0; levels <= 3; ++levels) {
      SCOPED_TRACE(levels);
      const RefinementCost cost = estimateRefinementCost(topology, levels);
      const std::optional<Subdivision> refined = subdivide(mesh, levels);
      ASSERT_TRUE(refined);
      EXPECT_EQ(cost.cells, refined->finest().numCells());
      EXPECT_EQ(cost.vertices, refined->finest().numVertices());
    }
  }
}

TEST(RefinementCost, StencilEntriesAreCloseToTheComposedTable) {
  for (const CellComplex& mesh : {test::hexGrid(4, 4, 4), test::ngonPrism(60)}) {
    const Topology topology = buildTopology(mesh);
    for (int levels = 1; levels <= 3; ++levels) {
      SCOPED_TRACE(levels);
      const double estimate = double(estimateRefinementCost(topology, levels).stencilEntries);
      const double actual = double(subdivide(mesh, levels)->stencils.numEntries());
      EXPECT_GT(estimate, 0.6 * actual);
      EXPECT_LT(estimate, 1.7 * actual);
    }
  }
}

TEST(RefinementCost, WideCellsCostQuadratically) {
  // Twice the sides: four times the entries, and cell 0 is named as the reason.
  const RefinementCost small = estimateRefinementCost(buildTopology(test::ngonPrism(500)), 2);
  const RefinementCost large = estimateRefinementCost(buildTopology(test::ngonPrism(1000)), 2);
  EXPECT_GT(double(large.stencilEntries), 3.5 * double(small.stencilEntries));
  EXPECT_EQ(large.widestCell, 0u);
  EXPECT_EQ(large.widestCellFaces, 1002u);
  EXPECT_EQ(large.widestCellVertices, 2000u);
  EXPECT_GT(large.widestCellBytes * 2, large.bytes);
  // A hexahedral block has no wide element.
  EXPECT_EQ(estimateRefinementCost(buildTopology(test::hexGrid(3, 3, 3)), 2).widestCellBytes, 0u);
}

TEST(RefinementCost, WorkOnTheCellsAddsToTheRefinement) {
  const Topology topology = buildTopology(test::hexGrid(3, 3, 3));
  const uint64_t refine = estimateRefinementCost(topology, 2).bytes;
  const uint64_t elements = estimateRefinementCost(topology, 2, kFiniteElements).bytes;
  const uint64_t simulation = estimateRefinementCost(topology, 2, kSimulation).bytes;
  EXPECT_LT(refine, elements);
  EXPECT_LT(elements, simulation);
  // 1728 cells at about 40 kB each (measured: 73 MB for `simulate block3.json --levels 2`).
  EXPECT_GT(simulation, 50'000'000u);
  EXPECT_LT(simulation, 110'000'000u);
}

TEST(RefinementCost, RefusalNamesTheLevelTheNeedAndTheCell) {
  const Topology block = buildTopology(test::hexGrid(10, 10, 10));
  const RefinementCost cost = estimateRefinementCost(block, 4);
  EXPECT_EQ(cost.cells, 4'096'000u);
  EXPECT_EQ(refinementRefusal(cost, "block10.json", 100 * kGB), "");
  const std::string refusal = refinementRefusal(cost, "block10.json", 2 * kGB);
  EXPECT_EQ(refusal.rfind("level 4 of block10.json needs about ", 0), 0u) << refusal;
  EXPECT_NE(refusal.find(" GB (4,096,000 cells); this machine has 2.0 GB available"),
            std::string::npos)
      << refusal;

  const RefinementCost prism = estimateRefinementCost(buildTopology(test::ngonPrism(2000)), 2);
  const std::string wide = refinementRefusal(prism, "prism.json", kGB);
  EXPECT_NE(wide.find("level 2 of prism.json needs about "), std::string::npos) << wide;
  EXPECT_NE(wide.find("cell 0 (2002 faces, 4000 vertices) alone takes about "), std::string::npos)
      << wide;

  // Far more cells than vertex ids allow, whatever the memory.
  const RefinementCost huge = estimateRefinementCost(block, 6);
  EXPECT_NE(refinementRefusal(huge, "b.json", UINT64_MAX).find("(more than 50000000)"),
            std::string::npos);
}

TEST(RefinementCost, TheEnvironmentSetsTheAvailableMemory) {
  const Topology block = buildTopology(test::hexGrid(10, 10, 10));
  {
    ScopedEnvironment limit("SCULPT_MEMORY_LIMIT_MB", "100");
    EXPECT_EQ(availableMemoryBytes(), 100u << 20);
    const std::string refusal = refinementRefusal(block, 2, "block10.json");
    EXPECT_NE(refusal.find("; SCULPT_MEMORY_LIMIT_MB allows 105 MB; use fewer levels"),
              std::string::npos)
        << refusal;
  }
  {
    ScopedEnvironment limit("SCULPT_MEMORY_LIMIT_MB", "100000");
    EXPECT_EQ(refinementRefusal(block, 2, "block10.json"), "");
  }
  ScopedEnvironment junk("SCULPT_MEMORY_LIMIT_MB", "lots");
  EXPECT_NE(availableMemoryBytes(), 0u);  // measured instead
}

TEST(RefinementCost, MemoryTextIsShort) {
  EXPECT_EQ(memoryText(3'700'000'000), "3.7 GB");
  EXPECT_EQ(memoryText(350'000'000), "350 MB");
  EXPECT_EQ(memoryText(12'345), "12 kB");
  EXPECT_EQ(groupedNumber(1'230'000), "1,230,000");
  EXPECT_EQ(groupedNumber(999), "999");
}

}  // namespace
}  // namespace sculpt
