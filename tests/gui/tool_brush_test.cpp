// Per-tool brushes (tool_state.h): each brush tool keeps its own radius, strength and falloff, a
// unified radius shares one radius while on; the brushes' round trip through a project's tool
// settings (a project from before per-tool brushes gives its one radius to every tool), and the
// radii kept in the preferences, which a new window starts with.

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <memory>
#include <string>

#include "gui/sculpt_session.h"
#include "io/atomic_file.h"
#include "project/preferences.h"
#include "sculpt/sculpt_app.h"
#include "sculpt/tool_state.h"
#include "support/scratch_directory.h"

namespace sculpt::app {
namespace {

const std::string kBlock3 = std::string(SCULPT_SOURCE_DIR) + "/assets/block3.json";

float radiusOf(const ToolState& state, ToolKind tool) { return state.brush(tool).radiusPixels; }

TEST(ToolBrush, EachToolKeepsItsOwnBrushUnlessTheRadiusIsUnified) {
  ToolState t;
  t.tool = ToolKind::Inflate;
  t.brush().radiusPixels = 150.0f;
  t.brush().strength = 0.9f;
  t.tool = ToolKind::Paint;
  EXPECT_EQ(t.brush().radiusPixels, kDefaultBrushRadiusPixels) << "paint keeps its own radius";
  EXPECT_EQ(t.brush().strength, 0.5f);
  t.brush().radiusPixels = 30.0f;
  t.brush().falloff = Falloff::Sharp;
  EXPECT_EQ(radiusOf(t, ToolKind::Inflate), 150.0f);
  EXPECT_EQ(t.brush(ToolKind::Inflate).falloff, Falloff::Smooth);

  // Unified: the current tool's radius becomes everyone's, and a change reaches every tool.
  t.setUnifiedRadius(true);
  EXPECT_EQ(radiusOf(t, ToolKind::Inflate), 30.0f);
  EXPECT_EQ(radiusOf(t, ToolKind::Pin), 30.0f);
  t.tool = ToolKind::Pin;
  t.brush().radiusPixels = 80.0f;
  EXPECT_EQ(radiusOf(t, ToolKind::Inflate), 80.0f);
  EXPECT_EQ(radiusOf(t, ToolKind::Paint), 80.0f);
  EXPECT_EQ(t.brush(ToolKind::Paint).falloff, Falloff::Sharp) << "only the radius is shared";
  EXPECT_EQ(t.brush(ToolKind::Inflate).strength, 0.9f);

  // Off again: each its own, as before.
  t.setUnifiedRadius(false);
  EXPECT_EQ(radiusOf(t, ToolKind::Inflate), 150.0f);
  EXPECT_EQ(radiusOf(t, ToolKind::Paint), 30.0f);
  EXPECT_EQ(radiusOf(t, ToolKind::Pin), kDefaultBrushRadiusPixels);
}

TEST(ToolBrush, ProjectToolSettingsRoundTrip) {
  ToolState t;
  t.tool = ToolKind::Pin;
  t.brushes[static_cast<size_t>(ToolKind::Inflate)] = {150.0f, 0.25f, Falloff::Linear};
  t.brushes[static_cast<size_t>(ToolKind::Paint)] = {30.0f, 1.0f, Falloff::Constant};
  t.brushes[static_cast<size_t>(ToolKind::Pin)] = {70.0f, 0.5f, Falloff::Sphere};
  t.unifiedRadius = true;
  t.unifiedRadiusPixels = 42.0f;
  ToolSettings settings;
  storeToolState(t, settings);
  EXPECT_EQ(std::get<double>(settings.at("tool.inflate.radiusPixels")), 150.0);
  EXPECT_EQ(std::get<std::string>(settings.at("tool.paint.falloff")), "constant");
  EXPECT_EQ(std::get<bool>(settings.at("tool.unifiedRadius")), true);

  const ToolState loaded = loadToolState(settings);
  EXPECT_EQ(loaded.tool, ToolKind::Pin);
  for (const ToolKind tool : {ToolKind::Inflate, ToolKind::Paint, ToolKind::Pin})
    EXPECT_EQ(loaded.brushes[static_cast<size_t>(tool)], t.brushes[static_cast<size_t>(tool)])
        << toolName(tool);
  EXPECT_TRUE(loaded.unifiedRadius);
  EXPECT_EQ(loaded.unifiedRadiusPixels, 42.0f);
  EXPECT_EQ(loaded.brush().radiusPixels, 42.0f);
}

TEST(ToolBrush, AnOldProjectsOneBrushGoesToEveryTool) {
  const ToolSettings old{{"tool.kind", 3.0},
                         {"tool.radiusPixels", 120.0},
                         {"tool.strength", 0.8},
                         {"tool.falloff", std::string("linear")}};
  const ToolState t = loadToolState(old);
  EXPECT_EQ(t.tool, ToolKind::Paint);
  EXPECT_FALSE(t.unifiedRadius);
  for (const ToolKind tool : {ToolKind::Inflate, ToolKind::Paint, ToolKind::Pin}) {
    EXPECT_EQ(t.brush(tool).radiusPixels, 120.0f) << toolName(tool);
    EXPECT_EQ(t.brush(tool).strength, 0.8f) << toolName(tool);
    EXPECT_EQ(t.brush(tool).falloff, Falloff::Linear) << toolName(tool);
  }
}

TEST(ToolBrush, BadProjectValuesAreClampedOrKeepTheFallback) {
  const ToolSettings settings{{"tool.radiusPixels", 60.0},
                              {"tool.inflate.radiusPixels", 5000.0},
                              {"tool.paint.radiusPixels", std::string("big")},
                              {"tool.pin.radiusPixels", -3.0},
                              {"tool.paint.strength", 7.0},
                              {"tool.inflate.falloff", std::string("soft")},
                              {"tool.unifiedRadius", 1.0}};
  const ToolState t = loadToolState(settings);
  EXPECT_EQ(t.brush(ToolKind::Inflate).radiusPixels, kMaxBrushRadiusPixels);
  EXPECT_EQ(t.brush(ToolKind::Paint).radiusPixels, 60.0f) << "the wrong kind: the shared key's";
  EXPECT_EQ(t.brush(ToolKind::Pin).radiusPixels, kMinBrushRadiusPixels);
  EXPECT_EQ(t.brush(ToolKind::Paint).strength, 1.0f);
  EXPECT_EQ(t.brush(ToolKind::Inflate).falloff, Falloff::Smooth);
  EXPECT_FALSE(t.unifiedRadius) << "a number is not a switch";
}

TEST(ToolBrush, PreferencesKeepTheRadii) {
  test::ScratchDirectory scratch("tool_brush_preferences");
  const std::filesystem::path path = scratch.path() / "preferences.json";
  ToolState t;
  t.brushes[static_cast<size_t>(ToolKind::Inflate)].radiusPixels = 150.0f;
  t.brushes[static_cast<size_t>(ToolKind::Paint)].radiusPixels = 25.0f;
  t.unifiedRadiusPixels = 64.0f;
  Preferences preferences;
  preferences.brushRadii = brushRadii(t);
  EXPECT_EQ(preferences.brushRadii.byTool.at("inflate"), 150.0);
  savePreferences(preferences, path);
  const LoadedPreferences loaded = loadPreferences(path);
  EXPECT_EQ(loaded.warning, "");
  EXPECT_EQ(loaded.preferences, preferences);

  ToolState restored;
  restoreBrushRadii(restored, loaded.preferences.brushRadii);
  EXPECT_EQ(restored.brush(ToolKind::Inflate).radiusPixels, 150.0f);
  EXPECT_EQ(restored.brush(ToolKind::Paint).radiusPixels, 25.0f);
  EXPECT_EQ(restored.brush(ToolKind::Pin).radiusPixels, kDefaultBrushRadiusPixels);
  EXPECT_EQ(restored.unifiedRadiusPixels, 64.0f);
  EXPECT_FALSE(restored.unifiedRadius);
}

TEST(ToolBrush, PreferencesMissingBadOrOutOfRangeRadii) {
  test::ScratchDirectory scratch("tool_brush_bad_preferences");
  const std::filesystem::path path = scratch.path() / "preferences.json";
  const std::string head = R"({"format": "sculpt-preferences", "version": 1)";

  // Written before brushes were kept: the defaults, no warning.
  writeFileAtomically(path, head + "}");
  LoadedPreferences loaded = loadPreferences(path);
  EXPECT_EQ(loaded.warning, "");
  EXPECT_EQ(loaded.preferences.brushRadii, BrushRadii{});

  // Out of range: clamped, no warning; of the wrong kind: that value's default, and a warning.
  writeFileAtomically(path, head + R"(, "brushRadii": {"unified": "yes", "unifiedPixels": 1e300,
      "byTool": {"inflate": 0.5, "paint": "wide", "pin": 300}}})");
  loaded = loadPreferences(path);
  EXPECT_NE(loaded.warning.find("\"brushRadii.unified\" has an unusable value"), std::string::npos)
      << loaded.warning;
  const BrushRadii& radii = loaded.preferences.brushRadii;
  EXPECT_FALSE(radii.unified);
  EXPECT_EQ(radii.unifiedPixels, BrushRadii::kMaxPixels);
  EXPECT_EQ(radii.byTool.at("inflate"), BrushRadii::kMinPixels);
  EXPECT_EQ(radii.byTool.count("paint"), 0u);
  EXPECT_EQ(radii.byTool.at("pin"), 300.0);

