#include "sculpt/help_overlay.h"

#include <imgui.h>

namespace sculpt::app {
namespace {

/// "Numpad 1, 1" for an action bound to several chords.
std::string chordsOf(const KeyMap& keys, Action action) {
  std::string text;
  for (const KeyBinding& b : keys.bindingsOf(action))
    text += (text.empty() ? "" : ", ") + chordLabel(b.key, b.modifiers);
  return text;
}

/// A heading and a two-column table (keys, what they do) of the group's bound actions.
void drawGroup(const KeyMap& keys, ActionGroup group) {
  ImGui::TextUnformatted(std::string(actionGroupLabel(group)).c_str());
  ImGui::Separator();
  const std::string id = "keys_" + std::string(actionGroupLabel(group));
  if (!ImGui::BeginTable(id.c_str(), 2, ImGuiTableFlags_SizingFixedFit)) return;
  for (int a = 0; a < kActionCount; ++a) {
    const auto action = static_cast<Action>(a);
    if (actionGroup(action) != group) continue;
    const std::string chords = chordsOf(keys, action);
    if (chords.empty()) continue;  // unbound: nothing to press
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(chords.c_str());
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(std::string(actionLabel(action)).c_str());
  }
  ImGui::EndTable();
  ImGui::Spacing();
}

}  // namespace

std::vector<GestureHelp> gestureHelp(NavigationPreset preset) {
  std::vector<GestureHelp> rows;
  if (preset == NavigationPreset::Blender) {
    rows = {{"Middle drag", "Orbit"},
            {"Shift + middle drag", "Pan"},
            {"Ctrl + middle drag", "Zoom (up: in)"},
            {"Wheel", "Zoom"},
            {"Alt + left drag",
             "Orbit (Alt+Shift: pan, Alt+Ctrl: zoom), for mice without a middle button"},
            {"Left drag", "Tool stroke"}};
  } else {
    rows = {{"Left drag on the background", "Orbit"},
            {"Shift + left drag on the background", "Zoom (up: in)"},
            {"Alt + left drag, anywhere", "Pan"},
            {"Alt + Shift + left drag, anywhere", "Zoom"},
            {"Right drag (pen button), anywhere", "Orbit"},
            {"Left drag on the model", "Tool stroke"},
            {"Middle drag / wheel", "As in the Blender preset"}};
  }
  rows.push_back({"Double click on the model", "Orbit around that point"});
  return rows;
}

void drawHelpOverlay(const KeyMap& keys, NavigationPreset preset, bool* open) {
  if (!open || !*open) return;
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(viewport->GetWorkCenter(), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowSizeConstraints(
      ImVec2(0.0f, 0.0f), ImVec2(0.95f * viewport->WorkSize.x, 0.95f * viewport->WorkSize.y));
  ImGui::SetNextWindowBgAlpha(0.94f);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoCollapse |
                                 ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings;
  if (ImGui::Begin("Help: mouse and keys", open, flags)) {
    // Mouse gestures of the preset
    ImGui::Text("Mouse (%s preset)", std::string(presetName(preset)).c_str());
    ImGui::Separator();
    if (ImGui::BeginTable("mouse", 2, ImGuiTableFlags_SizingFixedFit)) {
      for (const GestureHelp& row : gestureHelp(preset)) {
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(row.gesture.c_str());
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(row.effect.c_str());
      }
      ImGui::EndTable();
    }
    ImGui::Spacing();
    // Keys: View on the left; Simulation, Display and File on the right. Two groups side by
    // side rather than an outer table: fixed-fit tables nested in a table of an auto-resizing
    // window collapse to a few pixels in ImGui 1.86.
    ImGui::BeginGroup();
    drawGroup(keys, ActionGroup::View);
    drawGroup(keys, ActionGroup::Edit);
    ImGui::EndGroup();
    ImGui::SameLine(0.0f, 3.0f * ImGui::GetStyle().ItemSpacing.x);
    ImGui::BeginGroup();
    drawGroup(keys, ActionGroup::Simulation);
    drawGroup(keys, ActionGroup::Display);
    drawGroup(keys, ActionGroup::File);
    ImGui::EndGroup();
    if (keys.actionFor('1', 0) == Action::ViewFront)  // GLFW_KEY_1 is '1'
      ImGui::TextDisabled("The top-row digits 1, 3, 7 and 5 stand in for the numpad on laptops.");
    ImGui::TextDisabled("Keys do nothing while a text field has the keyboard.");
    if (ImGui::IsWindowFocused() && ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false))
      *open = false;
  }
  ImGui::End();
}

}  // namespace sculpt::app
