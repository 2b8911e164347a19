#pragma once
// One tick of the haptic servo as a pure function of its inputs: the device's sample, the newest
// probe of the scene and the session's command (which stroke the stylus drives, with which tool,
// mapping and scale) give the force to send to the device. No clock, no thread, no device: the
// servo thread (servo_thread.h) calls it at 1 kHz, tests call it on a manual clock.
//
// Per tool:
//  - pull and probe (contact): the coupling of the stroke's spring (coupling.h);
//  - inflate: a small spring back to where the button was pressed (the command's anchor), so the
//    hand feels it is holding a pump, not pushing the solid;
//  - none: zero.
// Every force then goes through ForceSafety (force_safety.h). A new stroke, a device that comes
// back and a re-arm ramp the force in.

#include <cstdint>

#include <Eigen/Core>

#include "haptics/device/haptic_device.h"
#include "haptics/servo/coupling.h"
#include "haptics/servo/force_safety.h"
#include "haptics/servo/haptic_tool.h"
#include "haptics/servo/workspace_mapping.h"
#include "scene/scene_probe.h"

namespace sculpt::haptics {

/// What the session tells the servo (published to it wait-free).
struct ServoCommand {
  uint64_t strokeId = 0;  ///< the stroke the stylus drives (0: none yet)
  HapticTool tool = HapticTool::None;
  WorkspaceMapping mapping;
  double forceScale = 1.0;  ///< S, scene N per device N
  double damping = 0.0;     ///< device N s/m while a coupling acts
  /// Inflate: the resistance spring (device N/m) and its anchor (device m), and its cap (N).
  double inflateStiffness = 0.0;
  Eigen::Vector3d inflateAnchor = Eigen::Vector3d::Zero();
  double inflateMaxForce = 0.0;
  uint64_t rearmCount = 0;  ///< re-arms the safety each time it grows
  bool focused = true;      ///< false: the window lost focus (zero force)
  bool panic = false;       ///< the panic key (zero force until re-armed)
};

struct ServoTickInput {
  double dt = 0.001;  ///< measured since the previous tick (s)
  DeviceSample device;
  const SceneProbe* probe = nullptr;
  double probeAge = 0.0;  ///< s since that probe was published
  ServoCommand command;
  bool shuttingDown = false;
};

struct ServoTickResult {
  Eigen::Vector3d toolScene = Eigen::Vector3d::Zero();  ///< the stylus in the scene (m)
  Eigen::Vector3d desired = Eigen::Vector3d::Zero();    ///< device N, before safety
  Eigen::Vector3d commanded = Eigen::Vector3d::Zero();  ///< device N, sent
  Eigen::Vector3d onSolid = Eigen::Vector3d::Zero();    ///< scene N, the coupling on the solid
  bool acting = false;  ///< a coupling acted this tick
  bool clamped = false; ///< the safety changed the force this tick (limit, slew, fade, trip)
};

class ServoController {
 public:
  ServoController(const DeviceInfo& device, const SafetySettings& safety);
  ServoTickResult tick(const ServoTickInput& in);
  const ForceSafety& safety() const { return safety_; }
  const DeviceInfo& device() const { return device_; }

 private:
  DeviceInfo device_;
  ForceSafety safety_;
  uint64_t stroke_ = 0, rearms_ = 0;
  bool wasConnected_ = false, panicLatched_ = false;
};

/// The probe's entry for `strokeId` (null when the stroke has no spring there yet).
const ProbeStroke* findStroke(const SceneProbe& probe, uint64_t strokeId);

}  // namespace sculpt::haptics
