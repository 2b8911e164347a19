// The display state saved with a project and restored when it opens: the real window sets a
// display away from every default, saves the project, and a fresh window opening it shows the
// same display, field by field.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "gui/sculpt_session.h"
#include "project/project_file.h"

namespace sculpt::app {
namespace {

TEST_F(SculptSession, TheDisplayStateIsSavedWithTheProjectAndRestoredWhenItOpens) {
  open(std::string(SCULPT_SOURCE_DIR) + "/assets/block3.json");
  frames(3);
  DisplaySettings& display = app_->model().display;
  display.method = InterpolationMethod::Vertex;
  display.gradients = GradientScheme::Average;
  display.field = FieldKind::Damping;
  display.smoothField = false;
  display.autoRange = false;
  display.rangeLow = 100.0f;
  display.rangeHigh = 2.5e4f;
  display.showSurface = false;
  display.flatShading = true;
  display.wireframe = true;
  display.showControlMesh = true;
  display.showCells = true;
  display.showGrid = false;
  display.showAxes = false;
  display.clip = true;
  display.clipAxis = 1;
  display.clipPosition = 0.25f;
  frames(2);
  const DisplaySettings before = app_->model().display;
  ASSERT_EQ(before.field, FieldKind::Damping) << "the window kept what was set";

  const std::filesystem::path file = folder_ / "display.sculpt";
  app_->model().requests.saveAs = file.string();
  frames(1);
  ASSERT_TRUE(std::filesystem::exists(file));
  EXPECT_EQ(std::get<std::string>(loadProject(file).tools.at("display.field")), "damping");

  open(file.string());  // a fresh window
  frames(3);
  const DisplaySettings after = app_->model().display;
  EXPECT_EQ(after.method, before.method);
  EXPECT_EQ(after.gradients, before.gradients);
  EXPECT_EQ(after.field, before.field);
  EXPECT_EQ(after.smoothField, before.smoothField);
  EXPECT_EQ(after.autoRange, before.autoRange);
  EXPECT_EQ(after.rangeLow, before.rangeLow);
  EXPECT_EQ(after.rangeHigh, before.rangeHigh);
  EXPECT_EQ(after.showSurface, before.showSurface);
  EXPECT_EQ(after.flatShading, before.flatShading);
  EXPECT_EQ(after.wireframe, before.wireframe);
  EXPECT_EQ(after.showControlMesh, before.showControlMesh);
  EXPECT_EQ(after.showCells, before.showCells);
  EXPECT_EQ(after.showGrid, before.showGrid);
  EXPECT_EQ(after.showAxes, before.showAxes);
  EXPECT_EQ(after.clip, before.clip);
  EXPECT_EQ(after.clipAxis, before.clipAxis);
  EXPECT_EQ(after.clipPosition, before.clipPosition);
  EXPECT_TRUE(after == before) << "every field, those added later included";
}

}  // namespace
}  // namespace sculpt::app
