#include "sculpt/colour_bar.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "render/colour_map.h"

namespace sculpt::app {

std::string formatValue(double value) {
  char text[32];
  const double magnitude = std::abs(value);
  if (magnitude != 0.0 && (magnitude < 1e-2 || magnitude >= 1e4))
    std::snprintf(text, sizeof text, "%.2e", value);
  else
    std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}

void drawColourBar(FieldKind field, FieldRange range, ImVec2 viewMin, ImVec2 viewMax) {
  if (field == FieldKind::None) return;
  const float scale = ImGui::GetFontSize() / 13.0f;
  const std::string unit(fieldUnit(field));
  const std::string title(fieldLabel(field));
  const double values[3] = {range.high, 0.5 * (range.low + range.high), range.low};
  std::string labels[3];
  float labelWidth = 0.0f;
  for (int k = 0; k < 3; ++k) {
    labels[k] = formatValue(values[k]) + " " + unit;
    labelWidth = std::max(labelWidth, ImGui::CalcTextSize(labels[k].c_str()).x);
  }
  const ImVec2 barSize(18.0f * scale, std::min(220.0f * scale, 0.5f * (viewMax.y - viewMin.y)));
  const ImVec2 padding = ImGui::GetStyle().WindowPadding;
  const float contentWidth =
      std::max(ImGui::CalcTextSize(title.c_str()).x, barSize.x + 6.0f * scale + labelWidth);
  // The end labels are centred on the bar's ends, so half a line sticks out above and below it:
  // the bar starts a line below the title (the top label clears it) and the window ends half a
  // line below the bar.
  const float lineHeight = ImGui::GetTextLineHeight();
  const float titleGap = 0.5f * lineHeight + 4.0f * scale;
  const ImVec2 windowSize(
      contentWidth + 2.0f * padding.x,
      lineHeight + titleGap + barSize.y + 0.5f * lineHeight + 2.0f * padding.y + 2.0f * scale);
  ImGui::SetNextWindowPos(ImVec2(viewMax.x - windowSize.x - 12.0f * scale,
                                 viewMax.y - windowSize.y - 12.0f * scale));
  ImGui::SetNextWindowSize(windowSize);
  ImGui::SetNextWindowBgAlpha(0.55f);
  ImGui::Begin("Legend", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                   ImGuiWindowFlags_NoNav);
  ImGui::TextUnformatted(title.c_str());
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const ImVec2 below = ImGui::GetCursorScreenPos();
  // On whole pixels: the ends of the bar then show the ends of the map exactly.
  const ImVec2 top(std::floor(below.x), std::floor(ImGui::GetItemRectMax().y + titleGap));
  // High values at the top: the bar is drawn in slices, each a vertical gradient.
  constexpr int kSlices = 32;
  for (int k = 0; k < kSlices; ++k) {
    const float t0 = 1.0f - static_cast<float>(k) / kSlices;
    const float t1 = 1.0f - static_cast<float>(k + 1) / kSlices;
    const glm::vec3 c0 = render::colourMap(t0), c1 = render::colourMap(t1);
    const ImU32 u0 = ImGui::ColorConvertFloat4ToU32(ImVec4(c0.x, c0.y, c0.z, 1.0f));
    const ImU32 u1 = ImGui::ColorConvertFloat4ToU32(ImVec4(c1.x, c1.y, c1.z, 1.0f));
    const float y0 = top.y + barSize.y * static_cast<float>(k) / kSlices;
    const float y1 = top.y + barSize.y * static_cast<float>(k + 1) / kSlices;
    draw->AddRectFilledMultiColor(ImVec2(top.x, y0), ImVec2(top.x + barSize.x, y1), u0, u0, u1, u1);
  }
  draw->AddRect(top, ImVec2(top.x + barSize.x, top.y + barSize.y), IM_COL32(230, 230, 230, 200));
  const float labelX = top.x + barSize.x + 6.0f * scale;
  for (int k = 0; k < 3; ++k) {
    const float y = top.y + barSize.y * 0.5f * static_cast<float>(k) - 0.5f * lineHeight;
    draw->AddText(ImVec2(labelX, y), IM_COL32(235, 235, 235, 255), labels[k].c_str());
  }
  ImGui::SetCursorScreenPos(top);
  ImGui::Dummy(barSize);
  ImGui::End();
}

}  // namespace sculpt::app
