// The window's panels and overlays with ImGui alone (no window, no GL): the 3D view is the
// rectangle between the panels; a running build shows a progress window whose Cancel button
// asks the application to cancel; the colour bar appears only with a field, inside the view.

#include "sculpt/panels.h"

#include <gtest/gtest.h>
#include <imgui.h>
#include <imgui_internal.h>

#include "sculpt/colour_bar.h"
#include "support/gl_context.h"

namespace sculpt::app {
namespace {

class Panels : public testing::ImGuiContextTest {
 protected:
  ViewRect frame(AppModel& model) {
    ImGui::NewFrame();
    const ViewRect view = drawPanels(model);
    drawBuildProgress(model, view);
    drawColourBar(model.display.field, model.fieldRange, view.min, view.max);
    ImGui::Render();
    return view;
  }
};

TEST_F(Panels, TheViewIsTheRectangleBetweenThePanels) {
  AppModel model;
  ViewRect view = frame(model);
  view = frame(model);
  EXPECT_GT(view.min.x, 100.0f);   // the tool panel on the left
  EXPECT_LT(view.max.x, 1100.0f);  // the properties on the right
  EXPECT_GT(view.min.y, 10.0f);    // the menu bar
  EXPECT_LT(view.max.y, 790.0f);   // the status strip
  EXPECT_GT(view.max.x - view.min.x, 600.0f);
  model.showPanels = false;
  view = frame(model);
  EXPECT_EQ(view.min.x, 0.0f);
  EXPECT_EQ(view.max.x, 1280.0f);
  EXPECT_EQ(view.max.y, 800.0f);
}

TEST_F(Panels, CancelOnTheBuildProgressAsksToCancel) {
  AppModel model;
  model.status.build.running = true;
  model.status.build.fraction = 0.4;
  model.status.build.stage = "embedding the surface";
  for (int i = 0; i < 3; ++i) frame(model);
  const ImGuiWindow* window = ImGui::FindWindowByName("Preparing");
  ASSERT_NE(window, nullptr);
  // Cancel spans the window's width at its bottom.
  const ImVec2 button(window->Pos.x + 0.5f * window->Size.x,
                      window->Pos.y + window->Size.y - ImGui::GetStyle().WindowPadding.y -
                          0.5f * ImGui::GetFrameHeight());
  ImGuiIO& io = ImGui::GetIO();
  io.MousePos = button;
  frame(model);
  EXPECT_FALSE(model.requests.cancelBuild);
  io.MouseDown[0] = true;
  frame(model);
  io.MouseDown[0] = false;
  frame(model);
  EXPECT_TRUE(model.requests.cancelBuild);
  // No build, no progress window drawn.
  model.status.build.running = false;
  model.requests = {};
  frame(model);
  const ImGuiWindow* after = ImGui::FindWindowByName("Preparing");
  EXPECT_TRUE(after == nullptr || !after->Active);
}

TEST_F(Panels, ColourBarOnlyWithAFieldAndInsideTheView) {
  AppModel model;
  frame(model);
  const ImGuiWindow* legend = ImGui::FindWindowByName("Legend");
  EXPECT_TRUE(legend == nullptr || !legend->Active);
  model.display.field = FieldKind::YoungsModulus;
  model.fieldRange = {1.0e5f, 3.0e6f};
  ViewRect view;
  for (int i = 0; i < 2; ++i) view = frame(model);
  legend = ImGui::FindWindowByName("Legend");
  ASSERT_NE(legend, nullptr);
  EXPECT_TRUE(legend->Active);
  EXPECT_GE(legend->Pos.x, view.min.x);
  EXPECT_GE(legend->Pos.y, view.min.y);
  EXPECT_LE(legend->Pos.x + legend->Size.x, view.max.x);
  EXPECT_LE(legend->Pos.y + legend->Size.y, view.max.y);
  // In the lower right quarter of the view.
  EXPECT_GT(legend->Pos.x, 0.5f * (view.min.x + view.max.x));
  EXPECT_GT(legend->Pos.y, 0.5f * (view.min.y + view.max.y) - 100.0f);
}

TEST(ColourBarText, ValuesKeepThreeSignificantDigits) {
  EXPECT_EQ(formatValue(3.0e6), "3.00e+06");
  EXPECT_EQ(formatValue(0.877), "0.877");
  EXPECT_EQ(formatValue(0.0), "0");
  EXPECT_EQ(formatValue(1.5e-3), "1.50e-03");
  EXPECT_EQ(formatValue(123.4), "123");
}

}  // namespace
}  // namespace sculpt::app
