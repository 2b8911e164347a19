#include "haptics/servo/servo_controller.h"

#include <algorithm>

namespace sculpt::haptics {

const ProbeStroke* findStroke(const SceneProbe& probe, uint64_t strokeId) {
  if (strokeId == 0) return nullptr;
  const int count = std::min(probe.strokeCount, kProbeStrokes);
  for (int i = 0; i < count; ++i)
    if (probe.strokes[i].strokeId == strokeId) return &probe.strokes[i];
  return nullptr;
}

ServoController::ServoController(const DeviceInfo& device, const SafetySettings& safety)
    : device_(device), safety_(safety) {}

ServoTickResult ServoController::tick(const ServoTickInput& in) {
  const ServoCommand& command = in.command;
  ServoTickResult out;
  out.toolScene = command.mapping.toScene(in.device.position);

  if (command.rearmCount != rearms_) {
    rearms_ = command.rearmCount;
    panicLatched_ = false;
    safety_.rearm();
  }
  if (command.panic) panicLatched_ = true;
  if (command.strokeId != stroke_) {
    stroke_ = command.strokeId;
    if (stroke_ != 0) safety_.rampIn();
  }
  if (in.device.connected && !wasConnected_) safety_.rampIn();
  wasConnected_ = in.device.connected;

  bool fresh = true;  // the force depends on the probe only for couplings
  switch (command.tool) {
    case HapticTool::Pull:
    case HapticTool::Probe: {
      CouplingInput coupling;
      coupling.stroke = in.probe ? findStroke(*in.probe, command.strokeId) : nullptr;
      coupling.probeAge = in.probeAge;
      coupling.toolScene = out.toolScene;
      coupling.toolVelocity = in.device.velocity;
      coupling.forceScale = command.forceScale;
      coupling.damping = command.damping;
      const CouplingForces forces = couplingForces(coupling, command.mapping);
      out.acting = forces.acting;
      out.onSolid = forces.onSolid;
      out.desired = forces.onHand;
      fresh = coupling.stroke != nullptr;
      break;
    }
    case HapticTool::Inflate: {
      Eigen::Vector3d f = -command.inflateStiffness * (in.device.position - command.inflateAnchor);
      if (command.inflateMaxForce >= 0 && f.norm() > command.inflateMaxForce)
        f *= command.inflateMaxForce / f.norm();
      out.desired = f;
      break;
    }
    case HapticTool::None:
      break;
  }

  SafetyInput safety;
  safety.desired = out.desired;
  safety.dt = in.dt;
  // Without a coupling there is nothing to be stale: the probe's age only fades a coupling.
  safety.probeAge = fresh ? in.probeAge : 0.0;
  safety.connected = in.device.connected;
  safety.focused = command.focused;
  safety.panic = panicLatched_;
  safety.deviceError = false;
  safety.shuttingDown = in.shuttingDown;
  out.commanded = safety_.filter(safety);
  out.clamped = (out.commanded - out.desired).norm() > 1e-12;
  return out;
}

}  // namespace sculpt::haptics
