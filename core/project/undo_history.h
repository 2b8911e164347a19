#pragma once
// Undo and redo of edits to a Project: one entry per stroke or operation, stored as deltas.
// record() compares the project before and after the edit and keeps only what changed, in the
// most compact form for each part:
//   - moved control points: the changed rows, before and after;
//   - crease/corner tags: both tag lists (small);
//   - topology edits (cells or vertex count changed): the whole control mesh before and after;
//   - painted materials: the changed samples (index, before, after) when the samples stay the
//     same set of points, else the whole sample set before and after (it was resampled);
//   - pins: the pins added and the pins removed;
//   - the embedded surface: before and after.
// Camera, tool settings and simulation settings are not edits and are never touched
// (docs/design/ux.md: "tool settings are not undo entries"; simulation playback is separate from
// edit history). The history is bounded by a step count and by bytes; the oldest entries go first.

#include <cstddef>
#include <deque>
#include <memory>
#include <string>

#include "project/project.h"

namespace sculpt {

class UndoHistory {
 public:
  struct Limits {
    size_t maxSteps = 100;
    size_t maxBytes = size_t{256} << 20;  ///< 256 MiB (estimated from the stored arrays)
  };

  explicit UndoHistory(Limits limits);
  UndoHistory();
  ~UndoHistory();
  UndoHistory(UndoHistory&&) noexcept;
  UndoHistory& operator=(UndoHistory&&) noexcept;

  /// Records the edit that turned `before` into `after` (the project as it now is) under `label`
  /// ("Paint Young's modulus", "Extrude face", ...). Clears the redo tail, then drops the oldest
  /// entries beyond the limits (the newest is always kept, so the last edit can be undone even
  /// when it alone exceeds maxBytes). Returns false, recording nothing, when nothing undoable
  /// changed.
  bool record(std::string label, const Project& before, const Project& after);

  bool canUndo() const { return done_ > 0; }
  bool canRedo() const { return done_ < entries_.size(); }
  /// Labels for the Edit menu ("Undo Paint Young's modulus"); empty when there is none.
  std::string undoLabel() const;
  std::string redoLabel() const;

  /// Restores the state before the newest done entry. Returns false when there is nothing to
  /// undo. Throws std::logic_error, leaving `project` unchanged, when the project does not match
  /// what the entry recorded (it was edited without record()).
  bool undo(Project& project);
  /// Re-applies the oldest undone entry; same rules as undo().
  bool redo(Project& project);

  void clear();
  /// Entries that can be undone / redone, and the estimated bytes all entries hold.
  size_t undoCount() const { return done_; }
  size_t redoCount() const { return entries_.size() - done_; }
  size_t bytes() const { return bytes_; }
  const Limits& limits() const { return limits_; }

 private:
  struct Entry;
  void apply(const Entry& entry, Project& project, bool forward) const;
  Limits limits_;
  std::deque<std::unique_ptr<Entry>> entries_;
  size_t done_ = 0;
  size_t bytes_ = 0;
};

}  // namespace sculpt
