#pragma once
// A stylus on a running scene: the servo thread (1 kHz, servo/servo_thread.h) renders the force;
// this session's own thread (500 Hz) turns the servo's newest device state into strokes of the
// one tool interface on the SimulationLoop (begin / update / end, like the window's mouse) and
// tells the servo which stroke to render, through which mapping and scale. The simulation sees a
// stylus only through those strokes; the servo sees the simulation only through the probe.
//
// Buttons (DeviceSample::buttons): bit 0 is the tool button (pull: grab while held; probe:
// paint while held, when painting is on; inflate: press while held), bit 1 the clutch (the
// workspace mapping slides while it is held, so the hand can re-centre). A device that
// disconnects ends its stroke at once; the servo has already zeroed the force that tick.

#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include <Eigen/Geometry>

#include "haptics/device/haptic_device.h"
#include "haptics/servo/force_scale.h"
#include "haptics/servo/servo_thread.h"
#include "scene/simulation_loop.h"
#include "tools/contact_stroke.h"
#include "tools/strokes.h"

namespace sculpt {
struct SceneGeometry;
struct SceneSettings;
}  // namespace sculpt

namespace sculpt::haptics {

/// What the session needs of the scene: where it is, how big, how stiff.
struct HapticScene {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  double radius = 1.0;  ///< m, of the bounding sphere of the rest shape
  double youngs = 0.0;  ///< Pa, the scene's material
  /// The surface the probe touches (the scene's detail surface); none: the solid's boundary.
  std::shared_ptr<const Points> surfaceVertices;
  std::shared_ptr<const std::vector<uint32_t>> surfaceTriangles;
};
/// The scene's box, material and detail surface (which the result shares).
HapticScene hapticSceneOf(const std::shared_ptr<const SceneGeometry>& geometry,
                          const SceneSettings& settings);

struct HapticSessionSettings {
  HapticTool tool = HapticTool::Pull;
  /// Probe: paint with `paint` while the tool button is held.
  bool paintWithProbe = false;
  PaintStroke::Settings paint;
  InflateStroke::Settings inflate;
  double forceFactor = 1.0;  ///< multiplies the force scale (ForceScale)
  /// None: SafetySettings::forMaxForce of the device.
  std::optional<SafetySettings> safety;
  double servoRateHz = 1000.0;
  size_t recordTicks = 0;    ///< ticks the servo records (the command line's force log)
};

/// For the device panel (any thread).
struct HapticStatus {
  bool connected = false;
  HapticTool tool = HapticTool::None;
  uint32_t buttons = 0;
  bool clutching = false;
  bool stroking = false;
  bool acting = false;   ///< a coupling acts (grabbed, or in contact)
  bool tripped = false;  ///< force latched at zero: re-arm
  Eigen::Vector3d toolScene = Eigen::Vector3d::Zero();
  Eigen::Vector3d force = Eigen::Vector3d::Zero();  ///< device N, commanded
  double forceLimit = 0.0;                          ///< N
  double probeAge = 0.0;                            ///< s
  ForceScale scale;
  WorkspaceMapping mapping;  ///< device -> scene, as the session uses it now (clutch included)
  uint64_t servoTicks = 0;
};

class HapticSession {
 public:
  /// `loop` and `device` outlive the session.
  HapticSession(SimulationLoop& loop, HapticDevice& device, const HapticScene& scene,
                HapticSessionSettings settings);
  ~HapticSession();
  HapticSession(const HapticSession&) = delete;
  HapticSession& operator=(const HapticSession&) = delete;

  void start();
  /// Ends the stroke and stops both threads (the force goes to zero first). Idempotent.
  void stop();

  // Any thread (the window's); applied by the session's thread within one of its periods.
  void setTool(HapticTool tool, bool paintWithProbe);
  void setForceFactor(double factor);
  /// Device axes into the scene (the window's camera orientation).
  void setRotation(const Eigen::Quaterniond& rotation);
  void setFocused(bool focused);
  void panic();
  void rearm();

  HapticStatus status() const;
  /// The servo, for its records and statistics after stop().
  ServoThread& servo() { return servo_; }

 private:
  void run();
  std::unique_ptr<Tool> makeTool(HapticTool tool, bool paint) const;
  void publishStatus(const HandState& hand, bool clutching, bool stroking, HapticTool tool);

  SimulationLoop& loop_;
  HapticDevice& device_;
  HapticScene scene_;
  WorkspaceMapping mapping_;
  ForceScale scale_;
  ServoThread servo_;

  mutable std::mutex mutex_;  // guards the requests and the status below
  HapticSessionSettings settings_;
  double forceFactor_ = 1.0;
  double appliedForceFactor_ = 1.0;  // the session thread's
  Eigen::Quaterniond rotation_ = Eigen::Quaterniond::Identity();
  bool focused_ = true, panic_ = false;
  uint64_t rearms_ = 0;
  HapticStatus status_;

  std::atomic<bool> stop_{false};
  bool started_ = false;
  std::thread thread_;
};

}  // namespace sculpt::haptics
