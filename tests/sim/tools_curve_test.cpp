// Curve-based manipulation and pinning through session scripts on block3 at level 1 (bottom
// pinned, implicit integrator): dragging a curve across the top moves every point of it toward
// its target, more than points far from it, and release removes every load and lets the solid
// relax; the smooth profile moves the curve's ends less than its middle; the curve is resampled
// evenly by arc length with the stiffness split over its springs; a pinned box stays exactly at
// rest under gravity while the rest falls, and unpin frees it; malformed curve events give one
// sentence naming the event and the field.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "io/file_error.h"
#include "sim/standard_forms.h"
#include "support/tool_scene.h"
#include "tools/curve_tool.h"
#include "tools/session_script.h"

namespace sculpt {
namespace {

using test::makeToolScene;
using test::play;
using test::pointAt;

std::string wrap(const std::string& events) {
  return R"({"format": "sculpt-session", "version": 1, "events": [)" + events + "]}";
}

// Bottom pinned; a curve along x across the middle of the top face dragged up by 0.6 m over
// 0.5 s, released at 1 s.
std::string curveScript(const std::string& profile) {
  return wrap(R"({"t": 0, "type": "pin", "box": [[-1, -1, -1], [4, 0.01, 4]]},
                 {"t": 0, "type": "curve", "points": [[0.25, 3, 1.5], [1.5, 3, 1.5], [2.75, 3, 1.5]],
                  "path": [[0, 0, 0, 0], [0.5, 0, 0.6, 0]], "profile": ")" +
              profile + R"(", "samples": 9, "release": 1.0})");
}

const Eigen::Vector3d kDrag(0, 0.6, 0);

// Displacements from rest of the curve's samples.
std::vector<double> curveDisplacements(const CurveTool& curve) {
  const std::vector<Eigen::Vector3d> now = curve.pointPositions();
  std::vector<double> moved;
  for (size_t i = 0; i < now.size(); ++i) moved.push_back((now[i] - curve.anchors()[i]).norm());
  return moved;
}

TEST(CurveTool, DraggingMovesTheCurveTowardItsTargetsAndReleasesCleanly) {
  test::ToolScene s = makeToolScene();
  ASSERT_TRUE(s.model);
  ScriptPlayer player(*s.simulator, parseSessionScript(curveScript("rigid"), "curve"));
  const size_t loadsBefore = s.simulator->numLoads();
  play(player, 0.98);  // the last step before the release
  const CurveTool* curve = player.curveTool(1);
  ASSERT_TRUE(curve && curve->active());
  ASSERT_EQ(curve->samples().size(), 9u);
  EXPECT_EQ(s.simulator->numLoads(), loadsBefore + 9);
  const std::vector<Eigen::Vector3d> now = curve->pointPositions(), targets = curve->targets();
  for (size_t i = 0; i < now.size(); ++i) {
    SCOPED_TRACE("sample " + std::to_string(i));
    EXPECT_EQ(targets[i], curve->anchors()[i] + kDrag);
    const double before = (curve->anchors()[i] - targets[i]).norm(),
                 after = (now[i] - targets[i]).norm();
    // Toward the target and in the drag direction, part of the way: the default springs are
    // about as stiff as the solid (measured: 0.29 of the 0.6 m drag).
    EXPECT_LT(after, 0.85 * before);
    EXPECT_GT((now[i] - curve->anchors()[i]).dot(kDrag.normalized()), 0.1);
  }
  // Points of the solid far from the curve (the lower half, the far top corners) move less.
  const std::vector<double> moved = curveDisplacements(*curve);
  const double leastCurve = *std::min_element(moved.begin(), moved.end());
  for (const Eigen::Vector3d& rest :
       {Eigen::Vector3d(1.5, 1, 1.5), Eigen::Vector3d(0.2, 1.2, 0.2),
        Eigen::Vector3d(2.8, 1.2, 2.8), Eigen::Vector3d(0.1, 2.9, 0.1),
        Eigen::Vector3d(2.9, 2.9, 2.9)}) {
    const MaterialPoint p = *locateMaterialPoint(s.model->mesh(), rest);
    const double far = (pointAt(*s.model, s.simulator->positions(), p) -
                        pointAt(*s.model, s.model->restControl(), p))
                           .norm();
    EXPECT_LT(far, 0.5 * leastCurve) << "rest " << rest.transpose();
  }

  play(player, 1.02);  // released before the step at t = 1
  EXPECT_FALSE(curve->active());
  EXPECT_EQ(s.simulator->numLoads(), loadsBefore);
  EXPECT_EQ(s.simulator->loadEnergy(), 0.0);
  const std::vector<double> released = curveDisplacements(*curve);
  play(player, 4.0);
  const std::vector<double> relaxed = curveDisplacements(*curve);
  for (size_t i = 0; i < relaxed.size(); ++i) {
    EXPECT_GT(released[i], 0.1) << "sample " << i;
    EXPECT_LT(relaxed[i], 0.1 * released[i]) << "sample " << i;
  }
}

TEST(CurveTool, SmoothProfileMovesTheEndsLessThanTheMiddle) {
  std::vector<double> moved[2];
  for (int smooth = 0; smooth < 2; ++smooth) {
    test::ToolScene s = makeToolScene();
    ASSERT_TRUE(s.model);
    ScriptPlayer player(*s.simulator,
                        parseSessionScript(curveScript(smooth ? "smooth" : "rigid"), "profile"));
    play(player, 0.98);
    const CurveTool* curve = player.curveTool(1);
    ASSERT_TRUE(curve && curve->active());
    const std::vector<double>& w = curve->weights();
    EXPECT_EQ(w.front(), smooth ? std::sin(0.0) : 1.0);
    EXPECT_EQ(w[4], 1.0);  // the middle sample, s = 0.5
    EXPECT_NEAR(w.back(), smooth ? 0.0 : 1.0, 1e-15);
    moved[smooth] = curveDisplacements(*curve);
  }
  const std::vector<double>& rigid = moved[0];
  const std::vector<double>& smooth = moved[1];
  EXPECT_LT(smooth.front(), 0.6 * smooth[4]);
  EXPECT_LT(smooth.back(), 0.6 * smooth[4]);
  EXPECT_LT(smooth.front(), 0.6 * rigid.front());
  EXPECT_LT(smooth.back(), 0.6 * rigid.back());
  // Rigid: the ends follow about as well as the middle.
  EXPECT_GT(rigid.front(), 0.7 * rigid[4]);
  EXPECT_GT(rigid.back(), 0.7 * rigid[4]);
}

TEST(CurveTool, ResamplesEvenlyByArcLengthAndSplitsTheStiffness) {
  test::ToolScene s = makeToolScene();
  ASSERT_TRUE(s.model);
  const MaterialPointLocator locator(s.model->mesh());
  // An L of length 3 (2 along x, 1 along z) on the top face.
  const std::vector<Eigen::Vector3d> polyline = {{0.5, 3, 0.5}, {2.5, 3, 0.5}, {2.5, 3, 1.5}};
  const std::vector<CurveSample> samples = sampleCurve(*s.model, locator, polyline, 4);
  ASSERT_EQ(samples.size(), 4u);
  const Eigen::Vector3d expected[] = {{0.5, 3, 0.5}, {1.5, 3, 0.5}, {2.5, 3, 0.5}, {2.5, 3, 1.5}};
  for (size_t i = 0; i < 4; ++i) {
    EXPECT_NEAR((samples[i].rest - expected[i]).norm(), 0.0, 1e-12) << i;
    EXPECT_DOUBLE_EQ(samples[i].s, static_cast<double>(i) / 3.0);
    const Eigen::Vector3d located = pointAt(*s.model, s.model->restControl(), samples[i].point);
    EXPECT_LT((located - expected[i]).norm(), 1e-6) << i;
  }
  // Default count: one per half typical cell (about 0.5 m here) plus one; one point for length 0.
  EXPECT_EQ(sampleCurve(*s.model, locator, polyline).size(), defaultCurveSamples(*s.model, 3.0));
  const double cell = typicalCellSize(*s.model);
  EXPECT_NEAR(cell, 0.5, 0.05);
  EXPECT_EQ(defaultCurveSamples(*s.model, 3.0), size_t(std::ceil(3.0 / (0.5 * cell))) + 1);
  EXPECT_EQ(sampleCurve(*s.model, locator, {{1, 3, 1}, {1, 3, 1}}).size(), 1u);
  EXPECT_THROW(sampleCurve(*s.model, locator, {}), std::invalid_argument);
  EXPECT_THROW(sampleCurve(*s.model, locator, polyline, kMaxCurveSamples + 1),
               std::invalid_argument);

  CurveTool tool(*s.simulator);
  tool.grab(polyline, CurveProfile::Smooth, 0.0, 5);
  EXPECT_EQ(s.simulator->numLoads(), 5u);
  EXPECT_NEAR(5 * tool.springStiffness(), defaultPullStiffness(*s.model), 1e-9);
  tool.drag(Eigen::Vector3d(0, 1, 0));
  EXPECT_NEAR(tool.targets()[1].y() - tool.anchors()[1].y(), std::sin(std::numbers::pi / 4), 1e-12);
  EXPECT_THROW(tool.drag(Eigen::Vector3d(0, NAN, 0)), std::invalid_argument);
  tool.release(ReleaseMode::Keep);
  EXPECT_EQ(tool.numKept(), 5u);
  EXPECT_EQ(s.simulator->numLoads(), 5u);
  tool.clearKept();
  EXPECT_EQ(s.simulator->numLoads(), 0u);
}

TEST(PinTool, PinnedBoxStaysExactlyAtRestUnderGravityAndUnpinFreesIt) {
  test::ToolScene s = makeToolScene();
  ASSERT_TRUE(s.model);
  s.simulator->addLoad(std::make_unique<GravityForm>(*s.model, Eigen::Vector3d(0, -9.81, 0)));
  // The block hangs from its top layer of control points, which is let go at 0.5 s.
  const std::string box = R"("box": [[-1, 2.99, -1], [4, 4, 4]])";
  ScriptPlayer player(
      *s.simulator,
      parseSessionScript(wrap(R"({"t": 0, "type": "pin", )" + box +
                              R"(}, {"t": 0.5, "type": "pin", "unpin": true, )" + box + "}"),
                         "pin"));
  const Points& rest = s.model->restControl();
  std::vector<Eigen::Index> pinned, free;
  for (Eigen::Index i = 0; i < rest.rows(); ++i) (rest(i, 1) >= 2.99 ? pinned : free).push_back(i);
  ASSERT_FALSE(pinned.empty());
  ASSERT_FALSE(free.empty());

  play(player, 0.48);
  const Points& x = s.simulator->positions();
  for (Eigen::Index i : pinned) {
    EXPECT_TRUE(s.simulator->fixedMask()[size_t(i)]);
    for (int c = 0; c < 3; ++c) ASSERT_EQ(x(i, c), rest(i, c)) << "pinned control point " << i;
  }
  double meanDrop = 0;
  for (Eigen::Index i : free) {
    EXPECT_LT(x(i, 1), rest(i, 1)) << "free control point " << i;
    meanDrop += (rest(i, 1) - x(i, 1)) / static_cast<double>(free.size());
  }
  EXPECT_GT(meanDrop, 0.01);

  play(player, 1.0);  // unpinned at 0.5 s: the whole block falls
  for (Eigen::Index i : pinned) {
    EXPECT_FALSE(s.simulator->fixedMask()[size_t(i)]);
    EXPECT_LT(s.simulator->positions()(i, 1), rest(i, 1) - 0.3) << "unpinned control point " << i;
  }
}

std::string errorOf(const std::string& events) {
  try {
    parseSessionScript(wrap(events), "s.json");
  } catch (const FileError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(CurveScript, ParsesACurveEvent) {
  const SessionScript script =
      parseSessionScript(wrap(R"({"t": 1, "type": "curve", "points": [[0, 3, 0], [3, 3, 0]],
               "path": [[0, 0, 0, 0], [2, 0, 1, 0]], "profile": "smooth", "stiffness": 4e5,
               "samples": 7, "keep": true})"),
                         "s.json");
  ASSERT_EQ(script.events.size(), 1u);
  EXPECT_STREQ(script.events[0].typeName(), "curve");
  const auto& curve = std::get<CurveEvent>(script.events[0].action);
  EXPECT_EQ(curve.points.size(), 2u);
  EXPECT_EQ(curve.points[1], Eigen::Vector3d(3, 3, 0));
  EXPECT_EQ(curve.profile, CurveProfile::Smooth);
  EXPECT_EQ(curve.stiffness, 4e5);
  EXPECT_EQ(curve.samples, 7u);
  EXPECT_TRUE(curve.keep);
  EXPECT_FALSE(curve.release);
  EXPECT_EQ(curve.offsetAt(1), Eigen::Vector3d(0, 0.5, 0));
  EXPECT_EQ(curve.offsetAt(9), Eigen::Vector3d(0, 1, 0));
  EXPECT_EQ(script.events[0].endTime(), 3.0);
  EXPECT_EQ(script.duration(), 3.0);
}

TEST(CurveScript, MalformedCurveEventsGiveOneSentenceNamingEventAndField) {
  const std::string head = R"({"t": 0, "type": "curve", )";
  const std::string points = R"("points": [[0, 3, 0], [3, 3, 0]])";
  const std::string path = R"("path": [[0, 0, 0, 0]])";
  struct Case {
    std::string events, message;
  };
  const Case cases[] = {
      {head + path + "}",
       "s.json: events[0] (curve): 'points' is missing (a non-empty array of [x, y, z])."},
      {head + R"("points": [], )" + path + "}",
       "s.json: events[0] (curve): 'points' must be a non-empty array of [x, y, z]."},
      {head + R"("points": [[0, 3, 0], [3, "top", 0]], )" + path + "}",
       "s.json: events[0] (curve): 'points[1]' must be an array of 3 finite numbers."},
      {head + points + "}",
       "s.json: events[0] (curve): 'path' is missing (a non-empty array of [t, dx, dy, dz])."},
      {head + points + R"(, "path": [[0, 0, 1]]})",
       "s.json: events[0] (curve): 'path[0]' must be an array [t, dx, dy, dz]."},
      {head + points + R"(, "path": [[1, 0, 0, 0], [0.5, 0, 1, 0]]})",
       "s.json: events[0] (curve): 'path[1]' must not go back in time (times must be "
       "non-decreasing)."},
      {head + points + ", " + path + R"(, "profile": "wavy"})",
       "s.json: events[0] (curve): 'profile' must be rigid or smooth (got \"wavy\")."},
      {head + points + ", " + path + R"(, "samples": 0})",
       "s.json: events[0] (curve): 'samples' must be an integer from 1 to 1024 (got 0)."},
      {head + points + ", " + path + R"(, "samples": 2.5})",
       "s.json: events[0] (curve): 'samples' must be an integer from 1 to 1024 (got 2.5)."},
      {head + points + ", " + path + R"(, "stiffness": -1})",
       "s.json: events[0] (curve): 'stiffness' must be a finite number > 0 (N/m) (got -1)."},
      {head + points + ", " + path + R"(, "release": -2})",
       "s.json: events[0] (curve): 'release' must be a finite number >= 0 (got -2)."},
      {head + points + ", " + path + R"(, "radius": 1})",
       "s.json: events[0] (curve): unknown field 'radius'."},
      {R"({"type": "curve", )" + points + ", " + path + "}",
       "s.json: events[0] (curve): 't' is missing (a finite number >= 0 (s))."},
  };
  for (const Case& c : cases) EXPECT_EQ(errorOf(c.events), c.message) << c.events;
}

}  // namespace
}  // namespace sculpt