  writeFileAtomically(path, head + R"(, "brushRadii": [50], "uiScale": 2})");
  loaded = loadPreferences(path);
  EXPECT_NE(loaded.warning.find("\"brushRadii\" has an unusable value"), std::string::npos);
  EXPECT_EQ(loaded.preferences.brushRadii, BrushRadii{});
  EXPECT_EQ(loaded.preferences.uiScale, 2.0) << "one bad value loses only itself";

  // A boolean where a number belongs (JSON libraries read true as 1) is of the wrong kind too.
  writeFileAtomically(
      path, head + R"(, "brushRadii": {"unifiedPixels": true, "byTool": {"pin": false}}})");
  loaded = loadPreferences(path);
  EXPECT_NE(loaded.warning.find("\"brushRadii.unifiedPixels\" has an unusable value"),
            std::string::npos)
      << loaded.warning;
  EXPECT_EQ(loaded.preferences.brushRadii, BrushRadii{});
}

// In the window: the [ and ] keys change the current tool's radius only.
TEST_F(SculptSession, BrushKeysChangeTheCurrentToolsRadiusOnly) {
  open(kBlock3);
  frames(3);
  ToolState& tools = app_->model().tools;
  tools.tool = ToolKind::Inflate;
  for (int k = 0; k < 3; ++k) press(GLFW_KEY_RIGHT_BRACKET, false);
  EXPECT_FLOAT_EQ(tools.brush().radiusPixels, 50.0f * 1.25f * 1.25f * 1.25f);
  tools.tool = ToolKind::Paint;
  frames(1);
  EXPECT_EQ(tools.brush().radiusPixels, kDefaultBrushRadiusPixels) << "paint keeps its own radius";
  press(GLFW_KEY_LEFT_BRACKET, false);
  EXPECT_FLOAT_EQ(tools.brush().radiusPixels, 40.0f);
  EXPECT_FLOAT_EQ(tools.brush(ToolKind::Inflate).radiusPixels, 97.65625f);

  tools.setUnifiedRadius(true);  // as the panel's checkbox does
  press(GLFW_KEY_LEFT_BRACKET, false);
  EXPECT_FLOAT_EQ(tools.brush(ToolKind::Inflate).radiusPixels, 32.0f) << "shared";
  EXPECT_FLOAT_EQ(tools.brush(ToolKind::Pin).radiusPixels, 32.0f);
  tools.setUnifiedRadius(false);
  EXPECT_FLOAT_EQ(tools.brush(ToolKind::Inflate).radiusPixels, 97.65625f) << "its own again";
  EXPECT_FLOAT_EQ(tools.brush(ToolKind::Paint).radiusPixels, 40.0f);
}

