#include "sculpt/tool_state.h"

#include <algorithm>
#include <cmath>

#include "sculpt/tool_setting_values.h"

namespace sculpt::app {

const char* toolName(ToolKind tool) {
  static const char* const kNames[] = {"Pull / push", "Inflate / deflate", "Curve",
                                       "Paint material", "Pin / unpin", "Topology"};
  return kNames[static_cast<int>(tool)];
}

const char* toolKey(ToolKind tool) {
  static const char* const kKeys[] = {"pull", "inflate", "curve", "paint", "pin", "topology"};
  return kKeys[static_cast<int>(tool)];
}

bool isBrushTool(ToolKind tool) {
  return tool == ToolKind::Inflate || tool == ToolKind::Paint || tool == ToolKind::Pin;
}

const char* topologyToolName(TopologyTool operation) {
  static const char* const kNames[] = {"Extrude face", "Delete cell",  "Subdivide cell",
                                       "Bridge two faces", "Weld two faces", "Crease face edges",
                                       "Corner at face vertices"};
  return kNames[static_cast<int>(operation)];
}

bool needsTwoFaces(TopologyTool operation) {
  return operation == TopologyTool::Bridge || operation == TopologyTool::Weld;
}

BrushRef ToolState::brush(ToolKind kind) {
  BrushSettings& own = brushes[static_cast<size_t>(kind)];
  return {unifiedRadius ? unifiedRadiusPixels : own.radiusPixels, own.strength, own.falloff};
}

BrushSettings ToolState::brush(ToolKind kind) const {
  BrushSettings settings = brushes[static_cast<size_t>(kind)];
  if (unifiedRadius) settings.radiusPixels = unifiedRadiusPixels;
  return settings;
}

void ToolState::setUnifiedRadius(bool on) {
  if (on && !unifiedRadius) unifiedRadiusPixels = brushes[static_cast<size_t>(tool)].radiusPixels;
  unifiedRadius = on;
}

MaterialBrushSettings paintBrush(const ToolState& state, double radius,
                                 const Eigen::Vector3d& mirrorCentre) {
  const BrushSettings paint = state.brush(ToolKind::Paint);
  MaterialBrushSettings brush;
  brush.radius = radius;
  brush.strength = paint.strength;
  brush.falloff = paint.falloff;
  brush.target = state.paint;
  brush.fields = {state.field == PaintField::Density, state.field == PaintField::Damping,
                  state.field == PaintField::Youngs, false};
  brush.mirror = {state.mirrorX, state.mirrorY, state.mirrorZ, mirrorCentre};
  return brush;
}

namespace {

int clampIndex(double value, int count, int fallback) {
  return std::isfinite(value) && value >= 0 && value < count ? static_cast<int>(value) : fallback;
}

float clampRadius(double pixels, float fallback) {
  return static_cast<float>(
      clampFinite(pixels, kMinBrushRadiusPixels, kMaxBrushRadiusPixels, fallback));
}

std::string brushKey(ToolKind tool, const char* field) {
  return std::string("tool.") + toolKey(tool) + "." + field;
}

// The tools whose brushes are kept in projects and preferences.
constexpr ToolKind kBrushTools[] = {ToolKind::Inflate, ToolKind::Paint, ToolKind::Pin};

}  // namespace

void storeToolState(const ToolState& s, ToolSettings& t) {
  t["tool.kind"] = static_cast<double>(static_cast<int>(s.tool));
  t["tool.unifiedRadius"] = s.unifiedRadius;
  t["tool.radiusPixels"] = static_cast<double>(s.unifiedRadiusPixels);  // the shared radius
  for (const ToolKind tool : kBrushTools) {
    const BrushSettings& own = s.brushes[static_cast<size_t>(tool)];
    t[brushKey(tool, "radiusPixels")] = static_cast<double>(own.radiusPixels);
    t[brushKey(tool, "strength")] = static_cast<double>(own.strength);
    t[brushKey(tool, "falloff")] = std::string(falloffName(own.falloff));
  }
  t["tool.mirrorX"] = s.mirrorX;
  t["tool.mirrorY"] = s.mirrorY;
  t["tool.mirrorZ"] = s.mirrorZ;
  t["tool.keepOnRelease"] = s.keepOnRelease;
  t["tool.pressureFraction"] = s.pressureFraction;
  t["tool.paintField"] = static_cast<double>(static_cast<int>(s.field));
  t["tool.paintYoungs"] = s.paint.youngs;
  t["tool.paintDensity"] = s.paint.density;
  t["tool.paintDamping"] = s.paint.damping;
  t["tool.smoothCurve"] = s.smoothCurve;
  t["tool.topologyOperation"] = static_cast<double>(static_cast<int>(s.operation));
  t["tool.extrudeCells"] = s.extrudeCells;
}

ToolState loadToolState(const ToolSettings& t) {
  ToolState s;
  s.tool = static_cast<ToolKind>(clampIndex(settingOr(t, "tool.kind", 0.0), kToolCount, 0));
  // Before brushes were per tool, "tool.radiusPixels", "tool.strength" and "tool.falloff" were
  // every tool's: they are the fallback of each tool's own keys.
  const BrushSettings defaults;
  const double radius =
      settingOr(t, "tool.radiusPixels", static_cast<double>(defaults.radiusPixels));
  const double strength = settingOr(t, "tool.strength", static_cast<double>(defaults.strength));
  const std::string falloff =
      settingOr(t, "tool.falloff", std::string(falloffName(defaults.falloff)));
  s.unifiedRadius = settingOr(t, "tool.unifiedRadius", false);
  s.unifiedRadiusPixels = clampRadius(radius, defaults.radiusPixels);
  for (const ToolKind tool : kBrushTools) {
    BrushSettings& own = s.brushes[static_cast<size_t>(tool)];
    own.radiusPixels =
        clampRadius(settingOr(t, brushKey(tool, "radiusPixels"), radius), defaults.radiusPixels);
    own.strength = static_cast<float>(
        clampFinite(settingOr(t, brushKey(tool, "strength"), strength), 0, 1, defaults.strength));
    own.falloff =
        parseFalloff(settingOr(t, brushKey(tool, "falloff"), falloff)).value_or(defaults.falloff);
  }
  s.mirrorX = settingOr(t, "tool.mirrorX", true);
  s.mirrorY = settingOr(t, "tool.mirrorY", false);
  s.mirrorZ = settingOr(t, "tool.mirrorZ", false);
  s.keepOnRelease = settingOr(t, "tool.keepOnRelease", false);
  s.pressureFraction =
      clampFinite(settingOr(t, "tool.pressureFraction", s.pressureFraction), kMinPressureFraction,
                  kMaxPressureFraction, kDefaultPressureFraction);
  s.field = static_cast<PaintField>(clampIndex(settingOr(t, "tool.paintField", 0.0), 3, 0));
  s.paint.youngs = clampFinite(settingOr(t, "tool.paintYoungs", s.paint.youngs), 1e3, 1e9, 3e7);
  s.paint.density = clampFinite(settingOr(t, "tool.paintDensity", s.paint.density), 1.0, 1e5, 3000);
  s.paint.damping = clampFinite(settingOr(t, "tool.paintDamping", s.paint.damping), 0.0, 1e5, 2000);
  s.smoothCurve = settingOr(t, "tool.smoothCurve", true);
  s.operation = static_cast<TopologyTool>(
      clampIndex(settingOr(t, "tool.topologyOperation", 0.0), kTopologyToolCount, 0));
  s.extrudeCells = clampFinite(settingOr(t, "tool.extrudeCells", 1.0), 0.05, 10.0, 1.0);
  return s;
}

BrushRadii brushRadii(const ToolState& state) {
  BrushRadii radii;
  radii.unified = state.unifiedRadius;
  radii.unifiedPixels = state.unifiedRadiusPixels;
  for (const ToolKind tool : kBrushTools)
    radii.byTool[toolKey(tool)] = state.brushes[static_cast<size_t>(tool)].radiusPixels;
  return radii;
}

void restoreBrushRadii(ToolState& state, const BrushRadii& radii) {
  state.unifiedRadius = radii.unified;
  state.unifiedRadiusPixels = clampRadius(radii.unifiedPixels, kDefaultBrushRadiusPixels);
  for (const ToolKind tool : kBrushTools)
    if (const auto it = radii.byTool.find(toolKey(tool)); it != radii.byTool.end()) {
      float& radius = state.brushes[static_cast<size_t>(tool)].radiusPixels;
      radius = clampRadius(it->second, radius);
    }
}

}  // namespace sculpt::app
