#pragma once
// The strokes made while a take records, kept as session-script events (tools/session_script.h)
// with times relative to the take's start, so that a take made with the mouse can be replayed
// and re-recorded from the command line (sculpt-cli record SCENE --script S.json).

#include <optional>

#include <Eigen/Core>

#include "tools/session_script.h"

namespace sculpt {

class StrokeCapture {
 public:
  /// Drops what was captured (a new take).
  void clear();
  /// A grab of the material point at rest position `rest`, its target at `world`, at take time t.
  void beginGrab(double t, const Eigen::Vector3d& rest, const Eigen::Vector3d& world, bool keep);
  /// The grab's target moved (ignored without a grab in progress or when t goes back).
  void moveGrab(double t, const Eigen::Vector3d& world);
  /// The grab ends (released) at take time t.
  void endGrab(double t);

  /// The events so far (a grab in progress is held, without a release).
  const SessionScript& script() const { return script_; }

 private:
  SessionScript script_;
  std::optional<size_t> grab_;  // the event in progress
};

}  // namespace sculpt
