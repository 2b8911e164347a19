#pragma once
// The sculpting tools as the left panel edits them (docs/design/ux.md "Brushes", "Material painting"), and
// their round trip through a project's tool settings (saved with the project, never undo
// entries).
//
// Physical tools act on the running simulation and are not edits: pull/push (a spring from the
// material point under the cursor to the cursor), inflate/deflate (pressure inside the brush
// while held), curve (draw a curve on the surface, then drag it). Edits of the user's work, one
// undo entry per stroke or operation: paint (material into the volume), pin/unpin (control
// points inside the brush) and the topology operations on the control mesh.

#include <string>

#include "fem/material.h"
#include "project/project.h"
#include "tools/material_brush.h"

namespace sculpt::app {

enum class ToolKind { Pull = 0, Inflate, Curve, Paint, Pin, Topology };
inline constexpr int kToolCount = 6;
const char* toolName(ToolKind tool);
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

struct ToolState {
  ToolKind tool = ToolKind::Pull;
  // Brush (docs/design/ux.md: radius in screen pixels)
  float radiusPixels = 50.0f;
  float strength = 0.5f;  ///< [0, 1]: how far a dab moves a sample to the target; pin ignores it
  Falloff falloff = Falloff::Smooth;
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

/// The tool state as project tool settings ("tool.radius", ...) and back; keys missing or of the
/// wrong kind keep the defaults, out-of-range values are clamped.
void storeToolState(const ToolState& state, ToolSettings& settings);
ToolState loadToolState(const ToolSettings& settings);

}  // namespace sculpt::app
