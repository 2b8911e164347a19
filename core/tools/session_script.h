#pragma once
// Session scripts (docs/file-formats.md "Session script"): a JSON list of timed tool
// events (grab and drag along a path, inflate for a while, paint a sphere, pin a box) that
// ScriptPlayer replays on a Simulator as simulated time passes. Replay is deterministic: the
// same script on the same model and settings gives the same control points bit for bit.
//
// Times are seconds of script time; time 0 is when the player is created. An event starts
// before the first step whose start time t satisfies t_event <= t + h/2 (h the step), i.e. at
// the step nearest to its time; events due at the same step start in file order after ordering
// by time. A grab's path target is evaluated at the end of each step (where the implicit step
// evaluates its forces); a grab or inflate ends before the first step with t_end <= t + h/2.

#include <Eigen/Geometry>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "edit/topology_operation.h"
#include "sim/simulator.h"
#include "tools/curve_tool.h"
#include "tools/inflate_tool.h"
#include "tools/material_brush.h"
#include "tools/pull_tool.h"
#include "tools/strokes.h"
#include "tools/tool.h"

namespace sculpt {

/// A key of a drag path: a world target (grab) or a translation (curve) at a time.
struct PathKey {
  double time = 0;                                   ///< s after the event's start, >= 0
  Eigen::Vector3d target = Eigen::Vector3d::Zero();  ///< m: grab target, curve offset
};
/// The path at `time` s after the start: linear between keys, held outside them; `empty` when
/// there are no keys.
Eigen::Vector3d pathAt(const std::vector<PathKey>& path, double time, const Eigen::Vector3d& empty);

/// Grab the material point at rest position `point` with a spring and drag it along `path`.
struct GrabEvent {
  using Key = PathKey;
  Eigen::Vector3d point = Eigen::Vector3d::Zero();  ///< rest position (nearest solid point)
  std::vector<Key> path;                            ///< non-empty, times non-decreasing
  double stiffness = 0;                             ///< N/m; 0: defaultPullStiffness
  std::optional<double> release;                    ///< s after the start; none: held
  bool keep = false;                                ///< release with ReleaseMode::Keep
  bool push = false;                                ///< reflect the path through the anchor
  /// Target at `time` s after the start: linear between keys, held outside them.
  Eigen::Vector3d targetAt(double time) const;
};

/// Pressure on the boundary faces in a rest sphere for `duration` seconds.
struct InflateEvent {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  double radius = std::numeric_limits<double>::infinity();  ///< m; infinity: whole boundary
  double pressure = 0;                                       ///< Pa; negative deflates
  double duration = 0;                                       ///< s
};

/// One material-brush dab; mirror centre none: the centre of the rest control-point box.
struct PaintEvent {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  MaterialBrushSettings brush;
  std::optional<Eigen::Vector3d> mirrorCentre;
};

/// Pin (or unpin) the control points in a rest box or sphere.
struct PinEvent {
  std::optional<Eigen::AlignedBox3d> box;  ///< else the sphere
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  double radius = 0;
  bool unpin = false;
};

/// Grab the curve through rest positions `points` (CurveTool) and drag it by the offsets of
/// `path`.
struct CurveEvent {
  std::vector<Eigen::Vector3d> points;  ///< rest polyline, non-empty
  std::vector<PathKey> path;            ///< offsets (m), non-empty, times non-decreasing
  CurveProfile profile = CurveProfile::Rigid;
  double stiffness = 0;           ///< N/m for the whole curve; 0: defaultPullStiffness
  size_t samples = 0;             ///< 0: defaultCurveSamples
  std::optional<double> release;  ///< s after the start; none: held
  bool keep = false;              ///< release with ReleaseMode::Keep
  Eigen::Vector3d offsetAt(double time) const {
    return pathAt(path, time, Eigen::Vector3d::Zero());
  }
};

/// Edit the control mesh's topology (core/edit/topology_operation.h). Only at t = 0: a script's
/// topology events are applied to the control mesh, in file order, before the model is built
/// (tools/script_topology.h); ScriptPlayer rejects them.
using TopologyEvent = TopologyOperation;

struct ScriptEvent {
  size_t index = 0;  ///< position in the file's "events" array
  double time = 0;   ///< s
  using Action =
      std::variant<GrabEvent, InflateEvent, PaintEvent, PinEvent, CurveEvent, TopologyEvent>;
  Action action;
  const char* typeName() const;  ///< "grab", "inflate", "paint", "pin", "curve", "topology"
  /// When it stops acting: the start for paint and pin, start + release (or the last path key)
  /// for grab and curve, start + duration for inflate.
  double endTime() const;
};

struct SessionScript {
  std::vector<ScriptEvent> events;  ///< in file order
  /// The latest endTime() (0 without events).
  double duration() const;
  /// The event with the latest endTime() (the first of them), nullptr without events.
  const ScriptEvent* lastEvent() const;
};

/// Parses the JSON text. Throws FileError (io/control_mesh_json.h) with one sentence prefixed by
/// `sourceName`, naming the event index and field, e.g.
/// "s.json: events[2] (inflate): 'duration' must be a finite number >= 0 (got -1)."
SessionScript parseSessionScript(std::string_view text, std::string_view sourceName);
/// Reads and parses a file. Throws FileError.
SessionScript loadSessionScript(const std::filesystem::path& path);

class ScriptPlayer {
 public:
  /// Locates every grab point and curve sample in the model. The simulator must outlive the
  /// player; the player's loads are removed when it is destroyed (kept springs included). Throws
  /// std::invalid_argument when a grab point or curve cannot be located (a model without
  /// elements) or a curve has too many samples, and for a topology event (those edit the mesh
  /// the model is built from: apply them first, see tools/script_topology.h). Events are named
  /// by their index in the file (ScriptEvent::index).
  /// Every event is a stroke of its tool (tools/strokes.h) through `context` (none: a context
  /// over the bare simulator; the running scene passes its own).
  ScriptPlayer(Simulator& simulator, SessionScript script, ToolContext* context = nullptr);
  ~ScriptPlayer();
  ScriptPlayer(const ScriptPlayer&) = delete;
  ScriptPlayer& operator=(const ScriptPlayer&) = delete;

