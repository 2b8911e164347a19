#pragma once
// Sliders whose value stays readable: ImGui draws the value centred over the frame, where the
// grab block passes over it ("3e+06 Pa" half hidden). These draw the slider as a filled bar up
// to the value, as Blender's number fields do, with the value text centred on it and no grab
// block; dragging, Ctrl+click to type and the clamping are ImGui's own.

#include <imgui.h>

namespace sculpt::app {

/// ImGui::SliderScalar with the value drawn on a fill bar (`format` as ImGui's, for the type).
bool valueSlider(const char* label, ImGuiDataType type, void* value, const void* low,
                 const void* high, const char* format, ImGuiSliderFlags flags = 0);

bool valueSliderFloat(const char* label, float* value, float low, float high, const char* format,
                      ImGuiSliderFlags flags = 0);
bool valueSliderDouble(const char* label, double* value, double low, double high,
                       const char* format, ImGuiSliderFlags flags = 0);
bool valueSliderInt(const char* label, int* value, int low, int high, const char* format = "%d",
                    ImGuiSliderFlags flags = 0);
/// Logarithmic and clamped to [low, high]: physical quantities spanning decades.
bool logValueSlider(const char* label, double* value, double low, double high, const char* format);

/// Where the fill ends, as a fraction of the frame: linear, or logarithmic for positive ranges.
float sliderFraction(double value, double low, double high, bool logarithmic);

}  // namespace sculpt::app
