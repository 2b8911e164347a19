#include "sculpt/ui_scale.h"

#include <imgui.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace sculpt::app {

float uiScale(float contentScaleX, float contentScaleY, float userOverride) {
  if (!std::isfinite(userOverride) || userOverride < 0.0f)
    throw std::invalid_argument("the UI scale override must be 0 (automatic) or positive, got " +
                                std::to_string(userOverride));
  constexpr float kMin = 1.0f, kMax = 3.0f;
  if (userOverride > 0.0f) return std::clamp(userOverride, kMin, kMax);
  const auto usable = [](float s) { return std::isfinite(s) && s > 0.0f ? s : 1.0f; };
  const float automatic = std::max(usable(contentScaleX), usable(contentScaleY));
  return std::clamp(std::round(automatic * 4.0f) / 4.0f, kMin, kMax);
}

void applyUiScale(float scale) {
  if (!(scale >= 0.5f && scale <= 4.0f))
    throw std::invalid_argument("a UI scale must be in [0.5, 4], got " + std::to_string(scale));
  if (!ImGui::GetCurrentContext())
    throw std::logic_error("applyUiScale needs an ImGui context (ImGui::CreateContext)");
  ImGuiIO& io = ImGui::GetIO();
  // Fonts: the built-in ProggyClean at the scaled pixel size.
  io.Fonts->Clear();
  ImFontConfig config;
  config.SizePixels = 13.0f * scale;
  io.Fonts->AddFontDefault(&config);
  io.Fonts->Build();
  io.FontGlobalScale = 1.0f;
  // Style: scale a fresh one, so that applying twice does not compound.
  ImGuiStyle style;
  ImGui::StyleColorsDark(&style);
  style.ScaleAllSizes(scale);
  ImGui::GetStyle() = style;
  // The backend keeps the atlas as a texture: upload the new one.
  if (io.BackendRendererUserData) {
    ImGui_ImplOpenGL3_DestroyFontsTexture();
    ImGui_ImplOpenGL3_CreateFontsTexture();
  }
}

}  // namespace sculpt::app
