#pragma once
// The zero-length springs (PenaltySpringForm) that the drag tools (PullTool, CurveTool) attach
// to material points: the held ones follow the drag; release either lets them go (removed, the
// solid relaxes under its other loads) or keeps them, each target moved to where its point is at
// release, so the solid holds its new shape there. Kept springs stay until clearKept() or the
// set's destruction. Keeps a reference to the simulator, which must outlive it.

#include <Eigen/Core>
#include <vector>

#include "sim/load_forms.h"
#include "sim/material_point.h"
#include "sim/simulator.h"

namespace sculpt {

enum class ReleaseMode { LetGo, Keep };

/// Edge length of a typical element: cbrt(rest volume / #elements) (m).
double typicalCellSize(const FemModel& model);

/// The solid's own stiffness at a material point, F / u for a point load, measured on the
/// default bunny and on block3 at surface points along each axis: 0.5 to 3.6 E h (h the cell
/// size), median about 1.5 E h (tests/scene/pull_default_test.cpp).
inline constexpr double kPullStiffnessPerCell = 1.5;

/// kPullStiffnessPerCell x E x cell size (N/m), E the largest Young's modulus of the Gauss
/// samples: a spring about as stiff as the object where it is grabbed, so a drag of d moves the
/// point about d / 2 and pulls with the force the object itself answers with. A stiffer default
/// (10 E h) made the point follow the mouse whatever the material, with forces that drive the
/// solid to extremes on an ordinary drag.
double defaultPullStiffness(const FemModel& model);

/// `stiffness` when > 0, else defaultPullStiffness(model). Throws std::invalid_argument
/// ("<tool>: the spring stiffness is not finite.") for a non-finite value.
double toolStiffness(const FemModel& model, double stiffness, const char* tool);

/// Current positions of material points (the simulator's control points through the nodes).
std::vector<Eigen::Vector3d> currentPositions(Simulator& simulator,
                                              const std::vector<MaterialPoint>& points);

class ToolSprings {
 public:
  explicit ToolSprings(Simulator& simulator) : simulator_(simulator) {}
  ~ToolSprings();
  ToolSprings(const ToolSprings&) = delete;
  ToolSprings& operator=(const ToolSprings&) = delete;

  Simulator& simulator() const { return simulator_; }
  /// Adds a held spring (stiffness > 0, N/m) from `point` to `target`.
  PenaltySpringForm& add(const MaterialPoint& point, const Eigen::Vector3d& target,
                         double stiffness);
  /// The held springs, in the order added (owned by the simulator).
  const std::vector<PenaltySpringForm*>& held() const { return held_; }
  /// Lets go of (or keeps) every held spring.
  void release(ReleaseMode mode);
  /// Removes the springs kept by release(Keep).
  void clearKept();
  size_t numKept() const { return kept_.size(); }

 private:
  Simulator& simulator_;
  std::vector<PenaltySpringForm*> held_;
  std::vector<const Form*> kept_;
};

}  // namespace sculpt