// The interactive window writes the radii into the preferences when it closes; a new window
// loaded with those preferences (and no project) starts with them.
TEST_F(SculptSession, ANewWindowStartsWithTheRadiiLastUsed) {
  open(kBlock3, false);
  frames(2);
  ToolState& tools = app_->model().tools;
  tools.brushes[static_cast<size_t>(ToolKind::Inflate)].radiusPixels = 150.0f;
  tools.brushes[static_cast<size_t>(ToolKind::Paint)].radiusPixels = 22.0f;
  tools.brushes[static_cast<size_t>(ToolKind::Pin)].radiusPixels = 310.0f;
  const std::array<BrushSettings, kToolCount> used = tools.brushes;
  app_.reset();  // closes: writes the preferences

  const std::filesystem::path file = folder_ / "preferences.json";
  LoadedPreferences loaded = loadPreferences(file);
  ASSERT_EQ(loaded.warning, "");
  EXPECT_EQ(loaded.preferences.brushRadii.byTool.at("inflate"), 150.0);

  Options options;
  options.headless = true;
  options.width = 1280, options.height = 800;
  options.scene = kBlock3;
  app_ = std::make_unique<SculptApp>(window_, options, std::chrono::steady_clock::now(),
                                     std::move(loaded), file);
  frames(1);
  const ToolState& fresh = app_->model().tools;
  for (const ToolKind tool : {ToolKind::Inflate, ToolKind::Paint, ToolKind::Pin})
    EXPECT_EQ(fresh.brush(tool).radiusPixels, used[static_cast<size_t>(tool)].radiusPixels)
        << toolName(tool);
  EXPECT_FALSE(fresh.unifiedRadius);
}

}  // namespace
}  // namespace sculpt::app
