#include "haptics/servo/coupling.h"

#include <algorithm>

namespace sculpt::haptics {

CouplingForces couplingForces(const CouplingInput& in, const WorkspaceMapping& mapping) {
  CouplingForces out;
  const ProbeStroke* stroke = in.stroke;
  if (!stroke || !(stroke->stiffness > 0) || !(in.forceScale > 0)) return out;
  const double age = std::clamp(in.probeAge, 0.0, in.maxExtrapolation);
  const Eigen::Vector3d point = stroke->point + age * stroke->velocity;
  const Eigen::Vector3d stretch = in.toolScene - point;
  const bool contact = stroke->normal.squaredNorm() > 0;
  if (contact && stretch.dot(stroke->normal) >= 0) return out;
  out.acting = true;
  out.onSolid = stroke->stiffness * stretch;
  const Eigen::Vector3d pointVelocity =
      mapping.directionToDevice(stroke->velocity) / mapping.scale;  // device m/s
  out.onHand = -mapping.directionToDevice(out.onSolid) / in.forceScale +
               in.damping * (pointVelocity - in.toolVelocity);
  return out;
}

}  // namespace sculpt::haptics
