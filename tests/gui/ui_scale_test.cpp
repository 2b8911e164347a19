// HiDPI scale (app/sculpt/ui_scale.h): the automatic scale rounds the content scale to quarter
// steps and clamps to [1, 3]; applying a scale loads the font at 13 * scale pixels and scales a
// fresh default style, so applying twice does not compound. No window or GL backend needed.

#include "sculpt/ui_scale.h"

#include <gtest/gtest.h>
#include <imgui.h>

#include <cmath>
#include <stdexcept>

namespace sculpt::app {
namespace {

TEST(UiScale, AutomaticScaleRoundsToQuartersAndClamps) {
  EXPECT_EQ(uiScale(1.0f, 1.0f), 1.0f);
  EXPECT_EQ(uiScale(1.3f, 1.2f), 1.25f);  // max 1.3 -> nearest quarter 1.25
  EXPECT_EQ(uiScale(1.0f, 1.38f), 1.5f);  // 5.52 quarters -> 6
  EXPECT_EQ(uiScale(2.1f, 1.9f), 2.0f);
  EXPECT_EQ(uiScale(1.125f, 1.0f), 1.25f);  // halfway rounds away from zero
  EXPECT_EQ(uiScale(0.5f, 0.75f), 1.0f);    // never below 1
  EXPECT_EQ(uiScale(4.0f, 3.5f), 3.0f);     // never above 3
  EXPECT_EQ(uiScale(0.0f, 0.0f), 1.0f);     // a platform that reports nothing
  EXPECT_EQ(uiScale(NAN, 2.0f), 2.0f);
  EXPECT_EQ(uiScale(INFINITY, 1.0f), 1.0f);
}

TEST(UiScale, UserOverrideWinsAndIsClamped) {
  EXPECT_EQ(uiScale(2.0f, 2.0f, 1.1f), 1.1f);  // not rounded: the user chose it
  EXPECT_EQ(uiScale(1.0f, 1.0f, 2.2f), 2.2f);
  EXPECT_EQ(uiScale(1.0f, 1.0f, 5.0f), 3.0f);
  EXPECT_EQ(uiScale(2.0f, 2.0f, 0.5f), 1.0f);
  EXPECT_THROW(uiScale(1.0f, 1.0f, -1.0f), std::invalid_argument);
  EXPECT_THROW(uiScale(1.0f, 1.0f, NAN), std::invalid_argument);
}

TEST(UiScale, ApplyLoadsTheScaledFontAndScalesAFreshStyle) {
  EXPECT_THROW(applyUiScale(2.0f), std::logic_error);  // no context yet
  ImGui::CreateContext();
  const ImGuiStyle reference;  // ImGui's defaults
  for (const float scale : {2.0f, 1.5f, 1.5f, 1.0f}) {
    applyUiScale(scale);
    ImGuiIO& io = ImGui::GetIO();
    ASSERT_EQ(io.Fonts->Fonts.Size, 1);
    EXPECT_EQ(io.Fonts->Fonts[0]->FontSize, 13.0f * scale);
    EXPECT_TRUE(io.Fonts->IsBuilt());
    const ImGuiStyle& style = ImGui::GetStyle();
    // ScaleAllSizes floors the scaled sizes; a compounding bug would give 8 * 1.5 * 1.5.
    EXPECT_EQ(style.WindowPadding.x, std::floor(reference.WindowPadding.x * scale));
    EXPECT_EQ(style.FramePadding.y, std::floor(reference.FramePadding.y * scale));
    EXPECT_EQ(style.ScrollbarSize, std::floor(reference.ScrollbarSize * scale));
  }
  EXPECT_THROW(applyUiScale(0.0f), std::invalid_argument);
  EXPECT_THROW(applyUiScale(NAN), std::invalid_argument);
  ImGui::DestroyContext();
}

}  // namespace
}  // namespace sculpt::app
