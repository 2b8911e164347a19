#pragma once
// The strokes made while a take records, kept as session-script events (tools/session_script.h)
// with times relative to the take's start, so that a take made with the mouse can be replayed
// and re-recorded from the command line (sculpt-cli record SCENE --script S.json).
//
// Each stroke becomes the events its tool acts as (tools/strokes.h):
// - pull: one grab whose path is the target's travel;
// - curve (the drag of a drawn curve): one curve event whose path is the drag's offset;
// - inflate: one inflate event per press, lasting until the brush re-presses elsewhere (it moved a
//   quarter of its radius, as InflateStroke does) or the stroke ends;
// - paint: one paint event per dab, spaced as PaintStroke spaces them;
// - pin: one pin (or unpin) sphere each time the brush moves.
// One stroke is captured at a time; beginning another ends the one in progress.

#include <optional>
#include <vector>

#include <Eigen/Core>

#include "tools/session_script.h"

namespace sculpt {

class StrokeCapture {
 public:
  /// Drops what was captured (a new take).
  void clear();

  /// A grab of the material point at rest position `rest`, its target at `world`, at take time t.
  void beginGrab(double t, const Eigen::Vector3d& rest, const Eigen::Vector3d& world, bool keep);
  /// A drag of the curve through the rest polyline `points`, starting with the input at `world`.
  void beginCurve(double t, std::vector<Eigen::Vector3d> points, CurveProfile profile,
                  const Eigen::Vector3d& world);
  /// Inflate (pressure < 0: deflate) around rest point `rest`, as `settings` inflates.
  void beginInflate(double t, const Eigen::Vector3d& rest, const InflateStroke::Settings& settings,
                    double pressure);
  /// A paint stroke of `settings` starting at rest point `rest` (its first dab).
  void beginPaint(double t, const Eigen::Vector3d& rest, const PaintStroke::Settings& settings);
  /// Pin (or unpin) the control points within `radius` of rest point `rest`.
  void beginPin(double t, const Eigen::Vector3d& rest, double radius, bool unpin);

  /// The stroke's input moved: to `world` for a grab or a curve, over rest point `rest` for a
  /// brush (ignored without a stroke, when t goes back, or when a brush has no rest point).
  void move(double t, const Eigen::Vector3d& world, const std::optional<Eigen::Vector3d>& rest);
  /// The stroke ends (released) at take time t.
  void end(double t);
  /// Whether a stroke is in progress.
  bool active() const { return stroke_.has_value(); }

  /// The events so far (a grab or curve in progress is held, without a release).
  const SessionScript& script() const { return script_; }

 private:
  enum class Kind { Grab, Curve, Inflate, Paint, Pin };
  static constexpr size_t kNoEvent = static_cast<size_t>(-1);
  struct Stroke {
    Kind kind = Kind::Grab;
    size_t event = kNoEvent;  // the stroke's latest event
    double time = 0;   // of its last input
    Eigen::Vector3d origin = Eigen::Vector3d::Zero();  // curve: the input at begin
    Eigen::Vector3d last = Eigen::Vector3d::Zero();    // brushes: where it last acted
    double spacing = 0, radius = 0;  // brushes: they act again after spacing x radius (rest m)
    ScriptEvent::Action repeated;    // brushes: the event each action repeats at a new centre
  };
  void startStroke(Kind kind, size_t event, double t);
  void add(double t, ScriptEvent::Action action);
  void beginBrush(double t, Kind kind, const Eigen::Vector3d& rest, double spacing, double radius,
                  ScriptEvent::Action action);
  void actAt(double t, const Eigen::Vector3d& rest);

  SessionScript script_;
  std::optional<Stroke> stroke_;  // the stroke in progress
};

}  // namespace sculpt