  /// Ends and starts the events due, sets the drag targets, and advances the simulator by one
  /// step. Throws std::invalid_argument when an event cannot be applied (a paint whose brush
  /// is rejected), naming the event.
  StepReport step();

  double time() const { return time_; }  ///< script time (s)
  const SessionScript& script() const { return script_; }
  /// The material point grabbed by events[index] (nullopt for other events).
  std::optional<MaterialPoint> grabPoint(size_t index) const;
  /// The pull tool of events[index] (nullptr for other events).
  const PullTool* pullTool(size_t index) const;
  /// The curve tool of events[index] (nullptr for other events or before it starts).
  const CurveTool* curveTool(size_t index) const;
  /// Appends the springs of the strokes acting now.
  void springs(std::vector<ToolSpring>& out) const;
  /// Lines about events started and ended since the last call ("t=0.5 s: events[1] inflate
  /// started ..."), for a command-line log.
  std::vector<std::string> takeLog();

 private:
  enum class Phase { Pending, Active, Done };
  struct Runner {
    Phase phase = Phase::Pending;
    std::optional<MaterialPoint> point;
    std::unique_ptr<PullTool> pull;
    std::vector<CurveSample> curve;
    std::unique_ptr<Tool> tool;  // the event's stroke; kept after it ends while it holds loads
  };
  void start(size_t i);
  void finish(size_t i);

  Simulator& simulator_;
  std::unique_ptr<SimulatorToolContext> ownContext_;
  ToolContext* context_ = nullptr;
  SessionScript script_;
  std::vector<size_t> order_;  // event indices by (time, index)
  std::vector<Runner> runners_;
  long long steps_ = 0;
  double time_ = 0;
  std::vector<std::string> log_;
};

}  // namespace sculpt
