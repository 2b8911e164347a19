// The material brush through session scripts: a dab changes only the Gauss samples inside the
// brush (others bit-identical) by the documented falloff weight; the falloff presets' values at
// r = 0, R/2, R; mirror x paints the mirrored samples identically; the eyedropper reads the
// nearest sample.

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "fem/fem_model.h"
#include "sim/simulator.h"
#include "support/fem_builders.h"
#include "tools/material_brush.h"
#include "tools/session_script.h"

namespace sculpt {
namespace {

bool sameBits(const Material& a, const Material& b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// Plays a one-event paint script on a fresh block3 (level 1, E = 1e5) and returns the model.
std::unique_ptr<FemModel> paintedModel(const std::string& paintEvent) {
  auto model = test::buildModel(test::block3(), 1, false);
  if (!model) return nullptr;
  Simulator simulator(*model);
  ScriptPlayer player(simulator, parseSessionScript(
      R"({"format": "sculpt-session", "version": 1, "events": [)" + paintEvent + "]}", "paint"));
  EXPECT_TRUE(player.step().ok);
  return model;
}

TEST(MaterialBrush, FalloffPresetsHaveTheDocumentedWeights) {
  const double R = 2.0;
  struct Expect { Falloff f; double at0, atHalf, atR; };
  const Expect table[] = {{Falloff::Smooth, 1, 0.5, 0},
                          {Falloff::Sphere, 1, std::sqrt(3.0) / 2, 0},
                          {Falloff::Linear, 1, 0.5, 0},
                          {Falloff::Sharp, 1, 0.25, 0},
                          {Falloff::Constant, 1, 1, 1}};
  for (const Expect& e : table) {
    SCOPED_TRACE(falloffName(e.f));
    EXPECT_NEAR(falloffWeight(e.f, 0, R), e.at0, 1e-15);
    EXPECT_NEAR(falloffWeight(e.f, R / 2, R), e.atHalf, 1e-15);
    EXPECT_NEAR(falloffWeight(e.f, R, R), e.atR, 1e-15);
    EXPECT_EQ(falloffWeight(e.f, R * 1.0001, R), 0.0);
    EXPECT_EQ(parseFalloff(falloffName(e.f)), e.f);
  }
  EXPECT_FALSE(parseFalloff("gaussian"));
}

TEST(MaterialBrush, PaintChangesOnlySamplesInsideTheBrushByTheFalloffWeight) {
  const Eigen::Vector3d centre(0.7, 1.5, 1.4);
  const double R = 0.8, strength = 0.75;
  auto before = test::buildModel(test::block3(), 1, false);
  auto after = paintedModel(R"({"t": 0, "type": "paint", "centre": [0.7, 1.5, 1.4], "radius": 0.8,
      "youngs": 1e7, "falloff": "smooth", "strength": 0.75, "mirror": "none"})");
  ASSERT_TRUE(before && after);
  const FemMesh& a = before->mesh();
  const FemMesh& b = after->mesh();
  ASSERT_EQ(a.numGaussPoints(), b.numGaussPoints());
  int inside = 0, outside = 0;
  for (uint32_t q = 0; q < a.numGaussPoints(); ++q) {
    const double r = (a.gaussRestPosition[q] - centre).norm();
    const Material& m0 = a.gaussMaterial[q];
    const Material& m1 = b.gaussMaterial[q];
    if (r >= R) {
      ++outside;
      ASSERT_TRUE(sameBits(m0, m1)) << "sample " << q << " at r=" << r;
      continue;
    }
    ++inside;
    const double p = 1 - r / R, w = strength * (3 * p * p - 2 * p * p * p);
    EXPECT_NEAR(m1.youngs, 1e5 + w * (1e7 - 1e5), 1e-9 * 1e7) << "sample " << q;
    EXPECT_EQ(m1.density, m0.density);  // not painted
    EXPECT_EQ(m1.poisson, m0.poisson);
  }
  EXPECT_GT(inside, 10);
  EXPECT_GT(outside, 5 * inside);
  // The eyedropper at the brush centre reads the nearest sample, painted almost fully.
  EXPECT_GT(pickMaterial(*after, centre).youngs, 1e5 + 0.6 * (1e7 - 1e5));
  EXPECT_EQ(pickMaterial(*after, {10, 10, 10}).youngs, 1e5);
}

// Index of the sample nearest to x (and its distance).
uint32_t nearestSample(const FemMesh& mesh, const Eigen::Vector3d& x, double& distance) {
  uint32_t best = 0;
  distance = INFINITY;
  for (uint32_t q = 0; q < mesh.numGaussPoints(); ++q) {
    const double d = (mesh.gaussRestPosition[q] - x).norm();
    if (d < distance) {
      distance = d;
      best = q;
    }
  }
  return best;
}

int countMirroredChanges(const std::string& mirror) {
  auto model = paintedModel(R"({"t": 0, "type": "paint", "centre": [2.3, 1.6, 1.2], "radius": 0.7,
      "youngs": 5e6, "density": 4000, "falloff": "linear", "mirror": ")" + mirror + "\"}");
  if (!model) return -1;
  const FemMesh& mesh = model->mesh();
  int mirrored = 0;
  for (uint32_t q = 0; q < mesh.numGaussPoints(); ++q) {
    const Eigen::Vector3d x = mesh.gaussRestPosition[q];
    if (x.x() < 1.5 + 1e-9) continue;
    const Material& m = mesh.gaussMaterial[q];
    const bool changed = m.youngs != 1e5;
    double d = 0;
    const uint32_t twin = nearestSample(mesh, {3.0 - x.x(), x.y(), x.z()}, d);
    EXPECT_LT(d, 1e-9);
    const Material& t = mesh.gaussMaterial[twin];
    if (mirror == "x") {
      EXPECT_NEAR(t.youngs, m.youngs, 1e-9 * m.youngs) << "sample " << q;
      EXPECT_NEAR(t.density, m.density, 1e-9 * m.density) << "sample " << q;
    }
    if (changed && t.youngs != 1e5) ++mirrored;
  }
  return mirrored;
}

TEST(MaterialBrush, MirrorXPaintsTheMirroredSamplesIdentically) {
  EXPECT_GT(countMirroredChanges("x"), 5);
  EXPECT_EQ(countMirroredChanges("none"), 0);  // the check can see a missing mirror
}

TEST(MaterialBrush, RejectsBadSettings) {
  auto model = test::buildModel(test::block3(), 1, false);
  ASSERT_TRUE(model);
  MaterialBrushSettings s;
  s.radius = -1;
  EXPECT_THROW(paintDab(*model, {1, 1, 1}, s), std::invalid_argument);
  s.radius = 1;
  s.strength = 2;
  EXPECT_THROW(paintDab(*model, {1, 1, 1}, s), std::invalid_argument);
  s.strength = 1;
  s.target.youngs = -5;
  EXPECT_THROW(paintDab(*model, {1, 1, 1}, s), std::invalid_argument);
  s.target.youngs = 1e6;
  EXPECT_THROW(paintDab(*model, {NAN, 1, 1}, s), std::invalid_argument);
}

}  // namespace
}  // namespace sculpt
