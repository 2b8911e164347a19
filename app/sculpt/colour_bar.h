#pragma once
// The legend of the field shown: a vertical colour bar with its label, unit and end values,
// drawn with ImGui in the lower right corner of the 3D view.

#include <imgui.h>

#include "sculpt/display_settings.h"
#include "sculpt/scene_view.h"

namespace sculpt::app {

/// `viewMin`/`viewMax`: the 3D view's rectangle in ImGui coordinates.
void drawColourBar(FieldKind field, FieldRange range, ImVec2 viewMin, ImVec2 viewMax);

/// A value with 3 significant digits and an SI-style exponent when needed ("3.00e+06").
std::string formatValue(double value);

}  // namespace sculpt::app
