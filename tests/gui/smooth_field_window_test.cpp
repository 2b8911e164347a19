// The smooth field in the window, on the default bunny with a painted stripe of Young's modulus
// (assets/scripts/bunny_paint_stripe.json): the GPU's field values at the surface vertices are
// the CPU's sum_a beta_a v_a over each vertex's cell (embedding cell and local coordinates) of
// the view's node values, and those are the node reconstruction of the frame's cell values. The
// strain energy, new every frame, is reconstructed every frame: its cost is measured.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "embed/cell_coordinates.h"
#include "embed/node_field.h"
#include "gui/sculpt_session.h"

namespace sculpt::app {
namespace {

class SmoothFieldWindow : public SculptSession {
 protected:
  // The default bunny with the stripe painted at t = 0, Young's modulus shown.
  void openStripe() {
    Options options;
    options.headless = true;
    options.width = 1280, options.height = 800;
    options.script = std::string(SCULPT_SOURCE_DIR) + "/assets/scripts/bunny_paint_stripe.json";
    options.display.field = FieldKind::YoungsModulus;
    app_ = std::make_unique<SculptApp>(window_, options, std::chrono::steady_clock::now(),
                                       LoadedPreferences{}, folder_ / "preferences.json");
  }
};

TEST_F(SmoothFieldWindow, GpuValuesOnTheBunnyAreTheInterpolatedNodeValuesOfThePaintedCells) {
  openStripe();
  frames(4);
  ASSERT_TRUE(app_->sceneView().frame().physicsReady);
  const SceneView& view = app_->sceneView();
  const SceneGeometry& g = geometry();
  const std::vector<float>& cells = view.frame().cellYoungs;
  ASSERT_GT(*std::max_element(cells.begin(), cells.end()), 2.9e8f) << "the stripe is painted";
  ASSERT_EQ(*std::min_element(cells.begin(), cells.end()), 3e6f);
  ASSERT_TRUE(app_->model().display.smoothField) << "smooth is the default";

  // The view's node values are the reconstruction of the frame's cell values.
  std::vector<float> expectedNodes;
  nodeFieldFromCells(nodeFieldWeights(g.cellMesh), cells, expectedNodes);
  ASSERT_EQ(view.nodeField(), expectedNodes);

  std::vector<float> gpu;
  view.deformer()->captureField(render::SurfaceField::PerNode, gpu);
  ASSERT_EQ(gpu.size(), g.embedding.numPoints());
  double worst = 0.0;
  size_t between = 0;
  for (uint32_t p = 0; p < g.embedding.numPoints(); ++p) {
    const uint32_t cell = g.embedding.cells[p];
    double beta[8];
    const int count =
        cellNodeWeights(g.cellMesh.isTetrahedron(cell), g.embedding.local.row(p).transpose(), beta);
    double expected = 0.0;
    for (int a = 0; a < count; ++a)
      expected += beta[a] * expectedNodes[g.cellMesh.cells.row(cell)[a]];
    worst = std::max(worst, std::abs(gpu[p] - expected) / 3e8);
    between += gpu[p] > 3.1e6f && gpu[p] < 2.9e8f;
  }
  std::printf(
      "[ measured ] bunny, %u surface vertices: GPU smooth field within %.2e of the range "
      "of the CPU's; %zu vertices between the two moduli\n",
      g.embedding.numPoints(), worst, between);
  EXPECT_LT(worst, 1e-6) << "float precision";
  EXPECT_GT(between, 1000u) << "the stripe's border is graded, not a step";

  // Per cell: the cell's own value at every vertex.
  app_->model().display.smoothField = false;
  frames(1);
  std::vector<float> perCell;
  view.deformer()->captureField(render::SurfaceField::PerCell, perCell);
  for (uint32_t p = 0; p < g.embedding.numPoints(); p += 97)
    ASSERT_EQ(perCell[p], view.frame().cellYoungs[g.embedding.cells[p]]) << "vertex " << p;
}

TEST_F(SmoothFieldWindow, StrainEnergyIsReconstructedEveryFrameWellUnderAMillisecond) {
  openStripe();
  frames(4);
  // The painted modulus does not change while the bunny sways: no reconstruction.
  const SceneView& view = app_->sceneView();
  const uint64_t painted = view.nodeFieldReconstructions();
  EXPECT_GE(painted, 1u);
  frames(5);
  EXPECT_EQ(view.nodeFieldReconstructions(), painted) << "the same cell values, the same nodes";

  app_->model().display.field = FieldKind::StrainEnergy;
  frames(2);
  const uint64_t before = view.nodeFieldReconstructions();
  std::vector<double> ms;
  for (int k = 0; k < 30; ++k) {
    frames(1);
    ms.push_back(view.lastNodeFieldMs());
  }
  EXPECT_EQ(view.nodeFieldReconstructions(), before + 30) << "new strain energy every frame";
  std::sort(ms.begin(), ms.end());
  const SceneGeometry& g = geometry();
  std::printf(
      "[ measured ] node reconstruction on the default bunny (%u nodes, %u cells): median "
      "%.3f ms, max %.3f ms over 30 frames\n",
      g.cellMesh.numNodes(), g.cellMesh.numCells(), ms[ms.size() / 2], ms.back());
  EXPECT_LT(ms[ms.size() / 2], 1.0);
}

}  // namespace
}  // namespace sculpt::app
