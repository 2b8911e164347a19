#include "sculpt/display_state.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "sculpt/tool_setting_values.h"

namespace sculpt::app {
namespace {

float clampedFloat(const ToolSettings& settings, const std::string& key, float lo, float hi,
                   float fallback) {
  return static_cast<float>(clampFinite(settingOr(settings, key, static_cast<double>(fallback)),
                                        double{lo}, double{hi}, double{fallback}));
}

// Sets `field` of `saved` to the command line's when that differs from the default.
template <typename T>
void takeIfSet(T& saved, const T& commandLine, const T& fallback) {
  if (!(commandLine == fallback)) saved = commandLine;
}

}  // namespace

void storeDisplayState(const DisplaySettings& d, ToolSettings& t) {
  t["display.method"] = std::string(methodName(d.method));
  t["display.gradients"] = std::string(gradientSchemeName(d.gradients));
  t["display.field"] = std::string(fieldName(d.field));
  t["display.smoothField"] = d.smoothField;
  t["display.autoRange"] = d.autoRange;
  t["display.rangeLow"] = static_cast<double>(d.rangeLow);
  t["display.rangeHigh"] = static_cast<double>(d.rangeHigh);
  t["display.showSurface"] = d.showSurface;
  t["display.flatShading"] = d.flatShading;
  t["display.wireframe"] = d.wireframe;
  t["display.showControlMesh"] = d.showControlMesh;
  t["display.showCells"] = d.showCells;
  t["display.showGrid"] = d.showGrid;
  t["display.showAxes"] = d.showAxes;
  t["display.clip"] = d.clip;
  t["display.clipAxis"] = static_cast<double>(d.clipAxis);
  t["display.clipPosition"] = static_cast<double>(d.clipPosition);
}

DisplaySettings loadDisplayState(const ToolSettings& t) {
  const DisplaySettings defaults;
  DisplaySettings d;
  d.method =
      parseInterpolationMethod(settingOr(t, "display.method", std::string(methodName(d.method))))
          .value_or(defaults.method);
  d.gradients = parseGradientScheme(
                    settingOr(t, "display.gradients", std::string(gradientSchemeName(d.gradients))))
                    .value_or(defaults.gradients);
  d.field = parseField(settingOr(t, "display.field", std::string(fieldName(d.field))))
                .value_or(defaults.field);
  d.smoothField = settingOr(t, "display.smoothField", defaults.smoothField);
  d.autoRange = settingOr(t, "display.autoRange", defaults.autoRange);
  // Any finite float: the manual range is in the field's own units (Pa, J/m^3 ...).
  constexpr float kLargest = std::numeric_limits<float>::max();
  d.rangeLow = clampedFloat(t, "display.rangeLow", -kLargest, kLargest, defaults.rangeLow);
  d.rangeHigh = clampedFloat(t, "display.rangeHigh", -kLargest, kLargest, defaults.rangeHigh);
  d.showSurface = settingOr(t, "display.showSurface", defaults.showSurface);
  d.flatShading = settingOr(t, "display.flatShading", defaults.flatShading);
  d.wireframe = settingOr(t, "display.wireframe", defaults.wireframe);
  d.showControlMesh = settingOr(t, "display.showControlMesh", defaults.showControlMesh);
  d.showCells = settingOr(t, "display.showCells", defaults.showCells);
  d.showGrid = settingOr(t, "display.showGrid", defaults.showGrid);
  d.showAxes = settingOr(t, "display.showAxes", defaults.showAxes);
  d.clip = settingOr(t, "display.clip", defaults.clip);
  const double axis = settingOr(t, "display.clipAxis", static_cast<double>(defaults.clipAxis));
  d.clipAxis = std::isfinite(axis) ? static_cast<int>(std::clamp(std::round(axis), 0.0, 2.0))
                                   : defaults.clipAxis;
  d.clipPosition = clampedFloat(t, "display.clipPosition", 0.0f, 1.0f, defaults.clipPosition);
  return d;
}

DisplaySettings withCommandLineDisplay(DisplaySettings saved, const DisplaySettings& commandLine) {
  const DisplaySettings defaults;
  takeIfSet(saved.method, commandLine.method, defaults.method);
  takeIfSet(saved.gradients, commandLine.gradients, defaults.gradients);
  takeIfSet(saved.field, commandLine.field, defaults.field);
  takeIfSet(saved.smoothField, commandLine.smoothField, defaults.smoothField);
  takeIfSet(saved.autoRange, commandLine.autoRange, defaults.autoRange);
  takeIfSet(saved.rangeLow, commandLine.rangeLow, defaults.rangeLow);
  takeIfSet(saved.rangeHigh, commandLine.rangeHigh, defaults.rangeHigh);
  takeIfSet(saved.showSurface, commandLine.showSurface, defaults.showSurface);
  takeIfSet(saved.flatShading, commandLine.flatShading, defaults.flatShading);
  takeIfSet(saved.wireframe, commandLine.wireframe, defaults.wireframe);
  takeIfSet(saved.showControlMesh, commandLine.showControlMesh, defaults.showControlMesh);
  takeIfSet(saved.showCells, commandLine.showCells, defaults.showCells);
  takeIfSet(saved.showGrid, commandLine.showGrid, defaults.showGrid);
  takeIfSet(saved.showAxes, commandLine.showAxes, defaults.showAxes);
  if (commandLine.clip) {  // --clip x|y|z sets the plane and its axis together
    saved.clip = true;
    saved.clipAxis = commandLine.clipAxis;
  }
  takeIfSet(saved.clipPosition, commandLine.clipPosition, defaults.clipPosition);
  return saved;
}

}  // namespace sculpt::app
