// The strokes captured during a take become a session script that reads back to the same grab.

#include <gtest/gtest.h>

#include "anim/stroke_capture.h"
#include "tools/session_script_writer.h"

namespace sculpt {
namespace {

TEST(StrokeCapture, AGrabDraggedAndReleasedIsAScriptEventWithItsPath) {
  StrokeCapture capture;
  capture.beginGrab(0.5, {1, 2, 3}, {1, 2, 4}, false);
  capture.moveGrab(0.6, {2, 2, 4});
  capture.moveGrab(0.55, {9, 9, 9});  // back in time: ignored
  capture.moveGrab(0.9, {3, 2, 4});
  capture.endGrab(1.0);
  capture.moveGrab(1.1, {5, 5, 5});  // after the release: ignored
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

}  // namespace
}  // namespace sculpt
