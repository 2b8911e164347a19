// The strokes captured during a take become a session script: a grab reads back with its path,
// and brush strokes (pin, paint, inflate) driven through their tools replay from the captured
// script to the same solid, bit for bit.

#include <gtest/gtest.h>

#include <cstdio>
#include <functional>
#include <memory>

#include "anim/stroke_capture.h"
#include "support/tool_scene.h"
#include "tools/session_script_writer.h"
#include "tools/strokes.h"

namespace sculpt {
namespace {

TEST(StrokeCapture, AGrabDraggedAndReleasedIsAScriptEventWithItsPath) {
  StrokeCapture capture;
  capture.beginGrab(0.5, {1, 2, 3}, {1, 2, 4}, false);
  capture.move(0.6, {2, 2, 4}, std::nullopt);
  capture.move(0.55, {9, 9, 9}, std::nullopt);  // back in time: ignored
  capture.move(0.9, {3, 2, 4}, std::nullopt);
  capture.end(1.0);
  capture.move(1.1, {5, 5, 5}, std::nullopt);  // after the release: ignored
  const SessionScript script = parseSessionScript(sessionScriptJson(capture.script()), "take.json");
  ASSERT_EQ(script.events.size(), 1u);
  EXPECT_EQ(script.events[0].time, 0.5);
  const auto& grab = std::get<GrabEvent>(script.events[0].action);
  EXPECT_EQ(grab.point, Eigen::Vector3d(1, 2, 3));
  ASSERT_EQ(grab.path.size(), 3u);
  EXPECT_EQ(grab.path[0].target, Eigen::Vector3d(1, 2, 4));
  EXPECT_DOUBLE_EQ(grab.path[1].time, 0.1);
  EXPECT_EQ(grab.path[2].target, Eigen::Vector3d(3, 2, 4));
  ASSERT_TRUE(grab.release.has_value());
  EXPECT_DOUBLE_EQ(*grab.release, 0.5);
  EXPECT_DOUBLE_EQ(script.duration(), 1.0);
  capture.clear();
  EXPECT_TRUE(capture.script().events.empty());
}

// One brush stroke of the test: begins at step `first`, its input over rest point at(k) at step
// k, ends at step `last`.
struct BrushStroke {
  int first = 0, last = 0;
  std::function<Eigen::Vector3d(int)> at;
  std::function<std::unique_ptr<Tool>()> make;
  std::function<void(StrokeCapture&, double, const Eigen::Vector3d&)> capture;
};

TEST(StrokeCapture, BrushStrokesReplayFromTheCapturedScriptToTheSameSolid) {
  test::ToolScene direct = test::makeToolScene();
  ASSERT_TRUE(direct.model);
  const double h = direct.simulator->settings().timeStep;
  PaintStroke::Settings paint;
  paint.brush.radius = 0.8;
  paint.brush.target.youngs = 1e6;
  paint.brush.target.density = 3000;
  paint.mirrorCentre = Eigen::Vector3d(1.5, 1.5, 1.5);
  const InflateStroke::Settings inflate{1.0, 3000.0};
  const std::vector<BrushStroke> strokes{
      {0, 3, [](int k) { return Eigen::Vector3d(0.5 + 0.7 * k, 0, 1.5); },
       [] { return std::make_unique<PinStroke>(PinStroke::Settings{0.9, std::nullopt}); },
       [](StrokeCapture& c, double t, const Eigen::Vector3d& p) { c.beginPin(t, p, 0.9, false); }},
      {4, 14, [](int k) { return Eigen::Vector3d(0.3 + 0.13 * (k - 4), 3, 0.5); },
       [&] { return std::make_unique<PaintStroke>(paint); },
       [&](StrokeCapture& c, double t, const Eigen::Vector3d& p) { c.beginPaint(t, p, paint); }},
      {15, 32, [](int k) { return Eigen::Vector3d(0, 0.6 + 0.11 * (k - 15), 1.5); },
       [&] { return std::make_unique<InflateStroke>(inflate); },
       [&](StrokeCapture& c, double t, const Eigen::Vector3d& p) {
         c.beginInflate(t, p, inflate, inflate.pressure);
       }}};

  // The strokes through their tools, as the window drives them, captured alongside.
  SimulatorToolContext context(*direct.simulator);
  StrokeCapture capture;
  std::unique_ptr<Tool> tool;
  const int steps = 45;
  for (int k = 0; k < steps; ++k) {
    const double t = static_cast<double>(k) * h;
    for (const BrushStroke& stroke : strokes) {
      if (k < stroke.first || k > stroke.last) continue;
      ToolInput input;
      input.restPoint = stroke.at(k);
      input.position = *input.restPoint;
      if (k == stroke.first) {
        tool = stroke.make();
        tool->begin(context, input);
        stroke.capture(capture, t, *input.restPoint);
      } else if (k < stroke.last) {
        tool->update(context, input);
        capture.move(t, input.position, input.restPoint);
      } else {
        tool->end(context, input);
        capture.end(t);
      }
    }
    ASSERT_TRUE(direct.simulator->step().ok) << "step " << k;
  }

  // The captured script, written and read back, replayed on a fresh solid.
  const SessionScript script = parseSessionScript(sessionScriptJson(capture.script()), "take.json");
  size_t counts[3] = {0, 0, 0};
  for (const ScriptEvent& event : script.events) {
    counts[0] += std::holds_alternative<PinEvent>(event.action);
    counts[1] += std::holds_alternative<PaintEvent>(event.action);
    counts[2] += std::holds_alternative<InflateEvent>(event.action);
  }
  std::printf("[ captured ] %zu pins, %zu dabs, %zu inflate presses\n", counts[0], counts[1],
              counts[2]);
  EXPECT_EQ(counts[0], 3u) << "one pin per brush position, release excluded";
  EXPECT_GE(counts[1], 3u) << "dabs a quarter of the radius apart";
  EXPECT_LT(counts[1], 10u) << "not one dab per input";
  EXPECT_GE(counts[2], 3u) << "inflate re-presses as the brush moves";
  test::ToolScene replayed = test::makeToolScene();
  ScriptPlayer player(*replayed.simulator, script);
  for (int k = 0; k < steps; ++k) ASSERT_TRUE(player.step().ok) << "step " << k;

  const Points& a = direct.simulator->positions();
  const Points& b = replayed.simulator->positions();
  ASSERT_EQ(a.rows(), b.rows());
  EXPECT_GT((a - test::block3().positions).cwiseAbs().maxCoeff(), 1e-3) << "the strokes acted";
  for (Eigen::Index i = 0; i < a.size(); ++i)
    ASSERT_EQ(a.data()[i], b.data()[i]) << "coordinate " << i;
}

}  // namespace
}  // namespace sculpt
