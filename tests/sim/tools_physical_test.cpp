// The physical sculpting tools measured through session scripts on block3 at level 1: a pull
// moves the grabbed point toward its target and lets go cleanly (no load left, the solid relaxes
// toward rest); inflate grows and deflate shrinks the enclosed volume; a region painted 100x
// stiffer bulges less under the same pressure; a replay is bit-for-bit repeatable.

#include <gtest/gtest.h>

#include <cstdio>

#include <cmath>
#include <memory>
#include <string>

#include "fem/fem_model.h"
#include "sim/load_forms.h"
#include "sim/material_point.h"
#include "sim/simulator.h"
#include "support/fem_builders.h"
#include "support/tool_scene.h"
#include "tools/pull_tool.h"
#include "tools/session_script.h"

namespace sculpt {
namespace {

using test::makeToolScene;
using test::nodesOf;
using test::play;
using test::pointAt;

double enclosedVolume(const FemModel& model, const Points& control) {
  return PressureForm(model, 0.0).regionVolume(nodesOf(model, control));
}

const char* const kPullScript = R"({
  "format": "sculpt-session", "version": 1,
  "events": [
    {"t": 0, "type": "pin", "box": [[-1, -1, -1], [4, 0.01, 4]]},
    {"t": 0, "type": "grab", "point": [1.5, 3, 1.5],
     "path": [[0, 1.5, 3, 1.5], [0.5, 2.5, 4, 1.5]], "release": 1.0}
  ]})";

TEST(PhysicalTools, PullMovesThePointTowardTheTargetAndReleasesCleanly) {
  test::ToolScene s = makeToolScene();
  ASSERT_TRUE(s.model);
  ScriptPlayer player(*s.simulator, parseSessionScript(kPullScript, "pull"));
  const MaterialPoint point = *player.grabPoint(1);
  const Eigen::Vector3d anchor = pointAt(*s.model, s.model->restControl(), point);
  const Eigen::Vector3d target(2.5, 4, 1.5);
  const double unpulled = (anchor - target).norm();

  play(player, 0.98);  // the last step before the release
  const PullTool* pull = player.pullTool(1);
  ASSERT_TRUE(pull && pull->active());
  const Eigen::Vector3d held = pointAt(*s.model, s.simulator->positions(), point);
  const double pulled = (held - target).norm();
  // A spring about as stiff as the solid: the point goes part of the way, not all of it.
  EXPECT_LT(pulled, 0.8 * unpulled) << "anchor " << anchor.transpose();
  EXPECT_GT(pulled, 0.1 * unpulled) << "anchor " << anchor.transpose();
  EXPECT_EQ(pull->target(), target);
  // The force line: k |x - target| with the default stiffness 1.5 E h.
  EXPECT_NEAR(pull->springForce(), defaultPullStiffness(*s.model) * pulled,
              1e-9 * pull->springForce());
  EXPECT_NEAR(defaultPullStiffness(*s.model), 1.5 * 1e5 * 0.5, 0.05 * 1.5 * 1e5 * 0.5);
  EXPECT_GT(s.simulator->loadEnergy(), 0.0);

  play(player, 1.02);  // released before the step at t = 1
  EXPECT_FALSE(pull->active());
  EXPECT_EQ(pull->springForce(), 0.0);
  EXPECT_EQ(s.simulator->loadEnergy(), 0.0);  // no load left

  const double releasedOffset =
      (pointAt(*s.model, s.simulator->positions(), point) - anchor).norm();
  play(player, 5.0);
  const double relaxedOffset = (pointAt(*s.model, s.simulator->positions(), point) - anchor).norm();
  std::printf("pull: point to target %.4f m before, %.4f m held; offset %.4f m at release, "
              "%.4f m after 4 s\n", unpulled, pulled, releasedOffset, relaxedOffset);
  EXPECT_GT(releasedOffset, 0.5);
  EXPECT_LT(relaxedOffset, 0.1 * releasedOffset);
}

TEST(PhysicalTools, PushMovesThePointAwayFromTheCursor) {
  test::ToolScene s = makeToolScene();
  ASSERT_TRUE(s.model);
  std::string script = kPullScript;
  script.replace(script.find("\"release\""), 0, "\"push\": true, ");
  ScriptPlayer player(*s.simulator, parseSessionScript(script, "push"));
  const MaterialPoint point = *player.grabPoint(1);
  const Eigen::Vector3d anchor = pointAt(*s.model, s.model->restControl(), point);
  play(player, 0.98);
  const Eigen::Vector3d moved = pointAt(*s.model, s.simulator->positions(), point) - anchor;
  const Eigen::Vector3d drag = Eigen::Vector3d(2.5, 4, 1.5) - anchor;
  EXPECT_LT(moved.dot(drag), -0.5 * drag.squaredNorm() * 0.4);  // well against the drag
  EXPECT_EQ(player.pullTool(1)->target(),
            Eigen::Vector3d(2.0 * anchor - Eigen::Vector3d(2.5, 4, 1.5)));
}

