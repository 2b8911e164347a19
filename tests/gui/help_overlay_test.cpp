// The help overlay (app/sculpt/help_overlay.h) draws with ImGui alone (no window, no GL): open, it
// emits a window centred on the display that fits inside it; closed, it draws nothing. Its mouse
// rows follow the Navigator's rules.

#include "sculpt/help_overlay.h"

#include <gtest/gtest.h>
#include <imgui.h>

#include <algorithm>

#include "render/camera.h"
#include "support/gl_context.h"

namespace sculpt::app {
namespace {

class HelpOverlay : public testing::ImGuiContextTest {
 protected:
  /// Runs a frame with the overlay; returns the bounding box of everything drawn.
  bool frame(NavigationPreset preset, bool* open, ImVec2& lo, ImVec2& hi) {
    ImGui::NewFrame();
    drawHelpOverlay(KeyMap::defaults(), preset, open);
    ImGui::Render();
    const ImDrawData* data = ImGui::GetDrawData();
    lo = ImVec2(1e9f, 1e9f);
    hi = ImVec2(-1e9f, -1e9f);
    for (int l = 0; l < data->CmdListsCount; ++l)
      for (const ImDrawVert& v : data->CmdLists[l]->VtxBuffer) {
        lo = ImVec2(std::min(lo.x, v.pos.x), std::min(lo.y, v.pos.y));
        hi = ImVec2(std::max(hi.x, v.pos.x), std::max(hi.y, v.pos.y));
      }
    return data->TotalVtxCount > 0;
  }
};

TEST_F(HelpOverlay, OpenItDrawsACentredWindowInsideTheDisplayClosedNothing) {
  for (const NavigationPreset preset : {NavigationPreset::Blender, NavigationPreset::Stylus}) {
    bool open = true;
    ImVec2 lo, hi;
    // An auto-resizing window is measured, hidden, on its first frame; then it settles.
    for (int i = 0; i < 3; ++i) frame(preset, &open, lo, hi);
    ASSERT_TRUE(frame(preset, &open, lo, hi));
    EXPECT_TRUE(open);
    EXPECT_GE(lo.x, 0.0f);
    EXPECT_GE(lo.y, 0.0f);
    EXPECT_LE(hi.x, 1280.0f);
    EXPECT_LE(hi.y, 800.0f);
    EXPECT_NEAR(0.5f * (lo.x + hi.x), 640.0f, 2.0f);
    EXPECT_NEAR(0.5f * (lo.y + hi.y), 400.0f, 2.0f);
    EXPECT_GT(hi.x - lo.x, 300.0f);  // two columns of text, not an empty frame
    EXPECT_GT(hi.y - lo.y, 200.0f);
    open = false;
    EXPECT_FALSE(frame(preset, &open, lo, hi));
    EXPECT_FALSE(frame(preset, nullptr, lo, hi));
  }
}

TEST(GestureHelp, RowsNameEveryGestureOfThePreset) {
  const auto has = [](NavigationPreset preset, const std::string& gesture,
                      const std::string& effect) {
    for (const GestureHelp& row : gestureHelp(preset))
      if (row.gesture == gesture && row.effect.rfind(effect, 0) == 0) return true;
    return false;
  };
  EXPECT_TRUE(has(NavigationPreset::Blender, "Middle drag", "Orbit"));
  EXPECT_TRUE(has(NavigationPreset::Blender, "Shift + middle drag", "Pan"));
  EXPECT_TRUE(has(NavigationPreset::Blender, "Ctrl + middle drag", "Zoom"));
  EXPECT_TRUE(has(NavigationPreset::Stylus, "Left drag on the background", "Orbit"));
  EXPECT_TRUE(has(NavigationPreset::Stylus, "Left drag on the model", "Tool stroke"));
  EXPECT_TRUE(has(NavigationPreset::Stylus, "Alt + left drag, anywhere", "Pan"));
  for (const NavigationPreset preset : {NavigationPreset::Blender, NavigationPreset::Stylus})
    EXPECT_TRUE(has(preset, "Double click on the model", "Orbit around"));
}

}  // namespace
}  // namespace sculpt::app
