#pragma once
// The sculpting tools as the left panel edits them (docs/design/ux.md "Brushes", "Material
// painting"), and their round trip through a project's tool settings (saved with the project, never
// undo entries).
//
// Physical tools act on the running simulation and are not edits: pull/push (a spring from the
// material point under the cursor to the cursor), inflate/deflate (pressure inside the brush
// while held), curve (draw a curve on the surface, then drag it). Edits of the user's work, one
// undo entry per stroke or operation: paint (material into the volume), pin/unpin (control
// points inside the brush) and the topology operations on the control mesh.

#include <array>
#include <string>

#include "fem/material.h"
#include "project/preferences.h"
#include "project/project.h"
#include "tools/material_brush.h"

namespace sculpt::app {

enum class ToolKind { Pull = 0, Inflate, Curve, Paint, Pin, Topology };
inline constexpr int kToolCount = 6;
const char* toolName(ToolKind tool);
/// The tool's name in project and preference keys ("pull", "inflate", ...).
const char* toolKey(ToolKind tool);
/// True for the tools drawn with a brush circle (radius, strength, falloff).
bool isBrushTool(ToolKind tool);

enum class PaintField { Youngs = 0, Density, Damping };

enum class TopologyTool { Extrude = 0, Delete, Subdivide, Bridge, Weld, Crease, Corner };
inline constexpr int kTopologyToolCount = 7;
const char* topologyToolName(TopologyTool operation);
/// Operations that need two faces (the first click selects, the second applies).
bool needsTwoFaces(TopologyTool operation);

inline constexpr double kMinPressureFraction = 1e-4, kMaxPressureFraction = 0.1;
inline constexpr double kDefaultPressureFraction = 0.05;

inline constexpr float kDefaultBrushRadiusPixels = 50.0f;
inline constexpr float kMinBrushRadiusPixels = static_cast<float>(BrushRadii::kMinPixels);
inline constexpr float kMaxBrushRadiusPixels = static_cast<float>(BrushRadii::kMaxPixels);

/// One tool's brush (docs/design/ux.md: radius in screen pixels).
struct BrushSettings {
  float radiusPixels = kDefaultBrushRadiusPixels;
  float strength = 0.5f;  ///< [0, 1]: how far a dab moves a sample to the target; pin ignores it
  Falloff falloff = Falloff::Smooth;
  bool operator==(const BrushSettings&) const = default;
};

/// A tool's brush as strokes, keys and the panel change it: the tool's own strength and falloff,
/// and its own radius or, with the unified radius on, the shared one.
struct BrushRef {
  float& radiusPixels;
  float& strength;
  Falloff& falloff;
};

struct ToolState {
  ToolKind tool = ToolKind::Pull;
  // Each tool keeps its own brush, as in Blender: a large inflate leaves paint's radius alone.
  std::array<BrushSettings, kToolCount> brushes{};  ///< by ToolKind; only brush tools use theirs
  bool unifiedRadius = false;  ///< every tool uses unifiedRadiusPixels instead of its own radius
  float unifiedRadiusPixels = kDefaultBrushRadiusPixels;

  /// The current tool's brush (or `kind`'s), with the radius in use.
  BrushRef brush() { return brush(tool); }
  BrushSettings brush() const { return brush(tool); }
  BrushRef brush(ToolKind kind);
  BrushSettings brush(ToolKind kind) const;
  /// Turning the unified radius on shares the current tool's radius (nothing on screen jumps);
  /// turning it off gives each tool back its own.
  void setUnifiedRadius(bool on);

  bool mirrorX = true, mirrorY = false, mirrorZ = false;
  // Pull
  bool keepOnRelease = false;
  // Inflate: the pressure as a fraction of the scene's Young's modulus (Ctrl deflates), so that
  // the default visibly inflates any scene and the largest still has an equilibrium: an
  // inflated patch of a co-rotated solid runs away above about a third of E (docs/fem.md).
  double pressureFraction = kDefaultPressureFraction;
  // Paint: which field and the values painted
  PaintField field = PaintField::Youngs;
  Material paint{3000.0, 2000.0, 3.0e7, 0.3};  // density, damping, E, nu
  // Curve: profile along the curve ("rigid" or "smooth")
  bool smoothCurve = true;
  // Topology
  TopologyTool operation = TopologyTool::Extrude;
  double extrudeCells = 1.0;  ///< extrusion distance in control cell sizes
};

/// The brush settings of a paint dab of `state` (its field only; mirror planes through
/// `mirrorCentre`), with `radius` in rest metres.
MaterialBrushSettings paintBrush(const ToolState& state, double radius,
                                 const Eigen::Vector3d& mirrorCentre);

/// The tool state as project tool settings ("tool.paint.radiusPixels", ...) and back; keys
/// missing or of the wrong kind keep the defaults, out-of-range values are clamped. A project
/// written before brushes were per tool has one "tool.radiusPixels" (and strength, falloff):
/// every tool gets it.
void storeToolState(const ToolState& state, ToolSettings& settings);
ToolState loadToolState(const ToolSettings& settings);

/// The brush radii kept in the preferences, so that a new window starts with the radii the user
/// last used; restoring leaves tools the preferences do not name as they are.
BrushRadii brushRadii(const ToolState& state);
void restoreBrushRadii(ToolState& state, const BrushRadii& radii);

}  // namespace sculpt::app
