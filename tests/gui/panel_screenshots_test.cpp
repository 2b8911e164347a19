// Every panel, menu and dialog of the window at UI scale 1 (1280x800) and 2 (2560x1600: the same
// layout on a screen of twice the density), opened as a person would, by clicking. With
// SCULPT_SESSION_IMAGES set to a folder each state is written there as a PNG
// (docs/images/ui-*.png were made this way and looked at).
#include <gtest/gtest.h>
#include <imgui_internal.h>

#include <ostream>
#include <string>

#include "sculpt_session.h"

namespace sculpt::app {
namespace {

struct ScaleCase {
  float scale;
  int width, height;
};

void PrintTo(const ScaleCase& c, std::ostream* out) {
  *out << "UI scale " << c.scale << " at " << c.width << "x" << c.height;
}

class PanelScreenshots : public SculptSession, public ::testing::WithParamInterface<ScaleCase> {
 protected:
  void openAtScale() {
    const ScaleCase c = GetParam();
    glfwSetWindowSize(window_, c.width, c.height);
    glfwPollEvents();
    open();
    app_->model().uiScale = c.scale;
    app_->model().requests.uiScaleChanged = true;
    frames(3);
    int w = 0, h = 0;
    glfwGetFramebufferSize(window_, &w, &h);
    ASSERT_EQ(w, c.width) << "the hidden window could not be resized";
  }
  std::string name(const std::string& what) const {
    return "ui-" + what + "-scale" + std::to_string(static_cast<int>(GetParam().scale)) + ".png";
  }
  // Clicks the main menu's entry whose label starts at `x` pixels (at scale 1) and keeps the
  // pointer there, so that the menu stays open for the picture.
  void openMenu(float x) {
    const float s = GetParam().scale;
    pointer_.x = (x + 8.0f) * s, pointer_.y = 9.0f * s;
    pointer_.left = true;
    frames(1);
    pointer_.left = false;
    frames(2);
  }
  static bool menuOpen() {
    const ImGuiContext& g = *ImGui::GetCurrentContext();
    return !g.OpenPopupStack.empty();
  }
  void closeMenus() {
    pointer_.x = pointer_.y = -1e6f;
    press(GLFW_KEY_ESCAPE, false);
    frames(1);
  }
};

TEST_P(PanelScreenshots, EveryPanelMenuAndDialog) {
  openAtScale();
  // The panels, with a field shown (the colour bar) and a paint tool (its sliders).
  app_->model().display.field = FieldKind::YoungsModulus;
  app_->model().tools.tool = ToolKind::Paint;
  frames(20, name("panels-paint"));
  app_->model().tools.tool = ToolKind::Inflate;
  frames(2, name("panels-inflate"));
  app_->model().tools.tool = ToolKind::Topology;
  frames(2, name("panels-topology"));
  // A stroke, so that Edit names what it undoes.
  const ViewRect view = app_->viewRect();
  const ImVec2 middle(0.5f * (view.min.x + view.max.x), 0.5f * (view.min.y + view.max.y));
  app_->model().tools.tool = ToolKind::Paint;
  drag(middle, 20.0f * GetParam().scale, 0.0f, 4);
  release();
  frames(2);
  EXPECT_TRUE(app_->model().document.canUndo) << "the paint stroke is an undo entry";
  // A pull held at the middle of the view: its spring and force label.
  app_->model().tools.tool = ToolKind::Pull;
  drag(middle, 60.0f * GetParam().scale, -40.0f * GetParam().scale, 6);
  frames(4, name("pull-label"));
  release();
  // The menus, opened by clicking their titles (x of each title at scale 1).
  const struct {
    const char* name;
    float x;
  } menus[] = {
      {"file", 17.0f}, {"edit", 61.0f}, {"view", 105.0f}, {"simulation", 150.0f}, {"help", 236.0f}};
  for (const auto& menu : menus) {
    openMenu(menu.x);
    EXPECT_TRUE(menuOpen()) << menu.name << " menu";
    frames(1, name(std::string("menu-") + menu.name));
    closeMenus();
  }
  // The help overlay, the stylus panel and the export dialog.
  app_->model().showHelp = true;
  frames(2, name("help"));
  app_->model().showHelp = false;
  app_->model().showStylus = true;
  frames(2, name("stylus"));
  app_->model().showStylus = false;
  // A toast with a long message stays inside the 3D view.
  app_->model().toast(
      "autosave failed: /home/someone/.config/sculpt/untitled.sculpt.recovery: cannot create a "
      "temporary file for writing (No such file or directory)",
      true, 60.0);
  frames(2, name("toast"));
}

INSTANTIATE_TEST_SUITE_P(Scales, PanelScreenshots,
                         ::testing::Values(ScaleCase{1.0f, 1280, 800}, ScaleCase{2.0f, 2560, 1600}),
                         [](const ::testing::TestParamInfo<ScaleCase>& param) {
                           return "Scale" + std::to_string(static_cast<int>(param.param.scale));
                         });

}  // namespace
}  // namespace sculpt::app
