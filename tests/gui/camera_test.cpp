// The orbit camera (render/camera.h) against geometry worked out independently: framing keeps a
// box and its bounding sphere inside the view for several aspects in both projections, orbit
// keeps the distance, pan moves a point at the pivot's depth exactly with the cursor, the
// orthographic toggle keeps the scale at the pivot, standard views look along the axes, and
// unproject inverts project. No OpenGL needed.

#include "render/camera.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <optional>
#include <random>
#include <stdexcept>
#include <vector>

namespace sculpt::render {
namespace {

constexpr float kAspects[] = {0.5f, 1.0f, 2.5f};

/// Normalized device coordinates of a world point through the camera's float matrices (what
/// OpenGL gets).
glm::vec3 ndc(const Camera& camera, float aspect, const glm::vec3& p) {
  const glm::vec4 clip = camera.projection(aspect) * camera.view() * glm::vec4(p, 1.0f);
  EXPECT_GT(clip.w, 0.0f) << "point behind the eye";
  return glm::vec3(clip) / clip.w;
}

/// Points spread evenly over a sphere (Fibonacci lattice).
std::vector<glm::vec3> spherePoints(const glm::vec3& centre, float radius, int count) {
  std::vector<glm::vec3> points;
  const float golden = glm::pi<float>() * (3.0f - std::sqrt(5.0f));
  for (int i = 0; i < count; ++i) {
    const float y = 1.0f - 2.0f * (static_cast<float>(i) + 0.5f) / static_cast<float>(count);
    const float r = std::sqrt(1.0f - y * y);
    const float phi = golden * static_cast<float>(i);
    points.push_back(centre + radius * glm::vec3(r * std::cos(phi), y, r * std::sin(phi)));
  }
  return points;
}

float relativeError(const glm::vec3& a, const glm::vec3& b, float scale) {
  return glm::length(a - b) / scale;
}

TEST(Camera, FramedBoxAndItsBoundingSphereFitTheViewForEveryAspectAndProjection) {
  const glm::vec3 lo(-1.0f, 2.0f, -0.5f), hi(3.0f, 2.5f, 1.5f);
  const glm::vec3 centre = 0.5f * (lo + hi);
  const float radius = 0.5f * glm::length(hi - lo);
  std::vector<glm::vec3> points = spherePoints(centre, radius, 400);
  for (int c = 0; c < 8; ++c)
    points.push_back({c & 1 ? hi.x : lo.x, c & 2 ? hi.y : lo.y, c & 4 ? hi.z : lo.z});
  for (const float aspect : kAspects)
    for (const bool orthographic : {false, true})
      for (const float yaw : {0.0f, 0.7f, -2.4f})
        for (const float pitch : {0.0f, 0.4f, -1.2f, glm::half_pi<float>()}) {
          Camera camera;
          camera.setOrthographic(orthographic);
          camera.setOrientation(yaw, pitch);
          camera.frame(centre, radius, aspect);
          EXPECT_EQ(camera.pivot(), centre);
          float extent = 0.0f;  // largest |ndc| reached along the tighter axis
          for (const glm::vec3& p : points) {
            const glm::vec3 q = ndc(camera, aspect, p);
            EXPECT_LE(std::abs(q.x), 1.0f) << "aspect " << aspect << " ortho " << orthographic;
            EXPECT_LE(std::abs(q.y), 1.0f) << "aspect " << aspect << " ortho " << orthographic;
            EXPECT_GT(q.z, -1.0f) << "clipped by the near plane";
            EXPECT_LT(q.z, 1.0f) << "clipped by the far plane";
            extent = std::max(extent, aspect < 1.0f ? std::abs(q.x) : std::abs(q.y));
          }
          // Framed, not lost in the distance: the sphere's outline spans 80 % of the tighter
          // direction in both projections (its 400 samples reach within 1 % of the outline).
          EXPECT_LE(extent, 0.8f + 1e-4f) << "aspect " << aspect << " ortho " << orthographic;
          EXPECT_GT(extent, 0.79f) << "aspect " << aspect << " ortho " << orthographic;
        }
}

TEST(Camera, FrameRejectsBadInput) {
  Camera camera;
  EXPECT_THROW(camera.frame(glm::vec3(0.0f), 0.0f, 1.0f), std::invalid_argument);
  EXPECT_THROW(camera.frame(glm::vec3(0.0f), -1.0f, 1.0f), std::invalid_argument);
  EXPECT_THROW(camera.frame(glm::vec3(0.0f), 1.0f, 0.0f), std::invalid_argument);
  EXPECT_THROW(camera.frame(glm::vec3(NAN, 0.0f, 0.0f), 1.0f, 1.0f), std::invalid_argument);
  EXPECT_THROW(camera.projection(-1.0f), std::invalid_argument);
  EXPECT_THROW(camera.zoom(0.0f), std::invalid_argument);
  EXPECT_THROW(camera.zoom(INFINITY), std::invalid_argument);
  EXPECT_THROW(camera.pan(1.0f, 1.0f, 0), std::invalid_argument);
}

TEST(Camera, OrbitTurnsAboutThePivotAtAFixedDistance) {
  Camera camera;
  camera.frame(glm::vec3(0.5f, -1.0f, 2.0f), 0.8f, 1.5f);
  const float distance = camera.distance();
  std::mt19937 random(3);
  std::uniform_real_distribution<float> delta(-150.0f, 150.0f);
  for (int i = 0; i < 50; ++i) {
    const float yaw = camera.yaw(), pitch = camera.pitch();
    const float dx = delta(random), dy = delta(random);
    camera.orbit(dx, dy);
    EXPECT_FLOAT_EQ(camera.distance(), distance);
    EXPECT_NEAR(glm::length(camera.eye() - camera.pivot()), distance, 1e-5f * distance);
    // Dragging right turns the scene right: the eye moves left (yaw decreases), modulo 2 pi.
    const float expectedYaw = yaw - Camera::kOrbitRadiansPerPixel * dx;
    EXPECT_NEAR(std::remainder(camera.yaw() - expectedYaw, glm::two_pi<float>()), 0.0f, 1e-5f);
    EXPECT_NEAR(camera.pitch(),
                glm::clamp(pitch + Camera::kOrbitRadiansPerPixel * dy, -glm::half_pi<float>(),
                           glm::half_pi<float>()),
                1e-6f);
  }
  // Far past the pole the pitch stops at straight down, still at the same distance.
  camera.orbit(0.0f, 1e5f);
  EXPECT_FLOAT_EQ(camera.pitch(), glm::half_pi<float>());
  EXPECT_NEAR(glm::length(camera.eye() - camera.pivot()), distance, 1e-5f * distance);
}

TEST(Camera, ViewMatrixMatchesLookAtFromTheEye) {
  Camera camera;
  camera.frame(glm::vec3(1.0f, 2.0f, 3.0f), 2.0f, 1.0f);
  for (const float yaw : {0.0f, 1.0f, -2.5f, 3.0f})
    for (const float pitch : {0.0f, 0.5f, -1.3f}) {
      camera.setOrientation(yaw, pitch);
      const glm::mat4 expected = glm::lookAt(camera.eye(), camera.pivot(), glm::vec3(0, 1, 0));
      const glm::mat4 view = camera.view();
      for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) EXPECT_NEAR(view[c][r], expected[c][r], 1e-5f);
    }
}

TEST(Camera, PanMovesAPointAtPivotDepthExactlyWithTheCursor) {
  const int width = 900, height = 600;
  for (const bool orthographic : {false, true}) {
    Camera camera;
    camera.setOrthographic(orthographic);
    camera.setOrientation(0.8f, -0.4f);
    camera.frame(glm::vec3(0.2f, 0.1f, -0.3f), 1.2f, float(width) / float(height));
    // Points at the pivot's depth, across the screen.
    const std::vector<glm::vec3> points = {
        camera.pivot(), camera.pivot() + 0.7f * camera.right() - 0.4f * camera.up(),
        camera.pivot() - 1.1f * camera.right() + 0.9f * camera.up()};
    for (const glm::vec2 cursor : {glm::vec2(37.0f, -12.0f), glm::vec2(-250.5f, 81.25f)}) {
      std::vector<glm::vec3> before;
      for (const glm::vec3& p : points) before.push_back(camera.project(p, width, height));
      camera.pan(cursor.x, cursor.y, height);
      for (size_t i = 0; i < points.size(); ++i) {
        const glm::vec3 after = camera.project(points[i], width, height);
        EXPECT_NEAR(after.x - before[i].x, cursor.x, 1e-3f) << "ortho " << orthographic;
        EXPECT_NEAR(after.y - before[i].y, cursor.y, 1e-3f) << "ortho " << orthographic;
      }
    }
  }
}

TEST(Camera, ToggleOrthographicKeepsTheSizeOfThingsAtThePivot) {
  const int width = 1000, height = 700;
  Camera camera;
  camera.setOrientation(-0.6f, 0.35f);
  camera.frame(glm::vec3(-2.0f, 0.5f, 1.0f), 3.0f, float(width) / float(height));
  camera.zoom(0.6f);
  for (const glm::vec3 direction : {camera.right(), camera.up()}) {
    const auto pixels = [&] {
      const glm::vec3 a = camera.project(camera.pivot(), width, height);
      const glm::vec3 b = camera.project(camera.pivot() + direction, width, height);
      return glm::length(glm::vec2(b - a));
    };
    ASSERT_FALSE(camera.orthographic());
    const float perspective = pixels();
    camera.toggleOrthographic();
    ASSERT_TRUE(camera.orthographic());
    const float orthographic = pixels();
    camera.toggleOrthographic();
    EXPECT_NEAR(orthographic / perspective, 1.0f, 1e-4f);
    // and that size is 1 / pixelSizeAtPivot
    EXPECT_NEAR(perspective * camera.pixelSizeAtPivot(height), 1.0f, 1e-4f);
  }
}

TEST(Camera, StandardViewsLookAlongTheAxes) {
  struct Case {
    StandardView view;
    glm::vec3 fromPivotToEye, screenUp;
  };
  const Case cases[] = {
      {StandardView::Front, {0, 0, 1}, {0, 1, 0}}, {StandardView::Back, {0, 0, -1}, {0, 1, 0}},
      {StandardView::Right, {1, 0, 0}, {0, 1, 0}}, {StandardView::Left, {-1, 0, 0}, {0, 1, 0}},
      {StandardView::Top, {0, 1, 0}, {0, 0, -1}},  {StandardView::Bottom, {0, -1, 0}, {0, 0, 1}},
  };
  for (const Case& c : cases) {
    Camera camera;
    camera.frame(glm::vec3(1.0f, -2.0f, 0.5f), 1.0f, 1.0f);
    camera.orbit(123.0f, -45.0f);
    const float distance = camera.distance();
    camera.setStandardView(c.view);
    const glm::vec3 direction = glm::normalize(camera.eye() - camera.pivot());
    EXPECT_LT(glm::length(direction - c.fromPivotToEye), 1e-6f) << int(c.view);
    EXPECT_FLOAT_EQ(camera.distance(), distance);
    // The view matrix agrees: the eye maps to the origin, a point above the pivot on the screen
    // maps to +y in eye space, the pivot straight ahead.
    const glm::mat4 view = camera.view();
    EXPECT_LT(glm::length(glm::vec3(view * glm::vec4(camera.eye(), 1.0f))), 1e-5f);
    const glm::vec3 pivot = glm::vec3(view * glm::vec4(camera.pivot(), 1.0f));
    EXPECT_LT(glm::length(pivot - glm::vec3(0, 0, -distance)), 1e-5f);
    const glm::vec3 above = glm::vec3(view * glm::vec4(camera.pivot() + c.screenUp, 1.0f));
    EXPECT_LT(glm::length(above - glm::vec3(0, 1, -distance)), 1e-5f) << int(c.view);
  }
}

TEST(Camera, UnprojectInvertsProjectAndSeesTheBackgroundAsNothing) {
  const int width = 640, height = 480;
  std::mt19937 random(11);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  for (const bool orthographic : {false, true}) {
    Camera camera;
    camera.setOrthographic(orthographic);
    camera.setOrientation(0.3f, 0.2f);
    const glm::vec3 centre(4.0f, -1.0f, 2.0f);
    const float radius = 2.5f;
    camera.frame(centre, radius, float(width) / float(height));
    for (const float zoom : {1.0f, 0.3f}) {
      camera.zoom(zoom);
      for (int i = 0; i < 200; ++i) {
        const glm::vec3 p = centre + radius * glm::vec3(unit(random), unit(random), unit(random));
        const glm::vec3 window = camera.project(p, width, height);
        if (window.z <= 0.0f || window.z >= 1.0f) continue;  // clipped (zoomed in)
        const std::optional<glm::vec3> q =
            camera.unproject(window.x, window.y, window.z, width, height);
        ASSERT_TRUE(q.has_value());
        EXPECT_LT(relativeError(*q, p, glm::length(p)), 1e-4f) << "ortho " << orthographic;
      }
    }
    // The pivot is at the centre of the window.
    const glm::vec3 pivot = camera.project(camera.pivot(), width, height);
    EXPECT_NEAR(pivot.x, width / 2.0f, 1e-3f);
    EXPECT_NEAR(pivot.y, height / 2.0f, 1e-3f);
    EXPECT_FALSE(camera.unproject(10.0f, 20.0f, 1.0f, width, height).has_value());
  }
  Camera camera;
  EXPECT_THROW(camera.unproject(1.0f, 1.0f, 1.5f, 10, 10), std::invalid_argument);
  EXPECT_THROW(camera.unproject(1.0f, 1.0f, -0.1f, 10, 10), std::invalid_argument);
  EXPECT_THROW(camera.unproject(1.0f, 1.0f, 0.5f, 0, 10), std::invalid_argument);
}

TEST(Camera, ProjectPutsScreenYDownward) {
  Camera camera;
  camera.setStandardView(StandardView::Front);
  camera.frame(glm::vec3(0.0f), 1.0f, 1.0f);
  const glm::vec3 above = camera.project(glm::vec3(0.0f, 0.5f, 0.0f), 100, 100);
  const glm::vec3 right = camera.project(glm::vec3(0.5f, 0.0f, 0.0f), 100, 100);
  EXPECT_LT(above.y, 50.0f);  // up in the world is up on the screen: smaller window y
  EXPECT_NEAR(above.x, 50.0f, 1e-3f);
  EXPECT_GT(right.x, 50.0f);
  EXPECT_NEAR(right.y, 50.0f, 1e-3f);
}

TEST(Camera, SetPivotKeepsTheEyeAndCentresTheNewPivot) {
  const int width = 800, height = 600;
  Camera camera;
  camera.setOrientation(0.4f, 0.3f);
  camera.frame(glm::vec3(0.0f), 1.0f, float(width) / float(height));
  const glm::vec3 eye = camera.eye();
  const glm::vec3 target(0.3f, -0.2f, 0.4f);
  camera.setPivot(target);
  EXPECT_EQ(camera.pivot(), target);
  EXPECT_LT(glm::length(camera.eye() - eye), 1e-5f);
  EXPECT_NEAR(camera.distance(), glm::length(eye - target), 1e-5f);
  const glm::vec3 centre = camera.project(target, width, height);
  EXPECT_NEAR(centre.x, width / 2.0f, 1e-3f);
  EXPECT_NEAR(centre.y, height / 2.0f, 1e-3f);
  // Orbiting now turns about the new pivot.
  camera.orbit(40.0f, 25.0f);
  EXPECT_EQ(camera.pivot(), target);
  EXPECT_NEAR(glm::length(camera.eye() - target), glm::length(eye - target), 1e-5f);
  EXPECT_THROW(camera.setPivot(glm::vec3(INFINITY)), std::invalid_argument);
}

TEST(Camera, ZoomScalesTheDistanceWithinLimitsAndNothingAtThePivotIsClipped) {
  Camera camera;
  camera.frame(glm::vec3(0.0f), 2.0f, 1.0f);
  const float framed = camera.distance();
  camera.zoom(0.5f);
  EXPECT_FLOAT_EQ(camera.distance(), 0.5f * framed);
  for (int i = 0; i < 100; ++i) camera.zoom(0.1f);
  EXPECT_FLOAT_EQ(camera.distance(), 1e-3f * 2.0f);  // 1e-3 scene radii
  // Zoomed right in, a point just in front of the pivot is still in front of the near plane.
  const glm::vec3 q =
      ndc(camera, 1.0f, camera.pivot() + 0.5f * camera.distance() * camera.backward());
  EXPECT_GT(q.z, -1.0f);
  for (int i = 0; i < 100; ++i) camera.zoom(10.0f);
  EXPECT_FLOAT_EQ(camera.distance(), 1e3f * 2.0f);
  // Zoomed right out, the whole scene is inside the far plane.
  for (const glm::vec3& p : spherePoints(glm::vec3(0.0f), 2.0f, 50))
    EXPECT_LT(ndc(camera, 1.0f, p).z, 1.0f);
}

}  // namespace
}  // namespace sculpt::render
