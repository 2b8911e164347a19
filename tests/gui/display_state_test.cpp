// The Display panel's state as project tool settings (sculpt/display_state.h): a round trip of
// every field, defaults for keys missing or of the wrong kind, clamping, and the command line's
// switches over a project's display.

#include "sculpt/display_state.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

namespace sculpt::app {
namespace {

// Every field away from its default.
DisplaySettings unusualDisplay() {
  DisplaySettings d;
  d.method = InterpolationMethod::Vertex;
  d.gradients = GradientScheme::Average;
  d.field = FieldKind::StrainEnergy;
  d.smoothField = false;
  d.autoRange = false;
  d.rangeLow = -12.5f;
  d.rangeHigh = 2.5e4f;
  d.showSurface = false;
  d.flatShading = true;
  d.wireframe = true;
  d.showControlMesh = true;
  d.showCells = true;
  d.showGrid = false;
  d.showAxes = false;
  d.clip = true;
  d.clipAxis = 2;
  d.clipPosition = 0.3f;
  return d;
}

TEST(DisplayState, EveryFieldSurvivesTheRoundTrip) {
  const DisplaySettings d = unusualDisplay();
  ASSERT_NE(d.method, DisplaySettings{}.method);
  ASSERT_NE(d.gradients, DisplaySettings{}.gradients);
  ToolSettings settings;
  settings["tool.kind"] = 3.0;  // the tools' keys stay as they are
  storeDisplayState(d, settings);
  EXPECT_EQ(std::get<std::string>(settings.at("display.field")), "strain");
  EXPECT_EQ(std::get<std::string>(settings.at("display.method")), "vertex");
  EXPECT_EQ(std::get<std::string>(settings.at("display.gradients")), "average");
  EXPECT_EQ(std::get<bool>(settings.at("display.smoothField")), false);
  EXPECT_EQ(std::get<double>(settings.at("display.clipAxis")), 2.0);
  EXPECT_EQ(std::get<double>(settings.at("tool.kind")), 3.0);
  const DisplaySettings loaded = loadDisplayState(settings);
  EXPECT_TRUE(loaded == d);
  EXPECT_EQ(loaded.rangeLow, -12.5f);
  EXPECT_EQ(loaded.rangeHigh, 2.5e4f);
  EXPECT_EQ(loaded.clipPosition, 0.3f);
  // And the defaults too.
  ToolSettings defaults;
  storeDisplayState(DisplaySettings{}, defaults);
  EXPECT_TRUE(loadDisplayState(defaults) == DisplaySettings{});
}

TEST(DisplayState, MissingWrongKindAndUnknownKeepTheDefaultsAndNumbersAreClamped) {
  EXPECT_TRUE(loadDisplayState({}) == DisplaySettings{}) << "a project written before the keys";
  ToolSettings t;
  t["display.field"] = 2.0;                    // a number where a name belongs
  t["display.method"] = std::string("cubic");  // no such method
  t["display.gradients"] = true;
  t["display.smoothField"] = std::string("no");
  t["display.wireframe"] = 1.0;
  t["display.clipAxis"] = 7.0;
  t["display.clipPosition"] = -0.5;
  t["display.rangeLow"] = std::numeric_limits<double>::quiet_NaN();
  t["display.rangeHigh"] = 1e300;
  const DisplaySettings d = loadDisplayState(t);
  const DisplaySettings defaults;
  EXPECT_EQ(d.field, defaults.field);
  EXPECT_EQ(d.method, defaults.method);
  EXPECT_EQ(d.gradients, defaults.gradients);
  EXPECT_EQ(d.smoothField, defaults.smoothField);
  EXPECT_EQ(d.wireframe, defaults.wireframe);
  EXPECT_EQ(d.clipAxis, 2);
  EXPECT_EQ(d.clipPosition, 0.0f);
  EXPECT_EQ(d.rangeLow, defaults.rangeLow);
  EXPECT_EQ(d.rangeHigh, std::numeric_limits<float>::max());
  t["display.clipAxis"] = -3.0;
  t["display.clipPosition"] = 4.0;
  t["display.field"] = std::string("density");
  EXPECT_EQ(loadDisplayState(t).clipAxis, 0);
  EXPECT_EQ(loadDisplayState(t).clipPosition, 1.0f);
  EXPECT_EQ(loadDisplayState(t).field, FieldKind::Density);
}

TEST(DisplayState, CommandLineSwitchesWinOverTheProjectsDisplay) {
  const DisplaySettings saved = unusualDisplay();
  EXPECT_TRUE(withCommandLineDisplay(saved, DisplaySettings{}) == saved) << "no switches given";
  DisplaySettings commandLine;  // sculpt --field youngs --clip x --field-per-cell
  commandLine.field = FieldKind::YoungsModulus;
  commandLine.clip = true;
  commandLine.clipAxis = 0;
  commandLine.smoothField = false;
  DisplaySettings expected = saved;
  expected.field = FieldKind::YoungsModulus;
  expected.clipAxis = 0;
  const DisplaySettings d = withCommandLineDisplay(saved, commandLine);
  EXPECT_TRUE(d == expected);
  EXPECT_EQ(d.field, FieldKind::YoungsModulus);
  EXPECT_EQ(d.clipAxis, 0);
  EXPECT_TRUE(d.wireframe) << "the project's own";
}

}  // namespace
}  // namespace sculpt::app
