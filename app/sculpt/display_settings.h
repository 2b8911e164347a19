#pragma once
// What the Display panel edits: how the scene is drawn (not what is simulated).

#include <array>
#include <optional>
#include <string_view>

#include "embed/gradient_scheme.h"
#include "embed/interpolation_method.h"

namespace sculpt::app {

/// Scalar fields shown on the surface and on the clipping plane.
enum class FieldKind { None, YoungsModulus, Density, Displacement, StrainEnergy, Damping };
constexpr std::array<FieldKind, 6> kFieldKinds = {FieldKind::None,         FieldKind::YoungsModulus,
                                                  FieldKind::Density,      FieldKind::Displacement,
                                                  FieldKind::StrainEnergy, FieldKind::Damping};
std::string_view fieldName(FieldKind field);   ///< "youngs", "density", ... (command line)
std::string_view fieldLabel(FieldKind field);  ///< "Young's modulus" (UI)
std::string_view fieldUnit(FieldKind field);   ///< "Pa", "kg/m^3", "m", "J/m^3"
std::optional<FieldKind> parseField(std::string_view name);

struct DisplaySettings {
  InterpolationMethod method = InterpolationMethod::Phong;
  GradientScheme gradients = kDefaultGradientScheme;  ///< node gradients of phong and vertex
  FieldKind field = FieldKind::None;
  /// Cell fields (materials, strain energy) drawn smoothly from node values (embed/node_field.h);
  /// false: flat per level-K cell, to inspect the cells.
  bool smoothField = true;
  bool autoRange = true;  ///< the colour map spans the field's current minimum and maximum
  float rangeLow = 0.0f, rangeHigh = 1.0f;
  bool showSurface = true, flatShading = false, wireframe = false;
  bool showControlMesh = false, showCells = false, showGrid = true, showAxes = true;
  bool clip = false;           ///< clipping plane through the volume
  int clipAxis = 0;            ///< normal along x, y or z
  float clipPosition = 0.5f;   ///< along the axis, as a fraction of the rest bounding box
  bool operator==(const DisplaySettings&) const = default;
};

}  // namespace sculpt::app
