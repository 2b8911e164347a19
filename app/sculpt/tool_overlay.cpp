// SculptApp: what is drawn over the 3D view for the tools (tool_state.h): each tool's cursor
// (brush circle with its falloff ring; pull's grab point and depth ring; curve's point), the
// mirror planes, the curve being drawn, the faces of the topology tool, and the pull springs'
// forces.

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "sculpt/overlay_label.h"
#include "sculpt/point_conversions.h"
#include "sculpt/sculpt_app.h"

namespace sculpt::app {
namespace {

ImU32 colour(int r, int g, int b, int a = 255) { return IM_COL32(r, g, b, a); }

// The pull cursor in the pull spring's colour (scene_view.cpp), the curve's cursor in the curve's.
const ImU32 kPullColour = colour(255, 89, 51);
const ImU32 kCurveColour = colour(80, 220, 255);
// A faint dark edge under the cursors' strokes, so that they show on light surfaces too.
const ImU32 kCursorShadow = colour(0, 0, 0, 90);
// The pull cursor's ring: a disc of this fraction of the scene's radius in the view plane at the
// grabbed depth, so that its size on screen tells how deep the grab is.
constexpr float kPullRingFraction = 0.04f;

// Where the falloff weight is 1/2 (the inner ring), as a fraction of the radius.
float halfWeightFraction(Falloff falloff) {
  double lo = 0.0, hi = 1.0;
  for (int k = 0; k < 40; ++k) {
    const double mid = 0.5 * (lo + hi);
    (falloffWeight(falloff, mid, 1.0) > 0.5 ? lo : hi) = mid;
  }
  return static_cast<float>(lo);
}

}  // namespace

void SculptApp::drawToolOverlay(const ViewRect& view) {
  if (!view_.hasGeometry()) return;
  ImDrawList* draw = ImGui::GetBackgroundDrawList();
  draw->PushClipRect(view.min, view.max, true);
  if (stylus_.active()) {
    stylus_.drawCursor(draw, camera_, view.min, view.max);
    draw->PopClipRect();
    return;
  }
  const int width = std::max(1, static_cast<int>(view.max.x - view.min.x));
  const int height = std::max(1, static_cast<int>(view.max.y - view.min.y));
  const auto screen = [&](const glm::vec3& world) {
    const glm::vec3 p = camera_.project(world, width, height);
    return ImVec2(view.min.x + p.x, view.min.y + p.y);
  };
  const ToolState& t = model_.tools;
  const BrushSettings brush = t.brush();
  const ImVec2 mouse = ImGui::GetIO().MousePos;
  const bool inView = mouse.x >= view.min.x && mouse.y >= view.min.y && mouse.x < view.max.x &&
                      mouse.y < view.max.y && !ImGui::GetIO().WantCaptureMouse;
  // The surface point under the cursor, from the depth read in the last frame; the ground grid
  // writes depth too, but lies outside the box of the control points (the solid lies inside
  // their hull).
  std::optional<glm::vec3> hovered =
      inView && cursorDepth_ < 1.0f ? camera_.unproject(mouse.x - view.min.x, mouse.y - view.min.y,
                                                        cursorDepth_, width, height)
                                    : std::nullopt;
  if (const Points& control = view_.frame().control; hovered && control.rows() > 0) {
    const Eigen::Vector3d slack = Eigen::Vector3d::Constant(0.01 * view_.radius());
    const Eigen::Vector3d lo = control.colwise().minCoeff().transpose() - slack;
    const Eigen::Vector3d hi = control.colwise().maxCoeff().transpose() + slack;
    const Eigen::Vector3d p = toEigen(*hovered);
    if ((p.array() < lo.array()).any() || (p.array() > hi.array()).any()) hovered.reset();
  }
  if ((t.tool == ToolKind::Paint ||
       (t.tool == ToolKind::Topology && !needsTwoFaces(t.operation))) &&
      (t.mirrorX || t.mirrorY || t.mirrorZ)) {
    // The symmetry planes through the rest control box's centre, as the box's mid sections.
    const Points& control = view_.geometry()->restControl;
    const Eigen::Vector3d lo = control.colwise().minCoeff(), hi = control.colwise().maxCoeff();
    const Eigen::Vector3d c = mirrorCentre();
    const bool axes[3] = {t.mirrorX, t.mirrorY, t.mirrorZ};
    for (int axis = 0; axis < 3; ++axis) {
      if (!axes[axis]) continue;
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      ImVec2 corners[4];
      for (int k = 0; k < 4; ++k) {
        Eigen::Vector3d p = c;
        p[u] = (k == 1 || k == 2) ? hi[u] : lo[u];
        p[v] = k >= 2 ? hi[v] : lo[v];
        corners[k] = screen(glm::vec3(p.x(), p.y(), p.z()));
      }
      draw->AddQuadFilled(corners[0], corners[1], corners[2], corners[3], colour(230, 60, 60, 40));
      draw->AddQuad(corners[0], corners[1], corners[2], corners[3], colour(230, 60, 60, 160), 1.5f);
    }
  }
  // The cursors, over the planes.
  if (isBrushTool(t.tool) && (inView || brushKey_ >= 0)) {
    const ImVec2 centre =
        brushKey_ >= 0 ? ImVec2(lastDabX_ + view.min.x, lastDabY_ + view.min.y) : mouse;
    const ImU32 ring = t.tool == ToolKind::Pin ? colour(255, 90, 80) : colour(255, 255, 255, 220);
    draw->AddCircle(centre, brush.radiusPixels, kCursorShadow, 48,
                    3.5f);  // shows on light surfaces
    draw->AddCircle(centre, brush.radiusPixels, ring, 48, 1.5f);
    if (t.tool != ToolKind::Pin && brush.falloff != Falloff::Constant)
      draw->AddCircle(centre, brush.radiusPixels * halfWeightFraction(brush.falloff),
                      colour(255, 255, 255, 110), 48, 1.0f);
    if (brushKey_ >= 0) {
      char text[48];
      if (brushKeyStrength_)
        std::snprintf(text, sizeof text, "strength %.2f", brush.strength);
      else
        std::snprintf(text, sizeof text,
                      t.unifiedRadius ? "radius %.0f px (unified)" : "radius %.0f px",
                      brush.radiusPixels);
      drawOverlayLabel(draw, centre, brush.radiusPixels, colour(255, 255, 255), text);
    }
  }
  const bool pulling = stroke_ != 0 && strokeTool_ == ToolKind::Pull;  // its spring is drawn
  if (t.tool == ToolKind::Pull && hovered && !pulling) {
    // Where a drag grabs, and a ring of a fixed size in the plane the grabbed point will move in.
    const ImVec2 centre = screen(*hovered);
    const ImVec2 edge = screen(*hovered + kPullRingFraction * view_.radius() * camera_.right());
    const float ring = std::clamp(std::hypot(edge.x - centre.x, edge.y - centre.y), 5.0f, 80.0f);
    draw->AddCircle(centre, ring, kCursorShadow, 40, 4.0f);
    draw->AddCircle(centre, ring, kPullColour, 40, 2.0f);
    draw->AddCircleFilled(centre, 4.5f, kCursorShadow, 16);
    draw->AddCircleFilled(centre, 3.5f, kPullColour, 16);
  }
  if (t.tool == ToolKind::Curve && hovered && !curveGrabbed_) {
    // Where the curve's next point goes (or, with Shift, where a drag of the curve starts).
    const ImVec2 centre = screen(*hovered);
    draw->AddCircle(centre, 8.0f, kCursorShadow, 24, 3.5f);
    draw->AddCircle(centre, 8.0f, kCurveColour, 24, 1.5f);
    draw->AddCircleFilled(centre, 4.0f, kCursorShadow, 12);
    draw->AddCircleFilled(centre, 3.0f, kCurveColour, 12);
  }
  // The force of each pull spring, at its target.
  const SceneFrame& frame = view_.frame();
  for (const ToolSpring& spring : frame.springs) {
    if (!std::isfinite(spring.force)) continue;
    const Eigen::Vector3d& target = spring.target;
    char text[48];
    // In units of the solid's weight too: "3.7e6 N" says little about a 1,600 t bunny.
    if (frame.weight > 0)
      std::snprintf(text, sizeof text, "%.3g N (%.2gx weight)", spring.force,
                    spring.force / frame.weight);
    else
      std::snprintf(text, sizeof text, "%.3g N", spring.force);
    const ImVec2 at = screen(glm::vec3(target.x(), target.y(), target.z()));
    // Beside the spring's end dot (8 px across), on a backdrop: readable on the light model.
    drawOverlayLabel(draw, at, 5.0f, colour(255, 150, 130), text);
  }
  if (!curveWorld_.empty() && t.tool == ToolKind::Curve) {
    std::vector<ImVec2> points;
    for (const glm::vec3& p : curveWorld_) points.push_back(screen(p));
    draw->AddPolyline(points.data(), static_cast<int>(points.size()), kCurveColour, 0, 3.0f);
  }
  if (t.tool == ToolKind::Topology) {
    const Points& control = view_.frame().control;
    const auto outline = [&](const PickedFace& face, ImU32 line, ImU32 fill) {
      std::vector<ImVec2> points;
      for (const uint32_t v : face.loop)
        if (v < control.rows()) points.push_back(screen(pointRow(control, v)));
      if (points.size() < 3) return;
      draw->AddConvexPolyFilled(points.data(), static_cast<int>(points.size()), fill);
      draw->AddPolyline(points.data(), static_cast<int>(points.size()), line, ImDrawFlags_Closed,
                        2.5f);
    };
    if (hoverFace_ && inView) outline(*hoverFace_, colour(80, 220, 255), colour(80, 220, 255, 70));
    if (firstFace_) outline(*firstFace_, colour(255, 120, 30), colour(255, 120, 30, 90));
  }
  draw->PopClipRect();
}

}  // namespace sculpt::app
