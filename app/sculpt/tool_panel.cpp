#include "sculpt/tool_panel.h"

#include <imgui.h>

#include "sculpt/value_slider.h"

namespace sculpt::app {
namespace {

void mirrorSettings(ToolState& t);
void pressureSlider(ToolState& t, double youngs);

constexpr double kExtrudeMin = 0.05, kExtrudeMax = 5.0;

// The current tool's own brush (each tool keeps its own, as in Blender).
void brushSettings(ToolState& t) {
  const BrushRef brush = t.brush();
  valueSliderFloat("Radius", &brush.radiusPixels, kMinBrushRadiusPixels, 400.0f, "%.0f px",
                   ImGuiSliderFlags_Logarithmic);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("F + drag, or [ and ]");
  bool unified = t.unifiedRadius;
  if (ImGui::Checkbox("Unified radius", &unified)) t.setUnifiedRadius(unified);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("One radius for every brush; off, each brush has its own again.");
  if (t.tool != ToolKind::Pin) {
    valueSliderFloat("Strength", &brush.strength, 0.0f, 1.0f, "%.2f");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Shift+F + drag");
    int falloff = static_cast<int>(brush.falloff);
    if (ImGui::Combo("Falloff", &falloff, "Smooth\0Sphere\0Linear\0Sharp\0Constant\0"))
      brush.falloff = static_cast<Falloff>(falloff);
  }
  if (t.tool == ToolKind::Paint) mirrorSettings(t);
}

// In Pa, over a range that follows the scene's Young's modulus (ToolState::pressureFraction).
void pressureSlider(ToolState& t, double youngs) {
  double pressure = t.pressureFraction * youngs;
  if (logValueSlider("Pressure", &pressure, kMinPressureFraction * youngs,
                     kMaxPressureFraction * youngs, "%.3g Pa"))
    t.pressureFraction = pressure / youngs;
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("Up to a tenth of the solid's Young's modulus (%.3g Pa): above about a "
                      "third an inflated patch has no equilibrium and runs away.",
                      youngs);
}

// Symmetry planes through the centre of the control mesh's box (paint and topology).
void mirrorSettings(ToolState& t) {
  ImGui::TextUnformatted("Mirror");
  ImGui::SameLine();
  ImGui::Checkbox("X", &t.mirrorX);
  ImGui::SameLine();
  ImGui::Checkbox("Y", &t.mirrorY);
  ImGui::SameLine();
  ImGui::Checkbox("Z", &t.mirrorZ);
}

}  // namespace

void drawToolSettings(AppModel& m) {
  ToolState& t = m.tools;
  ImGui::TextDisabled("Tools");
  for (int k = 0; k < kToolCount; ++k) {
    const auto tool = static_cast<ToolKind>(k);
    if (ImGui::RadioButton(toolName(tool), t.tool == tool)) {
      t.tool = tool;
      if (tool == ToolKind::Topology) m.display.showControlMesh = true;  // what it edits
    }
  }
  ImGui::Separator();
  ImGui::PushItemWidth(-ImGui::GetFontSize() * 4.5f);
  switch (t.tool) {
    case ToolKind::Pull:
      ImGui::TextWrapped("Drag on the surface. Ctrl pushes.");
      ImGui::Checkbox("Keep spring", &t.keepOnRelease);
      if (ImGui::IsItemHovered())
        ImGui::SetTooltip("The spring stays where it was when the button is released");
      break;
    case ToolKind::Inflate:
      ImGui::TextWrapped("Hold on the surface. Ctrl deflates.");
      brushSettings(t);
      pressureSlider(t, m.settings.material.youngs);
      break;
    case ToolKind::Curve:
      ImGui::TextWrapped("Draw a curve on the surface, then drag it with Shift.");
      ImGui::Checkbox("Smooth profile", &t.smoothCurve);
      break;
    case ToolKind::Paint: {
      ImGui::TextWrapped("Paint into the volume. Ctrl+click picks the value.");
      int field = static_cast<int>(t.field);
      if (ImGui::Combo("Field", &field, "Young's modulus\0Density\0Damping\0"))
        t.field = static_cast<PaintField>(field);
      if (t.field == PaintField::Youngs)
        logValueSlider("Value", &t.paint.youngs, 1e3, 1e9, "%.3g Pa");
      else if (t.field == PaintField::Density)
        logValueSlider("Value", &t.paint.density, 1.0, 1e5, "%.4g kg/m^3");
      else
        logValueSlider("Value", &t.paint.damping, 0.01, 1e5, "%.3g kg/m^3/s");
      brushSettings(t);
      break;
    }
    case ToolKind::Pin:
      ImGui::TextWrapped("Paint pins on control points. Ctrl unpins.");
      brushSettings(t);
      break;
    case ToolKind::Topology: {
      int operation = static_cast<int>(t.operation);
      const auto name = [](void*, int i, const char** out) {
        *out = topologyToolName(static_cast<TopologyTool>(i));
        return true;
      };
      if (ImGui::Combo("##operation", &operation, name, nullptr, kTopologyToolCount))
        t.operation = static_cast<TopologyTool>(operation);
      if (t.operation == TopologyTool::Extrude)
        valueSliderDouble("Distance", &t.extrudeCells, kExtrudeMin, kExtrudeMax, "%.2f cells");
      if (!needsTwoFaces(t.operation)) mirrorSettings(t);
      ImGui::TextWrapped(needsTwoFaces(t.operation)
                             ? "Click two boundary faces of the control mesh."
                             : "Click a boundary face of the control mesh.");
      if (!m.topologySelection.empty()) ImGui::TextWrapped("%s", m.topologySelection.c_str());
      break;
    }
  }
  ImGui::PopItemWidth();
}

}  // namespace sculpt::app
