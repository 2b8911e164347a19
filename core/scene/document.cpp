#include "scene/document.h"

#include <stdexcept>

#include "project/project_file.h"

namespace sculpt {

std::string documentName(const std::filesystem::path& path) {
  return path.empty() ? std::string("untitled") : path.filename().string();
}

Document::Document(std::filesystem::path recoveryDirectory, double autosaveIntervalS,
                   Autosave::Clock clock)
    : recoveryDirectory_(std::move(recoveryDirectory)),
      autosaveIntervalS_(autosaveIntervalS),
      clock_(std::move(clock)),
      autosave_(untitledRecovery(), autosaveIntervalS_, clock_) {}

std::filesystem::path Document::untitledRecovery() const {
  return recoveryDirectory_ / "untitled.sculpt.recovery";
}

std::string Document::title() const { return documentName(path_) + (dirty() ? " *" : ""); }

void Document::start(Project project, std::filesystem::path path, bool dirty) {
  project_ = std::move(project);
  path_ = std::move(path);
  history_.clear();
  ids_ = {nextId_++};
  position_ = 0;
  savedId_ = dirty ? nextId_++ : ids_.front();
  // A new autosave (and interval) for the new file; the previous document's recovery file is
  // left alone, so that work it holds is still offered.
  autosave_ = Autosave(path_.empty() ? untitledRecovery() : recoveryPathFor(path_),
                       autosaveIntervalS_, clock_);
}

bool Document::commit(std::string label, Project after) {
  if (!history_.record(std::move(label), project_, after)) return false;
  // Camera, tool and simulation settings are not edits: keep the document's own.
  after.camera = project_.camera;
  after.tools = project_.tools;
  after.simulation = project_.simulation;
  project_ = std::move(after);
  ids_.resize(position_ + 1);  // the redo tail is gone
  ids_.push_back(nextId_++);
  position_ = ids_.size() - 1;
  // The history may have dropped its oldest entries (step and memory bounds).
  while (ids_.size() > history_.undoCount() + history_.redoCount() + 1) {
    ids_.pop_front();
    --position_;
  }
  return true;
}

std::optional<Document::Change> Document::step(bool forward) {
  const Project before = project_;
  if (!(forward ? history_.redo(project_) : history_.undo(project_))) return std::nullopt;
  forward ? ++position_ : --position_;
  Change change;
  change.controlMesh = !sameControlMesh(before.controlMesh, project_.controlMesh);
  change.materialsOrPins = !sameMaterialSamples(before.materials, project_.materials) ||
                           before.pins != project_.pins;
  return change;
}

std::optional<Document::Change> Document::undo() { return step(false); }
std::optional<Document::Change> Document::redo() { return step(true); }

void Document::save() {
  if (path_.empty()) throw std::invalid_argument("the project has no file yet: use Save As");
  saveProject(project_, path_);
  savedId_ = ids_[position_];
  autosave_.savedCleanly();
}

void Document::saveAs(const std::filesystem::path& path) {
  saveProject(project_, path);
  const bool moved = path != path_;
  path_ = path;
  savedId_ = ids_[position_];
  if (moved) autosave_.setRecoveryPath(recoveryPathFor(path_));
  autosave_.savedCleanly();
}

std::string Document::tick() {
  try {
    autosave_.tick(project_, dirty());
  } catch (const std::exception& error) {
    return std::string("autosave failed: ") + error.what();
  }
  return {};
}

}  // namespace sculpt
