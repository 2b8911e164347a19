// The Display panel's node-gradient scheme reaches what the window draws: with each scheme, the
// GPU-deformed bunny matches the CPU deformer with that scheme on the same frame, and not the CPU
// deformer with the other one.

#include <gtest/gtest.h>

#include <cstdio>
#include <vector>

#include "embed/embedded_deformer.h"
#include "gui/sculpt_session.h"

namespace sculpt::app {
namespace {

/// Largest distance between the view's captured vertices and `expected`, over the diagonal.
double relativeDistance(const std::vector<float>& captured, const Points& expected) {
  double worst = 0.0;
  for (Eigen::Index p = 0; p < expected.rows(); ++p)
    worst = std::max(worst, (Eigen::Vector3d(captured[3 * p], captured[3 * p + 1],
                                             captured[3 * p + 2]) -
                             expected.row(p).transpose())
                                .norm());
  return worst / (expected.colwise().maxCoeff() - expected.colwise().minCoeff()).norm();
}

TEST_F(SculptSession, TheDisplayedNodeGradientsAreTheChosenSchemes) {
  open();
  frames(40);  // the bunny is built, hangs and swings
  ASSERT_TRUE(app_->sceneView().frame().physicsReady);
  // Pull its lowest point well to the side, so that the deformation is far from affine.
  const Points& rest = geometry().restPositions;
  Eigen::Index low = 0;
  rest.col(1).minCoeff(&low);
  app_->model().tools.tool = ToolKind::Pull;
  drag(screen(rest.row(low).transpose() + Eigen::Vector3d(0, 0.3, 0)), 260.0f, 60.0f, 16);
  frames(20);

  const SceneGeometry& g = geometry();
  for (GradientScheme shown : {GradientScheme::Average, GradientScheme::Fit}) {
    app_->model().display.gradients = shown;
    frames(1);
    std::vector<float> positions, normals;
    app_->sceneView().deformer()->capture(positions, normals);
    ASSERT_EQ(positions.size(), 3 * static_cast<size_t>(rest.rows()));
    double distance[2];
    for (GradientScheme scheme : {GradientScheme::Average, GradientScheme::Fit}) {
      DeformerSettings settings;
      settings.gradients = scheme;
      settings.buildAttributeWeights = false;
      EmbeddedDeformer cpu(g.cellMesh, g.restPositions, g.embedding, settings);
      cpu.setFrame(app_->sceneView().frame().nodes, InterpolationMethod::Phong);
      distance[static_cast<int>(scheme)] = relativeDistance(positions, cpu.positions());
    }
    const int same = static_cast<int>(shown), other = 1 - same;
    std::printf("[ measured ] shown %s: distance to the CPU deformer with it %.2e, with the other "
                "scheme %.2e (of the diagonal)\n",
                std::string(gradientSchemeName(shown)).c_str(), distance[same], distance[other]);
    EXPECT_LT(distance[same], 1e-5);
    EXPECT_GT(distance[other], 4.0 * distance[same]);
  }
}

}  // namespace
}  // namespace sculpt::app
