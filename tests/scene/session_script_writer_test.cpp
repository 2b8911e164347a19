// Session scripts written by sessionScriptJson read back to the same events, field for field.

#include <gtest/gtest.h>

#include <cmath>
#include <variant>

#include "tools/session_script.h"
#include "tools/session_script_writer.h"

namespace sculpt {
namespace {

constexpr const char* kScript = R"({
  "format": "sculpt-session", "version": 1, "events": [
    {"t": 0.1, "type": "grab", "point": [0.5, 0.25, 1.0], "path": [[0, 0.5, 0.25, 1.0], [0.3333333333333333, 1.5, 0.25, 1.0]],
     "stiffness": 1234.5, "release": 0.75, "keep": true},
    {"t": 0.2, "type": "inflate", "centre": [1, 2, 3], "radius": 0.5, "pressure": -250.125, "duration": 0.4},
    {"t": 0.3, "type": "inflate", "pressure": 99, "duration": 1},
    {"t": 0.4, "type": "paint", "centre": [0.1, 0.2, 0.3], "radius": 0.7, "youngs": 5e7, "damping": 3,
     "falloff": "linear", "strength": 0.5, "mirror": "xz", "mirrorCentre": [1, 1, 1]},
    {"t": 0.5, "type": "pin", "box": [[0, 0, 0], [1, 0.1, 1]]},
    {"t": 0.6, "type": "pin", "centre": [2, 2, 2], "radius": 0.25, "unpin": true},
    {"t": 0.7, "type": "curve", "points": [[0, 0, 0], [1, 0, 0]], "path": [[0, 0, 0, 0], [1, 0, 0.5, 0]],
     "profile": "smooth", "samples": 12}
  ]})";

TEST(SessionScriptWriter, WrittenScriptsReadBackToTheSameEvents) {
  const SessionScript original = parseSessionScript(kScript, "original.json");
  const std::string text = sessionScriptJson(original, "a take");
  const SessionScript again = parseSessionScript(text, "written.json");
  ASSERT_EQ(again.events.size(), original.events.size());
  EXPECT_EQ(sessionScriptJson(again, "a take"), text) << "writing is a fixed point";
  for (size_t i = 0; i < original.events.size(); ++i) {
    EXPECT_EQ(again.events[i].time, original.events[i].time);
    EXPECT_STREQ(again.events[i].typeName(), original.events[i].typeName());
    EXPECT_EQ(again.events[i].endTime(), original.events[i].endTime());
  }
  const auto& grab = std::get<GrabEvent>(again.events[0].action);
  EXPECT_EQ(grab.point, Eigen::Vector3d(0.5, 0.25, 1.0));
  ASSERT_EQ(grab.path.size(), 2u);
  EXPECT_EQ(grab.path[1].time, 1.0 / 3.0) << "17 significant digits round-trip";
  EXPECT_EQ(grab.stiffness, 1234.5);
  EXPECT_TRUE(grab.keep);
  const auto& inflate = std::get<InflateEvent>(again.events[1].action);
  EXPECT_EQ(inflate.pressure, -250.125);
  EXPECT_TRUE(std::isinf(std::get<InflateEvent>(again.events[2].action).radius));
  const auto& paint = std::get<PaintEvent>(again.events[3].action);
  EXPECT_TRUE(paint.brush.fields.youngs && paint.brush.fields.damping);
  EXPECT_FALSE(paint.brush.fields.density || paint.brush.fields.poisson);
  EXPECT_EQ(paint.brush.falloff, Falloff::Linear);
  EXPECT_TRUE(paint.brush.mirror.x && paint.brush.mirror.z && !paint.brush.mirror.y);
  EXPECT_TRUE(std::get<PinEvent>(again.events[4].action).box.has_value());
  EXPECT_TRUE(std::get<PinEvent>(again.events[5].action).unpin);
  const auto& curve = std::get<CurveEvent>(again.events[6].action);
  EXPECT_EQ(curve.profile, CurveProfile::Smooth);
  EXPECT_EQ(curve.samples, 12u);
}

TEST(SessionScriptWriter, TopologyEventsAreRefused) {
  const SessionScript script = parseSessionScript(
      R"({"format": "sculpt-session", "version": 1, "events": [
          {"t": 0, "type": "topology", "op": "delete", "cells": [0]}]})",
      "topology.json");
  EXPECT_THROW(sessionScriptJson(script), std::invalid_argument);
}

}  // namespace
}  // namespace sculpt
