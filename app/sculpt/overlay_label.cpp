#include "sculpt/overlay_label.h"

namespace sculpt::app {

ImVec4 drawOverlayLabel(ImDrawList* draw, ImVec2 anchor, float clearance, ImU32 colour,
                        const char* text) {
  const float scale = ImGui::GetFontSize() / 13.0f;
  const ImVec2 size = ImGui::CalcTextSize(text);
  const ImVec2 pad(4.0f * scale, 2.0f * scale);
  const ImVec2 min(anchor.x + clearance + 6.0f * scale, anchor.y - 0.5f * size.y - pad.y);
  const ImVec2 max(min.x + size.x + 2.0f * pad.x, min.y + size.y + 2.0f * pad.y);
  draw->AddRectFilled(min, max, IM_COL32(18, 18, 22, 200), 3.0f * scale);
  draw->AddText(ImVec2(min.x + pad.x, min.y + pad.y), colour, text);
  return ImVec4(min.x, min.y, max.x, max.y);
}

}  // namespace sculpt::app
