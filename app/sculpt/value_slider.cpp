#include "sculpt/value_slider.h"

#include <imgui_internal.h>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace sculpt::app {
namespace {

double asDouble(ImGuiDataType type, const void* value) {
  switch (type) {
    case ImGuiDataType_Float:
      return static_cast<double>(*static_cast<const float*>(value));
    case ImGuiDataType_Double:
      return *static_cast<const double*>(value);
    case ImGuiDataType_S32:
      return static_cast<double>(*static_cast<const int*>(value));
    default:
      return 0.0;
  }
}

}  // namespace

float sliderFraction(double value, double low, double high, bool logarithmic) {
  if (!(high > low) || !std::isfinite(value)) return 0.0f;
  double t = (value - low) / (high - low);
  if (logarithmic && low > 0.0 && value > 0.0) t = std::log(value / low) / std::log(high / low);
  return static_cast<float>(std::clamp(t, 0.0, 1.0));
}

bool valueSlider(const char* label, ImGuiDataType type, void* value, const void* low,
                 const void* high, const char* format, ImGuiSliderFlags flags) {
  // ImGui draws the frame and handles the input; its grab and text are made invisible (a
  // transparent grab, an empty format) and drawn here instead.
  // When the slider may turn into a text field this frame (Ctrl+click, double click, keyboard
  // activation) ImGui gets the real format, which fills the field with the value to edit.
  const ImGuiContext& g = *ImGui::GetCurrentContext();
  const ImGuiID id = ImGui::GetID(label);
  const bool typing = ImGui::TempInputIsActive(id);
  const bool mayStartTyping = typing || ImGui::IsMouseDoubleClicked(0) ||
                              (g.IO.KeyCtrl && ImGui::IsMouseClicked(0)) ||
                              g.NavActivateInputId == id;
  const float frameWidth = ImGui::CalcItemWidth();
  ImGui::PushStyleColor(ImGuiCol_SliderGrab, IM_COL32(0, 0, 0, 0));
  ImGui::PushStyleColor(ImGuiCol_SliderGrabActive, IM_COL32(0, 0, 0, 0));
  const bool changed =
      ImGui::SliderScalar(label, type, value, low, high, mayStartTyping ? format : "", flags);
  ImGui::PopStyleColor(2);
  if (typing || ImGui::TempInputIsActive(id)) return changed;

  const ImVec2 min = ImGui::GetItemRectMin();
  const ImVec2 max(min.x + frameWidth, ImGui::GetItemRectMax().y);
  const float t = sliderFraction(asDouble(type, value), asDouble(type, low), asDouble(type, high),
                                 (flags & ImGuiSliderFlags_Logarithmic) != 0);
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const float rounding = ImGui::GetStyle().FrameRounding;
  ImVec4 fill = ImGui::GetStyleColorVec4(ImGui::IsItemActive() ? ImGuiCol_SliderGrabActive
                                                               : ImGuiCol_SliderGrab);
  fill.w *= 0.55f;  // the text on top keeps its contrast
  if (t > 0.0f)
    draw->AddRectFilled(min, ImVec2(min.x + t * (max.x - min.x), max.y),
                        ImGui::ColorConvertFloat4ToU32(fill), rounding);

  if (mayStartTyping) return changed;  // ImGui drew the value, centred as below
  char text[64];
  ImGui::DataTypeFormatString(text, sizeof text, type, value, format);
  const float padding = ImGui::GetStyle().FramePadding.x;
  // A narrow frame (a large UI scale on a small window) shows the number without its unit, and
  // the whole value when hovered.
  if (ImGui::CalcTextSize(text).x > max.x - min.x - 2.0f * padding) {
    if (ImGui::IsItemHovered() && !ImGui::IsItemActive()) ImGui::SetTooltip("%s", text);
    if (char* space = std::strchr(text, ' ')) *space = 0;
  }
  const ImVec2 size = ImGui::CalcTextSize(text);
  // Centred; a value wider than the frame starts at its left edge and is clipped at its right.
  const float x = std::max(min.x + padding, 0.5f * (min.x + max.x - size.x));
  const ImVec4 clip(min.x + padding, min.y, max.x - padding, max.y);
  draw->AddText(nullptr, 0.0f, ImVec2(x, 0.5f * (min.y + max.y - size.y)),
                ImGui::GetColorU32(ImGuiCol_Text), text, nullptr, 0.0f, &clip);
  return changed;
}

bool valueSliderFloat(const char* label, float* value, float low, float high, const char* format,
                      ImGuiSliderFlags flags) {
  return valueSlider(label, ImGuiDataType_Float, value, &low, &high, format, flags);
}

bool valueSliderDouble(const char* label, double* value, double low, double high,
                       const char* format, ImGuiSliderFlags flags) {
  return valueSlider(label, ImGuiDataType_Double, value, &low, &high, format, flags);
}

bool valueSliderInt(const char* label, int* value, int low, int high, const char* format,
                    ImGuiSliderFlags flags) {
  return valueSlider(label, ImGuiDataType_S32, value, &low, &high, format, flags);
}

bool logValueSlider(const char* label, double* value, double low, double high, const char* format) {
  return valueSliderDouble(label, value, low, high, format,
                           ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp);
}

}  // namespace sculpt::app
