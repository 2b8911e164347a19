#pragma once
// The user's work in the window: the Project (the master copy of what is saved), the file it
// belongs to, whether it has unsaved changes, its undo history and autosave. No GL, no threads:
// the window calls it from the UI thread and tests drive it directly.
//
// Edits go through commit(label, after): one undo entry per stroke or operation (docs/design/ux.md
// "Undo"). Dirty tracking: every state the undo history can reach has an id; the document is dirty
// when the id of the state shown is not the id of the state last saved (so undoing back to the
// saved state is clean again, as in Blender).

#include <cstdint>
#include <deque>
#include <filesystem>
#include <optional>
#include <string>

#include "project/autosave.h"
#include "project/project.h"
#include "project/undo_history.h"

namespace sculpt {

class Document {
 public:
  /// `recoveryDirectory`: where an untitled project autosaves ("untitled.sculpt.recovery").
  Document(std::filesystem::path recoveryDirectory, double autosaveIntervalS,
           Autosave::Clock clock);

  const Project& project() const { return project_; }
  const std::filesystem::path& path() const { return path_; }  ///< empty: untitled
  bool dirty() const { return ids_[position_] != savedId_; }
  /// "name.sculpt" or "untitled", with " *" when dirty: the window title.
  std::string title() const;

  /// A new document (a scene loaded from a file, or a project opened from `path`): no history,
  /// clean (or dirty: work recovered from an autosave is not saved yet). An untitled one
  /// autosaves in recoveryDirectory.
  void start(Project project, std::filesystem::path path = {}, bool dirty = false);
  /// Settings that are saved but are not edits (camera, tool and simulation settings).
  Project& settingsOnly() { return project_; }

  /// Makes `after` the project, recording the edit under `label`. False (nothing recorded, the
  /// project unchanged) when nothing undoable changed.
  bool commit(std::string label, Project after);

  struct Change {
    bool controlMesh = false;  ///< the topology or positions changed: the scene is rebuilt
    bool materialsOrPins = false;
  };
  std::optional<Change> undo();
  std::optional<Change> redo();
  bool canUndo() const { return history_.canUndo(); }
  bool canRedo() const { return history_.canRedo(); }
  std::string undoLabel() const { return history_.undoLabel(); }
  std::string redoLabel() const { return history_.redoLabel(); }

  /// Saves to path() (Save) or to `path` (Save As; the document then belongs to it). Atomic;
  /// throws FileError or std::invalid_argument with a sentence, leaving the state as it was.
  void save();
  void saveAs(const std::filesystem::path& path);
  /// Called every frame: autosaves when dirty and the interval passed. Returns a sentence when the
  /// autosave failed (the window shows it and retries at the next interval), else empty.
  std::string tick();
  /// The recovery file this document writes to.
  const std::filesystem::path& recoveryPath() const { return autosave_.recoveryPath(); }
  /// Closing on purpose (Don't save): removes the recovery file.
  void discardRecovery() { autosave_.savedCleanly(); }

 private:
  std::filesystem::path untitledRecovery() const;
  std::optional<Change> step(bool forward);

  std::filesystem::path recoveryDirectory_;
  double autosaveIntervalS_;
  Autosave::Clock clock_;
  Project project_;
  std::filesystem::path path_;
  UndoHistory history_;
  Autosave autosave_;
  std::deque<uint64_t> ids_{0};  // id of each reachable state, oldest first
  size_t position_ = 0;          // index of the state shown in ids_
  uint64_t nextId_ = 1, savedId_ = 0;
};

/// The display name of a project file ("untitled" for an empty path).
std::string documentName(const std::filesystem::path& path);

}  // namespace sculpt
