#pragma once
// The force the solid puts on the stylus, rendered at servo rate from the last probe (a local
// model between simulation updates, so the force does not buzz at the simulation's rate).
//
// The simulation holds a spring of stiffness k from the grabbed material point p to the tool's
// scene position x (the target it was last sent): it applies +F = k (x - p) to the solid. The
// hand gets the opposite, -F, converted to the device (rotated into its frame and divided by the
// force scale S). Between probes the model extrapolates p with the point's velocity over the
// probe's age (at most `maxExtrapolation`) and uses the tool's position now, so the felt spring
// follows the hand at 1 kHz and the material's motion at the simulation's rate.
//
// A contact (a probe spring with a normal n) only pushes: -F acts while the tool is inside,
// (x - p) . n < 0, and is zero once the hand withdraws, even before the simulation notices.
//
// Damping: b (v_point - v_tool) on the hand, in device units, while the coupling acts (the
// passivity margin of a sampled spring, b > k T / 2; docs/design/haptics.md "Passivity").

#include <Eigen/Core>

#include "scene/scene_probe.h"
#include "haptics/servo/workspace_mapping.h"

namespace sculpt::haptics {

struct CouplingForces {
  bool acting = false;
  /// +F, the force on the solid from the coupling at the tool's position now (scene N).
  Eigen::Vector3d onSolid = Eigen::Vector3d::Zero();
  /// -F / S in the device frame plus the damping term: what the hand should feel (device N),
  /// before any safety limit.
  Eigen::Vector3d onHand = Eigen::Vector3d::Zero();
};

struct CouplingInput {
  const ProbeStroke* stroke = nullptr;  ///< the tool's stroke in the probe; null: nothing acts
  double probeAge = 0.0;                ///< s since the probe was published
  Eigen::Vector3d toolScene = Eigen::Vector3d::Zero();     ///< the tool's position (scene m)
  Eigen::Vector3d toolVelocity = Eigen::Vector3d::Zero();  ///< device m/s, device frame
  double forceScale = 1.0;          ///< S, scene N per device N
  double damping = 0.0;             ///< b, device N s/m
  double maxExtrapolation = 0.02;   ///< s
};

CouplingForces couplingForces(const CouplingInput& in, const WorkspaceMapping& mapping);

}  // namespace sculpt::haptics
