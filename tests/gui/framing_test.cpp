// F and Home in the real window: the framed sphere is measured on screen, by projecting points
// spread over it and taking the widest, as a person would hold a ruler to the view.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/gtc/constants.hpp>

#include "sculpt_session.h"

namespace sculpt::app {
namespace {

class FramingTest : public SculptSession {
 protected:
  // The on-screen diameter of a sphere over the view's shorter side (its outline is sampled by
  // 20,000 points: within 0.1 % of the true outline).
  double projectedFill(const glm::vec3& centre, float radius) const {
    const ViewRect view = app_->viewRect();
    const float w = view.max.x - view.min.x, h = view.max.y - view.min.y;
    const int count = 20000;
    const float golden = glm::pi<float>() * (3.0f - std::sqrt(5.0f));
    float lowX = 1e30f, highX = -1e30f, lowY = 1e30f, highY = -1e30f;
    for (int i = 0; i < count; ++i) {
      const float y = 1.0f - 2.0f * (static_cast<float>(i) + 0.5f) / static_cast<float>(count);
      const float r = std::sqrt(1.0f - y * y), phi = golden * static_cast<float>(i);
      const glm::vec3 p = centre + radius * glm::vec3(r * std::cos(phi), y, r * std::sin(phi));
      const glm::vec3 s = app_->camera().project(p, static_cast<int>(w), static_cast<int>(h));
      lowX = std::min(lowX, s.x), highX = std::max(highX, s.x);
      lowY = std::min(lowY, s.y), highY = std::max(highY, s.y);
    }
    return w < h ? (highX - lowX) / w : (highY - lowY) / h;
  }
};

TEST_F(FramingTest, FFramesTheModelsBoundingSphereToEightyPercentOfTheShorterSide) {
  open();
  frames(3);
  ASSERT_TRUE(app_->sceneView().hasGeometry());
  const glm::vec3 centre = app_->sceneView().centre();
  const float radius = app_->sceneView().radius();
  const double atStart = projectedFill(centre, radius);
  // Move away: orbit, zoom out and pan, then F over the view.
  app_->camera().setOrientation(2.0f, -0.6f);
  app_->camera().zoom(3.0f);
  app_->camera().pan(200.0f, -80.0f, 600);
  frames(1);
  const double away = projectedFill(app_->camera().pivot(), radius);
  const ViewRect view = app_->viewRect();
  pointer_.x = 0.5f * (view.min.x + view.max.x), pointer_.y = 0.5f * (view.min.y + view.max.y);
  press(GLFW_KEY_F, false);
  const double framed = projectedFill(centre, radius);
  std::printf(
      "[ framing ] view %.0f x %.0f px: sphere fills %.3f at start, %.3f moved away, "
      "%.3f after F\n",
      view.max.x - view.min.x, view.max.y - view.min.y, atStart, away, framed);
  EXPECT_EQ(app_->camera().pivot(), centre);
  EXPECT_GE(framed, 0.7);
  EXPECT_LE(framed, 0.9);
  EXPECT_NEAR(framed, atStart, 0.01) << "F frames as the start does";
  EXPECT_LT(away, 0.5) << "the test moved the camera away before pressing F";
}

TEST_F(FramingTest, HomeFramesTheModelAndItsCageTogether) {
  open();
  frames(3);
  ASSERT_TRUE(app_->sceneView().hasGeometry());
  app_->camera().zoom(0.2f);
  const ViewRect view = app_->viewRect();
  pointer_.x = 0.5f * (view.min.x + view.max.x), pointer_.y = 0.5f * (view.min.y + view.max.y);
  press(GLFW_KEY_HOME, false);
  // The sphere around the model's box and every control point of the cage.
  const Points& control = app_->sceneView().frame().control;
  ASSERT_GT(control.rows(), 0);
  glm::vec3 low = app_->sceneView().boxLow(), high = app_->sceneView().boxHigh();
  for (Eigen::Index i = 0; i < control.rows(); ++i) {
    const glm::vec3 p(control(i, 0), control(i, 1), control(i, 2));
    low = glm::min(low, p), high = glm::max(high, p);
  }
  const glm::vec3 centre = 0.5f * (low + high);
  const float radius = 0.5f * glm::length(high - low);
  EXPECT_GT(radius, app_->sceneView().radius()) << "the cage reaches beyond the surface";
  const double framed = projectedFill(centre, radius);
  std::printf("[ framing ] Home: the model and cage sphere fills %.3f\n", framed);
  EXPECT_GE(framed, 0.7);
  EXPECT_LE(framed, 0.9);
}

}  // namespace
}  // namespace sculpt::app
