// SculptApp: the user's work as a document (document.h): starting it from a scene, opening,
// saving, undo and redo, autosave and the recovery offer, the unsaved-changes prompt, and the
// recovery file written when SIGTERM, SIGINT or SIGHUP ends the window.

#include <algorithm>
#include <chrono>
#include <csignal>
#include <fstream>
#include <iostream>
#include <sstream>

#include "edit/project_edit.h"
#include "project/project_file.h"
#include "scene/scene_file.h"
#include "sculpt/display_state.h"
#include "sculpt/scene_start.h"
#include "sculpt/sculpt_app.h"
#include "sculpt/termination_signals.h"

namespace sculpt::app {

void SculptApp::startDocumentFromScene(const SceneGeometry& geometry) {
  Project project;
  if (geometry.controlMesh) project.controlMesh = *geometry.controlMesh;
  for (uint32_t v = 0; v < geometry.pinned.size(); ++v)
    if (geometry.pinned[v]) project.pins.push_back(v);
  project.surface.path = documentSource_.kind == SceneKind::DefaultBunny
                             ? std::string("bunny.obj")
                             : std::filesystem::absolute(documentSource_.path).string();
  if (documentSource_.kind == SceneKind::ImportedSurface)
    project.surface.contentHash = fileContentHash(documentSource_.path);
  project.tools[kSceneSourceKey] = sceneKindName(documentSource_.kind);
  document_.start(std::move(project));
  storeSettingsInProject();
}

void SculptApp::storeSettingsInProject() {
  Project& p = document_.settingsOnly();
  p.camera.pivot = Eigen::Vector3d(camera_.pivot().x, camera_.pivot().y, camera_.pivot().z);
  p.camera.yawRad = camera_.yaw();
  p.camera.pitchRad = camera_.pitch();
  p.camera.distance = camera_.distance();
  p.camera.orthographic = camera_.orthographic();
  const std::string source = std::get<std::string>(p.tools.count(kSceneSourceKey)
                                                       ? p.tools.at(kSceneSourceKey)
                                                       : ToolValue(std::string("bunny")));
  storeToolState(model_.tools, p.tools);
  storeDisplayState(model_.display, p.tools);
  p.tools[kSceneSourceKey] = source;
  storeSceneSettings(model_.settings, p);
}

void SculptApp::loadDocumentScene() {
  SceneSource source = documentSource_;
  source.project = std::make_shared<const Project>(document_.project());
  documentFromNextScene_ = false;
  controller_->load(source, model_.settings);
}

void SculptApp::openFile(const std::string& path) {
  if (!isProjectPath(path)) {
    loadScene(path);
    return;
  }
  try {
    openProject(path, path);
  } catch (const std::exception& error) {
    model_.toast(error.what(), true, 8.0);
  }
}

void SculptApp::openProject(const std::filesystem::path& path, const std::filesystem::path& from) {
  Project project = loadProject(from);  // FileError: one sentence naming the file
  ProjectScene scene = projectScene(project, from, path.filename().string(), model_.settings);
  for (const std::string& warning : scene.warnings) model_.toast(warning, true, 8.0);
  scene.source.project = nullptr;  // loadDocumentScene() gives the scene the document's project
  // Settings saved with the project
  model_.tools = loadToolState(project.tools);
  model_.display = loadDisplayState(project.tools);
  if (from == options_.scene)  // display switches given with the project win (--field, --clip)
    model_.display = withCommandLineDisplay(model_.display, options_.display);
  model_.settings = scene.settings;
  // The project named on the command line: --level, --cage and --dt over its own settings.
  if (from == options_.scene) applyCommandLineSettings(options_, model_.settings);
  const CameraState camera = project.camera;
  const bool recovered = from != path;
  document_.start(std::move(project), path, recovered);  // recovered work is unsaved work
  documentSource_ = scene.source;
  // A project written without a view (a script, another program) is framed when it shows up.
  cameraFramed_ = !(camera == CameraState{});
  if (cameraFramed_) {
    camera_.setPivot(glm::vec3(camera.pivot.x(), camera.pivot.y(), camera.pivot.z()));
    camera_.setOrientation(static_cast<float>(camera.yawRad), static_cast<float>(camera.pitchRad));
    camera_.setDistance(static_cast<float>(camera.distance));
    camera_.setOrthographic(camera.orthographic);
  }
  model_.sceneFile = path.string();
  if (!recovered && !path.empty()) {
    preferences_.addRecentFile(std::filesystem::absolute(path).string());
    model_.recentScenes = preferences_.recentFiles;
    if (!options_.headless)  // autosaved work newer than the file: a crash left it
      if (const auto recovery = findRecovery(path)) {
        recoveryFile_ = *recovery;
        model_.document.recoveryOffer = recovery->string();
      }
  }
  loadDocumentScene();
}

bool SculptApp::saveDocument(const std::string& saveAsPath) {
  if (saveAsPath.empty() && document_.path().empty()) {
    model_.openSaveAsDialog = true;
    return false;
  }
  storeSettingsInProject();
  try {
    if (saveAsPath.empty()) {
      document_.save();
    } else {
      std::filesystem::path path = saveAsPath;
      if (path.extension() != kProjectExtension) path += kProjectExtension;
      document_.saveAs(path);
      preferences_.addRecentFile(std::filesystem::absolute(path).string());
      model_.recentScenes = preferences_.recentFiles;
    }
  } catch (const std::exception& error) {
    model_.toast(std::string("not saved: ") + error.what(), true, 8.0);
    return false;
  }
  model_.toast("saved " + document_.path().string());
  return true;
}

void SculptApp::undoRedo(bool redo) {
  if (pendingCapture_ != Capture::None) return;  // a stroke is still being recorded
  const std::string label = redo ? document_.redoLabel() : document_.undoLabel();
  std::optional<Document::Change> change;
  try {
    change = redo ? document_.redo() : document_.undo();
  } catch (const std::exception& error) {  // the history does not match: say so, keep working
    model_.toast(std::string(redo ? "cannot redo: " : "cannot undo: ") + error.what(), true, 8.0);
    return;
  }
  if (!change) return;
  model_.toast((redo ? "Redo " : "Undo ") + label);
  if (change->controlMesh) {
    firstFace_.reset();
    hoverFace_.reset();
    loadDocumentScene();  // materials and pins come with the rebuilt scene
  } else if (change->materialsOrPins) {
    controller_->loop().restoreEdits(document_.project().materials, document_.project().pins);
  }
}

void SculptApp::syncDocument() {
  // A paint or pin stroke becomes one undo entry once the simulation has captured its result.
  if (std::optional<SceneEdits> edits = controller_->loop().takeEdits()) {
    if (pendingCapture_ != Capture::None) {
      Project after = document_.project();
      if (pendingCapture_ == Capture::Materials)
        after.materials = std::move(edits->materials);
      else
        after.pins = std::move(edits->pins);
      document_.commit(pendingLabel_, std::move(after));
      pendingCapture_ = Capture::None;
    }
  }
  if (materialEditPending_ && pendingCapture_ == Capture::None && !ImGui::GetIO().MouseDown[0]) {
    materialEditPending_ = false;
    controller_->loop().requestEdits();
    pendingCapture_ = Capture::Materials;
    pendingLabel_ = "Set material";
  }
  if (const std::string problem = document_.tick(); !problem.empty())
    model_.toast(problem, true, 8.0);
  model_.controlMeshScene = documentSource_.kind == SceneKind::ControlMesh;
  DocumentStatus& d = model_.document;
  d.title = document_.title();
  d.name = documentName(document_.path());
  d.dirty = document_.dirty();
  d.hasPath = !document_.path().empty();
  d.canUndo = document_.canUndo();
  d.canRedo = document_.canRedo();
  d.undoLabel = document_.undoLabel();
  d.redoLabel = document_.redoLabel();
  const std::string title = "sculpt - " + d.title;
  if (title != lastTitle_ && !options_.headless) glfwSetWindowTitle(window_, title.c_str());
  lastTitle_ = title;
  closeOnTerminationSignal();
  askBeforeClosingUnsaved();
}

void SculptApp::closeOnTerminationSignal() {
  // Nobody may be there to answer a prompt (a logout, `kill`): keep the work, then close.
  const int signal = terminationSignal();
  if (signal == 0 || terminatedBy_ != 0) return;
  const auto now = std::chrono::steady_clock::now();
  if (!terminationNoted_) {
    terminationNoted_ = now;
    if (stroke_ != 0 && pendingCapture_ != Capture::None) {  // a paint or pin stroke still held
      endToolStroke();
      controller_->loop().requestEdits();
    }
  }
  // A stroke's edit comes back from the simulation within a few steps: wait for it, not forever.
  if (pendingCapture_ != Capture::None && now - *terminationNoted_ < std::chrono::seconds(2))
    return;
  terminatedBy_ = signal;
  keepUnsavedWork(terminationSignalName(signal));
  closeConfirmed_ = true;
  glfwSetWindowShouldClose(window_, 1);
}

void SculptApp::keepUnsavedWork(const char* reason) {
  if (!document_.dirty()) return;
  storeSettingsInProject();
  const std::filesystem::path& recovery = document_.recoveryPath();
  try {
    std::error_code ignored;  // a folder that cannot be made fails the save, with its reason
    if (recovery.has_parent_path())
      std::filesystem::create_directories(recovery.parent_path(), ignored);
    saveProject(document_.project(), recovery);
    std::cerr << "sculpt: " << reason << ": the unsaved work is kept in " << recovery.string()
              << " (offered at the next start)\n";
  } catch (const std::exception& error) {
    std::cerr << "sculpt: " << reason << ": the unsaved work could not be kept: " << error.what()
              << '\n';
  }
}

void SculptApp::askBeforeClosingUnsaved() {
  // The window is closing (its close button, Ctrl+Q, File > Quit): ask about unsaved changes
  // first (not when a test closes it).
  if (!options_.headless && glfwWindowShouldClose(window_) && document_.dirty() &&
      !closeConfirmed_ && options_.quitAfter <= 0.0) {
    glfwSetWindowShouldClose(window_, 0);
    model_.document.closePrompt = true;
  }
}

}  // namespace sculpt::app
