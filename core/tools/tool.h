#pragma once
// One interface for every tool that acts on a running simulation. A tool is begun, updated and
// ended with a world-space ToolInput, whatever drives it: the window turns mouse rays into
// inputs, a session script turns its events into the same calls (tools/session_script.h), and a
// haptic device turns stylus samples into them. The calls run on the simulation thread between
// two steps (scene/simulation_loop.h), through a ToolContext that gives the tool the simulator
// and a way to find the material under a world position.
//
// A tool object carries its settings (brush radius, strength, pressure, ...) from the moment it
// is made; it creates its loads in begin() and removes them in end(), or keeps them (a pull
// released with "keep") until clear(). Tools are made on any thread and then handed over whole:
// only the simulation thread touches them after that.
//
// Adding a tool: a class here (or anywhere, a test included) that implements Tool; the window's
// panel makes it; a script event makes it. Nothing else changes.

#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "sim/material_point.h"
#include "sim/simulator.h"

namespace sculpt {

/// Modifier flags of a ToolInput.
enum ToolModifier : uint32_t {
  kToolInvert = 1u << 0,  ///< push instead of pull, deflate, unpin (Ctrl in the window)
  kToolShift = 1u << 1,
  kToolAlt = 1u << 2,
};

/// One sample of whatever drives a tool, in world coordinates (metres, deformed space).
struct ToolInput {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  std::optional<Eigen::Quaterniond> orientation;  ///< a 6-DOF device's; none for a mouse
  double pressure = 1.0;                          ///< in [0, 1]
  uint32_t buttons = 1;                           ///< bit i: button i held
  uint32_t modifiers = 0;                         ///< ToolModifier flags
  /// The rest position of the material point under the input, when the caller already knows it
  /// (the window's picking does); otherwise the context finds it from `position`.
  std::optional<Eigen::Vector3d> restPoint;

  bool inverted() const { return (modifiers & kToolInvert) != 0; }
};

/// A spring a tool holds now, as drawn in the view and published in the probe.
struct ToolSpring {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();     ///< the material point's position (m)
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();  ///< its velocity (m/s)
  Eigen::Vector3d target = Eigen::Vector3d::Zero();    ///< where the spring pulls it (m)
  double stiffness = 0.0;                              ///< N/m
  /// k |x - target| (N); NaN where the tool does not label it (the curve's many springs).
  double force = std::numeric_limits<double>::quiet_NaN();
  /// Zero for a spring that pulls both ways. Non-zero for a contact, the outward unit normal of
  /// the surface at `point`: the spring acts only while the target is inside, (target - point)
  /// . normal < 0 (a stylus pressing on the surface).
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
};

/// Which part of the user's work a tool edits: such a stroke becomes one undo entry.
enum class ToolEdit { None, Materials, Pins };

/// What a tool may use of the running scene.
class ToolContext {
 public:
  virtual ~ToolContext() = default;
  virtual Simulator& simulator() = 0;
  FemModel& model() { return simulator().model(); }
  /// A locator over the model's elements, kept for the scene (building one is O(elements)).
  virtual const MaterialPointLocator& locator() = 0;
  /// The rest position of the material at world position `world` in the current state; nullopt
  /// when no material is there.
  virtual std::optional<Eigen::Vector3d> restPointAt(const Eigen::Vector3d& world) = 0;
  /// The painted materials changed (the drawn fields follow).
  virtual void materialsChanged() {}
  /// A point on every mirror plane: the centre of the rest control points' box.
  Eigen::Vector3d symmetryCentre();
};

class Tool {
 public:
  virtual ~Tool() = default;
  /// For messages: "pull", "inflate", ...
  virtual const char* name() const = 0;
  /// Starts a stroke. Throws std::invalid_argument with a sentence when it cannot start (no
  /// material under the input, bad settings); nothing is changed then.
  virtual void begin(ToolContext& context, const ToolInput& input) = 0;
  /// The input moved (or its pressure changed).
  virtual void update(ToolContext& context, const ToolInput& input) { (void)context, (void)input; }
  /// The stroke ends; loads go, unless the tool keeps them (see holdsLoads).
  virtual void end(ToolContext& context, const ToolInput& input) { (void)context, (void)input; }
  /// Removes whatever the tool still holds (the scene is reset).
  virtual void clear() {}
  /// True while the tool has loads on the simulator (during a stroke, or kept after it).
  virtual bool holdsLoads() const { return false; }
  /// Appends the springs it holds now.
  virtual void springs(const Simulator& simulator, std::vector<ToolSpring>& out) const {
    (void)simulator, (void)out;
  }
  virtual ToolEdit edits() const { return ToolEdit::None; }
};

/// The rest position of the material under `input`: its restPoint, or the context's lookup.
/// Throws std::invalid_argument naming `tool` when there is none.
Eigen::Vector3d restPointOf(ToolContext& context, const ToolInput& input, const char* tool);

/// A ToolContext over a bare simulator (scripts, the command line, tests): restPointAt finds the
/// element whose current shape holds the point (nearest element otherwise).
class SimulatorToolContext : public ToolContext {
 public:
  explicit SimulatorToolContext(Simulator& simulator) : simulator_(simulator) {}
  Simulator& simulator() override { return simulator_; }
  const MaterialPointLocator& locator() override;
  std::optional<Eigen::Vector3d> restPointAt(const Eigen::Vector3d& world) override;

 private:
  Simulator& simulator_;
  std::optional<MaterialPointLocator> locator_;
};

}  // namespace sculpt
