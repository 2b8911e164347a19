#pragma once
// Pull / push (docs/design/ux.md "Brushes", McDonnell-Qin section 4.1): a zero-length spring
// (PenaltySpringForm) from a grabbed material point to a target that the mouse or a stylus
// moves. Push is the same spring with the drag reflected through the grab position (Ctrl in the
// window): target = anchor - (cursor - anchor), anchor being where the point was when grabbed.
//
// Release either lets go (the spring is removed; the solid relaxes under its other loads) or
// keeps: the spring stays, its target moved to where the point is at release, with the grab's
// stiffness, so the solid holds its new shape around that point (tools/tool_springs.h). Kept
// springs stay until clearKept(). The tool keeps a reference to its simulator, which must
// outlive it.

#include <Eigen/Core>

#include "sim/material_point.h"
#include "sim/simulator.h"
#include "tools/tool.h"
#include "tools/tool_springs.h"

namespace sculpt {

class PullTool {
 public:
  explicit PullTool(Simulator& simulator) : springs_(simulator) {}
  PullTool(const PullTool&) = delete;
  PullTool& operator=(const PullTool&) = delete;

  /// Starts a drag at `point` (a previous one is let go). `cursor` is the first target;
  /// stiffness in N/m (<= 0: defaultPullStiffness). `push` reflects every cursor through the
  /// anchor. Throws std::invalid_argument for a non-finite cursor or stiffness.
  void grab(const MaterialPoint& point, const Eigen::Vector3d& cursor, double stiffness = 0.0,
            bool push = false);
  /// Moves the target (reflected when pushing). Nothing when not grabbing.
  void moveTarget(const Eigen::Vector3d& cursor);
  void release(ReleaseMode mode = ReleaseMode::LetGo);
  /// Removes the springs kept by release(Keep).
  void clearKept();

  bool active() const { return !springs_.held().empty(); }
  size_t numKept() const { return springs_.numKept(); }
  /// Current position of the grabbed point (the anchor when not grabbing).
  Eigen::Vector3d pointPosition() const;
  /// Velocity of the grabbed point (m/s); zero when not grabbing.
  Eigen::Vector3d pointVelocity() const;
  /// The spring's stiffness (N/m); 0 when not grabbing.
  double stiffness() const;
  /// The spring's target (m); the anchor when not grabbing.
  Eigen::Vector3d target() const;
  /// Position of the grabbed point at grab time.
  const Eigen::Vector3d& anchor() const { return anchor_; }
  /// k |x - target| (N) for the force line; 0 when not grabbing.
  double springForce() const;
  /// The held spring as the view and the probe show it (call only while active()).
  ToolSpring heldSpring() const;

 private:
  PenaltySpringForm* spring() const { return active() ? springs_.held().front() : nullptr; }

  ToolSprings springs_;
  Eigen::Vector3d anchor_ = Eigen::Vector3d::Zero();
  bool push_ = false;
};

}  // namespace sculpt
