// Back-face culling of the deformed surface: the same picture as without it for a closed surface
// facing out, seen from outside (the bunny, Phong-deformed, from six sides, compared pixel by
// pixel), nothing drawn from inside it, and cullsBackFaces' decision: only for a closed surface
// facing out and nowhere turned inside out, not clipped, and wholly beyond the near plane.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "embed/embedded_deformer.h"
#include "embed/embedding.h"
#include "embed/recomputed_normals.h"
#include "io/surface_file.h"
#include "mesh/closed_surface.h"
#include "mesh/lattice_mesh.h"
#include "mesh/surface_triangles.h"
#include "render/offscreen_target.h"
#include "render/phong_gpu_deformer.h"
#include "sculpt/scene_view.h"
#include "support/gl_context.h"

namespace sculpt {
namespace {

class BackFaceCulling : public testing::GlContextTest {};

// The bunny in a hex lattice, its nodes bent and twisted, on the GPU deformer.
struct DeformedBunny {
  VolumeMesh lattice;
  std::unique_ptr<render::PhongGpuDeformer> deformer;
  glm::vec3 centre{0.0f};
  float radius = 0.0f;
};

DeformedBunny deformedBunny() {
  const LoadedSurface file = readSurfaceFile(std::string(SCULPT_SOURCE_DIR) + "/assets/bunny.obj");
  const SurfaceMesh& surface = file.surface();
  const std::vector<uint32_t> triangles = triangulate(surface);
  EXPECT_TRUE(isClosedOutwardSurface(surface.positions, triangles));
  const Eigen::Vector3d low = surface.positions.colwise().minCoeff().transpose();
  const Eigen::Vector3d high = surface.positions.colwise().maxCoeff().transpose();
  LatticeSpec spec;
  spec.spacing = (high - low).maxCoeff() / 5.0;
  spec.origin = low - Eigen::Vector3d::Constant(0.25 * spec.spacing);
  for (int d = 0; d < 3; ++d)
    spec.cubes[d] = static_cast<uint32_t>(std::ceil((high[d] - low[d]) / spec.spacing + 0.5));
  DeformedBunny bunny;
  bunny.lattice = hexLattice(spec);
  const Embedding embedding = embedPoints(bunny.lattice, surface.positions);
  std::vector<float> local, normals;
  const Points restNormals = vertexNormals(surface);
  for (uint32_t p = 0; p < embedding.numPoints(); ++p)
    for (int d = 0; d < 3; ++d) {
      local.push_back(static_cast<float>(embedding.local(p, d)));
      normals.push_back(static_cast<float>(restNormals(p, d)));
    }
  bunny.deformer = std::make_unique<render::PhongGpuDeformer>(bunny.lattice, embedding.cells,
                                                               local, normals);
  bunny.deformer->setTriangles(triangles);
  // A twist about the vertical axis through the middle, growing with height, and a bend.
  const double size = (high - low).norm();
  const Eigen::Vector3d middle = 0.5 * (low + high);
  Points nodes = bunny.lattice.positions;
  for (Eigen::Index i = 0; i < nodes.rows(); ++i) {
    const Eigen::Vector3d X = bunny.lattice.positions.row(i).transpose() - middle;
    const double height = (X.y() + middle.y() - low.y()) / size;
    const double c = std::cos(0.8 * height), s = std::sin(0.8 * height);
    nodes.row(i) = (middle + Eigen::Vector3d(c * X.x() + s * X.z() + 0.2 * size * height * height,
                                             X.y(), -s * X.x() + c * X.z()))
                       .transpose();
  }
  EmbeddedDeformer cpu(bunny.lattice, surface.positions, embedding);  // for the node gradients
  cpu.setFrame(nodes, InterpolationMethod::Phong);
  bunny.deformer->setFrame(nodes, cpu.nodeGradients(), InterpolationMethod::Phong);
  const Eigen::Vector3d lo = nodes.colwise().minCoeff(), hi = nodes.colwise().maxCoeff();
  bunny.centre = glm::vec3(0.5 * (lo + hi).x(), 0.5 * (lo + hi).y(), 0.5 * (lo + hi).z());
  bunny.radius = static_cast<float>(0.5 * (hi - lo).norm());
  return bunny;
}

std::vector<uint8_t> drawn(const render::PhongGpuDeformer& deformer, const glm::mat4& view,
                           const glm::mat4& projection, bool cull) {
  render::OffscreenTarget target(256, 256);
  target.bind();
  glViewport(0, 0, 256, 256);
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  render::SurfaceStyle style;
  style.cullBackFaces = cull;
  deformer.draw(view, projection, style);
  glFinish();
  return target.readPixels();
}

int litPixels(const std::vector<uint8_t>& rgba) {
  int lit = 0;
  for (size_t i = 0; i < rgba.size(); i += 4) lit += (rgba[i] | rgba[i + 1] | rgba[i + 2]) != 0;
  return lit;
}

TEST_F(BackFaceCulling, AClosedSurfaceFacingOutLooksTheSameFromEverySide) {
  const DeformedBunny bunny = deformedBunny();
  const glm::mat4 projection = glm::perspective(0.8f, 1.0f, 0.1f * bunny.radius,
                                                10.0f * bunny.radius);
  const glm::vec3 sides[] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0.3f, 0.2f, 1},
                             {-0.2f, 0.4f, -1}};
  for (const glm::vec3& side : sides) {
    const glm::vec3 up = std::abs(side.y) > 0.9f ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
    const glm::mat4 view =
        glm::lookAt(bunny.centre + 1.6f * bunny.radius * glm::normalize(side), bunny.centre, up);
    const std::vector<uint8_t> all = drawn(*bunny.deformer, view, projection, false);
    const std::vector<uint8_t> culled = drawn(*bunny.deformer, view, projection, true);
    int differing = 0;
    for (size_t i = 0; i < all.size(); i += 4)
      differing += !std::equal(all.begin() + i, all.begin() + i + 3, culled.begin() + i);
    const int surface = litPixels(all);
    std::printf("[ measured ] from (%.1f, %.1f, %.1f): %d of %d surface pixels differ\n", side.x,
                side.y, side.z, differing, surface);
    EXPECT_GT(surface, 5000);  // the bunny fills a good part of the picture
    EXPECT_LE(differing, surface / 1000);  // depth ties where the surface turns away, at most
  }
}