double volumeAfterPressure(double pressure) {
  test::ToolScene s = makeToolScene();
  if (!s.model) return NAN;
  const std::string text = R"({"format": "sculpt-session", "version": 1, "events": [
      {"t": 0, "type": "inflate", "pressure": )" + std::to_string(pressure) +
                           R"(, "duration": 2}]})";
  ScriptPlayer player(*s.simulator, parseSessionScript(text, "inflate"));
  play(player, 1.5);
  return enclosedVolume(*s.model, s.simulator->positions()) /
         enclosedVolume(*s.model, s.model->restControl());
}

TEST(PhysicalTools, InflateGrowsAndDeflateShrinksTheVolume) {
  // Bulk modulus K = E / (3 (1 - 2 nu)) = 8.3e4 Pa: 4000 Pa changes the volume by about 5%.
  const double inflated = volumeAfterPressure(4000), deflated = volumeAfterPressure(-4000);
  std::printf("volume / rest volume: +4000 Pa %.4f, -4000 Pa %.4f\n", inflated, deflated);
  EXPECT_GT(inflated, 1.02);
  EXPECT_LT(inflated, 1.10);
  EXPECT_LT(deflated, 0.98);
  EXPECT_GT(deflated, 0.90);
}

// Bulge of the top under a local pressure, measured as the change of the loaded region's volume
// term, with or without the top painted 100x stiffer first.
double topBulge(bool paintStiff) {
  test::ToolScene s = makeToolScene();
  if (!s.model) return NAN;
  std::string events =
      R"({"t": 0, "type": "pin", "box": [[-1, -1, -1], [4, 0.01, 4]]},
         {"t": 0, "type": "inflate", "centre": [1.5, 3, 1.5], "radius": 1.2, "pressure": 20000,
          "duration": 5})";
  if (paintStiff)
    events += R"(, {"t": 0, "type": "paint", "centre": [1.5, 3, 1.5], "radius": 1.6,
                   "youngs": 1e7, "falloff": "constant", "mirror": "none"})";
  ScriptPlayer player(*s.simulator, parseSessionScript(
      R"({"format": "sculpt-session", "version": 1, "events": [)" + events + "]}", "stiff"));
  play(player, 1.5);
  const PressureForm region(*s.model, 0.0, SphereRegion{{1.5, 3, 1.5}, 1.2});
  return region.regionVolume(nodesOf(*s.model, s.simulator->positions())) -
         region.regionVolume(nodesOf(*s.model, s.model->restControl()));
}

TEST(PhysicalTools, PaintedStiffRegionDeformsLessUnderTheSameLoad) {
  const double soft = topBulge(false), stiff = topBulge(true);
  std::printf("top bulge under the same load: unpainted %.4g m, painted stiff %.4g m\n", soft,
              stiff);
  EXPECT_GT(soft, 0.0);
  EXPECT_GT(stiff, 0.0);
  EXPECT_LT(stiff, 0.2 * soft) << "soft " << soft << " stiff " << stiff;
}

TEST(PhysicalTools, ReplayIsBitForBitRepeatable) {
  const std::string text = R"({"format": "sculpt-session", "version": 1, "events": [
      {"t": 0, "type": "pin", "box": [[-1, -1, -1], [4, 0.01, 4]]},
      {"t": 0, "type": "paint", "centre": [2.5, 2, 1.5], "radius": 0.8, "youngs": 1e6, "density": 3000},
      {"t": 0.1, "type": "grab", "point": [3, 3, 3], "path": [[0, 3, 3, 3], [0.3, 3.5, 3.8, 3]],
       "release": 0.4, "keep": true},
      {"t": 0.2, "type": "inflate", "centre": [0, 3, 0], "radius": 1, "pressure": -3000, "duration": 0.3}
    ]})";
  Points result[2];
  for (Points& r : result) {
    test::ToolScene s = makeToolScene();
    ASSERT_TRUE(s.model);
    ScriptPlayer player(*s.simulator, parseSessionScript(text, "twice"));
    play(player, 0.8);
    r = s.simulator->positions();
  }
  ASSERT_EQ(result[0].rows(), result[1].rows());
  EXPECT_GT((result[0] - test::block3().positions).cwiseAbs().maxCoeff(), 1e-3);  // it moved
  for (Eigen::Index i = 0; i < result[0].size(); ++i)
    ASSERT_EQ(result[0].data()[i], result[1].data()[i]) << "coordinate " << i;
}

}  // namespace
}  // namespace sculpt
