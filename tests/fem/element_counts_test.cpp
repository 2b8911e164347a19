// Element types per cell (paper section 3.4, Table 1 columns %BE / %LE / %PE) against counts
// derived by hand from the regularity rule of core/subdiv/regularity.h: a level-K hexahedron is
// tricubic when its 8 corners are interior, have 8 incident hexahedra and 6 edges, each edge
// with 4 cells. On an n1 x n2 x n3 box of hexes at level K the lattice has m_i = n_i 2^K cells
// along each axis, the interior vertices have lattice indices 1..m_i - 1, so a cell (index
// 0..m_i - 1) is regular when its indices are 1..m_i - 2: (m1 - 2)(m2 - 2)(m3 - 2) cells.

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>

#include "fem/fem_mesh.h"
#include "fem/fem_model.h"
#include "io/control_mesh_json.h"
#include "subdiv/regularity.h"
#include "support/mesh_builders.h"

namespace sculpt {
namespace {

using namespace sculpt::test;

std::optional<FemModel> makeModel(const CellComplex& control, int level, bool trilinear = false) {
  std::string error;
  auto model = FemModel::create(control, FemSetup{level, trilinear, Material{}}, &error);
  EXPECT_TRUE(model.has_value()) << error;
  return model;
}

uint32_t boxTricubic(int n1, int n2, int n3, int level) {
  auto inner = [level](int n) { return uint32_t(std::max(0, (n << level) - 2)); };
  return inner(n1) * inner(n2) * inner(n3);
}

TEST(ElementCounts, Block3AtLevel2) {
  const CellComplex control =
      loadControlMeshJson(std::filesystem::path(SCULPT_SOURCE_DIR) / "assets" / "block3.json");
  ASSERT_EQ(control.numCells(), 27u);
  auto model = makeModel(control, 2);
  ASSERT_TRUE(model);
  const ElementCounts c = model->mesh().counts();
  EXPECT_EQ(c.total(), 1728u);   // 27 cells * 8^2 children
  EXPECT_EQ(c.tricubic, 1000u);  // cells 1..10 of the 12^3 lattice in each direction
  EXPECT_EQ(c.trilinear, 728u);  // the two outer layers: 12^3 - 10^3
  EXPECT_EQ(c.pyramid, 0u);
  EXPECT_EQ(boxTricubic(3, 3, 3, 2), 1000u);
  // Independent of the element builder: the cell classification of the level-2 topology.
  uint32_t regular = 0;
  for (CellRegularity r : classifyCells(model->subdivision().finestTopology()))
    regular += r == CellRegularity::Regular;
  EXPECT_EQ(regular, 1000u);
  // Tricubic elements come first and every one is on a distinct cell.
  for (uint32_t e = 0; e < c.tricubic; ++e)
    EXPECT_EQ(model->mesh().elementType[e], ElementType::Tricubic);
  const double n = c.total();
  std::printf(
      "block3 level 2: %u elements: %%BE %.1f (%u tricubic), %%LE %.1f (%u trilinear), "
      "%%PE %.1f (%u pyramid); %u nodes, %u control points, %u Gauss points\n",
      c.total(), 100.0 * c.tricubic / n, c.tricubic, 100.0 * c.trilinear / n, c.trilinear,
      100.0 * c.pyramid / n, c.pyramid, model->numNodes(), model->numControlPoints(),
      model->mesh().numGaussPoints());
  RecordProperty("block3_percent_BE", std::to_string(100.0 * c.tricubic / n));
  RecordProperty("block3_percent_LE", std::to_string(100.0 * c.trilinear / n));
  RecordProperty("block3_percent_PE", std::to_string(100.0 * c.pyramid / n));
}

TEST(ElementCounts, BoxGridsFollowTheInteriorRule) {
  struct Case {
    int n1, n2, n3, level;
  };
  for (const Case& k : {Case{1, 1, 1, 1}, Case{1, 1, 1, 2}, Case{2, 1, 1, 2}, Case{2, 2, 2, 1},
                        Case{2, 2, 2, 2}, Case{1, 1, 1, 3}}) {
    auto model = makeModel(hexGrid(k.n1, k.n2, k.n3), k.level);
    ASSERT_TRUE(model);
    const ElementCounts c = model->mesh().counts();
    const uint32_t cells = uint32_t(k.n1 * k.n2 * k.n3) << (3 * k.level);
    EXPECT_EQ(c.total(), cells);
    EXPECT_EQ(c.tricubic, boxTricubic(k.n1, k.n2, k.n3, k.level))
        << k.n1 << "x" << k.n2 << "x" << k.n3 << " level " << k.level;
    EXPECT_EQ(c.trilinear, cells - c.tricubic);
    EXPECT_EQ(c.pyramid, 0u);
  }
}

TEST(ElementCounts, TrilinearModeHasNoTricubicElements) {
  auto model = makeModel(hexGrid(4, 4, 4), 0, true);
  ASSERT_TRUE(model);
  EXPECT_EQ(model->mesh().counts().tricubic, 0u);
  EXPECT_EQ(model->mesh().counts().trilinear, 64u);
  EXPECT_EQ(model->numNodes(), 125u);  // A = I: the control points themselves
}

TEST(ElementCounts, IrregularCellsBecomePyramids) {
  // An octahedron: at level 1 MJ makes 6 square trapezohedra (one per valence-4 corner), each
  // with 8 quadrilateral faces, so 6 * 8 pyramids around 6 virtual centre nodes.
  auto octa = makeModel(octahedron(), 1);
  ASSERT_TRUE(octa);
  const ElementCounts oc = octa->mesh().counts();
  EXPECT_EQ(oc.pyramid, 48u);
  EXPECT_EQ(oc.total(), 48u);
  EXPECT_EQ(octa->numNodes(), octa->mesh().numLatticeNodes + 6);
  // Pyramid slots 4-7 repeat the virtual apex; slots 0-3 are lattice nodes.
  for (const auto& nodes : octa->mesh().linearNodes) {
    EXPECT_GE(nodes[4], octa->mesh().numLatticeNodes);
    EXPECT_TRUE(nodes[4] == nodes[5] && nodes[5] == nodes[6] && nodes[6] == nodes[7]);
    for (int a = 0; a < 4; ++a) EXPECT_LT(nodes[size_t(a)], octa->mesh().numLatticeNodes);
  }
  // The mixed mesh (2 hexes, 2 prisms, 2 pyramids): in a pyramid cell only the apex has valence
  // 4 (prisms only have valence-3 corners), so level 1 has one square trapezohedron (8 pyramid
  // elements) per apex. That trapezohedron has two valence-4 poles (the apex and the pyramid's
  // cell point, which joins the 4 face points of the triangles), so level 2 has two per apex.
  for (int level = 1; level <= 2; ++level) {
    auto mixed = makeModel(mixedMesh(), level);
    ASSERT_TRUE(mixed);
    const ElementCounts mc = mixed->mesh().counts();
    EXPECT_EQ(mc.pyramid, 16u * uint32_t(level)) << "level " << level;
    std::printf("mixed mesh level %d: %u tricubic, %u trilinear, %u pyramid\n", level, mc.tricubic,
                mc.trilinear, mc.pyramid);
  }
}

}  // namespace
}  // namespace sculpt