TEST_F(BackFaceCulling, FromInsideTheCulledSurfaceIsNotDrawn) {
  const DeformedBunny bunny = deformedBunny();
  const glm::mat4 projection = glm::perspective(1.2f, 1.0f, 0.001f * bunny.radius,
                                                10.0f * bunny.radius);
  // From the middle of the body: every triangle faces away.
  const glm::vec3 eye = bunny.centre - glm::vec3(0.0f, 0.25f * bunny.radius, 0.0f);
  const glm::mat4 view = glm::lookAt(eye, eye + glm::vec3(1, 0, 0), glm::vec3(0, 1, 0));
  EXPECT_GT(litPixels(drawn(*bunny.deformer, view, projection, false)), 20000);
  EXPECT_EQ(litPixels(drawn(*bunny.deformer, view, projection, true)), 0);
}

TEST(CullsBackFaces, OnlyAClosedUprightSurfaceUnclippedAndBeyondTheNearPlane) {
  const glm::vec3 low(-1.0f), high(1.0f);
  const glm::mat4 perspective = glm::perspective(0.8f, 1.5f, 0.1f, 100.0f);
  const glm::mat4 orthographic = glm::ortho(-3.0f, 3.0f, -2.0f, 2.0f, 0.1f, 100.0f);
  const auto from = [](const glm::vec3& eye) {
    return glm::lookAt(eye, glm::vec3(0.0f), glm::vec3(0, 1, 0));
  };
  const std::vector<Eigen::Matrix3d> upright(5, Eigen::Matrix3d::Identity() * 1.2);
  app::DisplaySettings display;
  const auto culls = [&](const glm::mat4& viewProjection, bool closed = true,
                         const std::vector<Eigen::Matrix3d>& gradients = {}) {
    return app::cullsBackFaces(closed, gradients.empty() ? upright : gradients, display,
                               viewProjection, low, high);
  };
  EXPECT_TRUE(culls(perspective * from({0, 0, 5})));
  EXPECT_TRUE(culls(orthographic * from({3, 2, 4})));
  EXPECT_FALSE(culls(perspective * from({0, 0, 5}), false));
  // The eye inside the box, at its corner, or so near that the near plane cuts the box.
  EXPECT_FALSE(culls(perspective * from({0, 0, 0.5f})));
  EXPECT_FALSE(culls(perspective * from({1, 1, 1})));
  EXPECT_FALSE(culls(perspective * from({0, 0, 1.05f})));
  EXPECT_TRUE(culls(perspective * from({0, 0, 1.2f})));
  // Looking away from the box: behind the eye.
  EXPECT_FALSE(culls(perspective * glm::lookAt(glm::vec3(0, 0, 5), glm::vec3(0, 0, 10),
                                               glm::vec3(0, 1, 0))));
  // A node turned inside out (a mirror image there): its part of the surface faces in.
  std::vector<Eigen::Matrix3d> mirrored = upright;
  mirrored[3](0, 0) = -0.1;
  EXPECT_FALSE(culls(perspective * from({0, 0, 5}), true, mirrored));
  display.clip = true;  // the clipping plane opens the surface
  EXPECT_FALSE(culls(perspective * from({0, 0, 5})));
}

}  // namespace
}  // namespace sculpt
