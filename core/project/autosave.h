#pragma once
// Autosave and crash recovery. While the project has unsaved changes, Autosave writes it every
// N minutes to a recovery file beside it ("<name>.sculpt.recovery"); a clean save or close
// removes that file. After a crash the window calls findRecovery() on the project it opens and
// offers the newer recovery file.

#include <filesystem>
#include <functional>
#include <optional>

#include "project/project.h"

namespace sculpt {

/// "dir/name.sculpt" -> "dir/name.sculpt.recovery".
std::filesystem::path recoveryPathFor(const std::filesystem::path& projectPath);

/// The recovery file of `projectPath` when it exists and is not older than the project (or the
/// project file does not exist any more): what a crash left behind. nullopt otherwise. Called at
/// start, it also removes the temporary files of both that a kill mid-save left behind
/// (removeStaleTemporaries), so that they do not pile up beside the project.
std::optional<std::filesystem::path> findRecovery(const std::filesystem::path& projectPath);

class Autosave {
 public:
  /// Seconds on any monotonic clock; tests pass a fake one so that nothing sleeps.
  using Clock = std::function<double()>;

  /// Writes to `recoveryPath` (see recoveryPathFor; an untitled project may use a file in a
  /// recovery directory) every `intervalS` seconds of `clock` while changes are unsaved.
  Autosave(std::filesystem::path recoveryPath, double intervalS, Clock clock);

  /// Call often (e.g. once a frame). Writes the recovery file when `dirty` and at least the
  /// interval has passed since the last save or autosave; returns true when it wrote. A failed
  /// write throws FileError (the window shows it and keeps working) and is retried next interval.
  bool tick(const Project& project, bool dirty);
  /// The project was saved to its own file (or closed without saving, on purpose): removes the
  /// recovery file and restarts the interval.
  void savedCleanly();
  /// Save As: later autosaves go to `recoveryPath`; the old recovery file is removed.
  void setRecoveryPath(std::filesystem::path recoveryPath);

  const std::filesystem::path& recoveryPath() const { return recoveryPath_; }
  double intervalS() const { return intervalS_; }

 private:
  std::filesystem::path recoveryPath_;
  double intervalS_;
  Clock clock_;
  double lastWriteS_;
};

}  // namespace sculpt
