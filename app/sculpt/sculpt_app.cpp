#include "sculpt/sculpt_app.h"

#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <iostream>
#include <limits>

#include "project/autosave.h"
#include "project/project_file.h"
#include "render/image_downsample.h"
#include "render/offscreen_target.h"
#include "render/png_image.h"
#include "scene/control_export.h"
#include "scene/scene_file.h"
#include "sculpt/app_clock.h"
#include "sculpt/colour_bar.h"
#include "sculpt/display_loss.h"
#include "sculpt/draw_benchmark.h"
#include "sculpt/help_overlay.h"
#include "sculpt/real_time_factor.h"
#include "sculpt/scene_start.h"
#include "sculpt/ui_scale.h"
#include "tools/session_script.h"

namespace sculpt::app {
namespace {

// Autosave every five minutes of unsaved changes (docs/design/ux.md "Files").
constexpr double kAutosaveIntervalS = 300.0;

int glfwModifiers(const ImGuiIO& io) {
  return (io.KeyShift ? GLFW_MOD_SHIFT : 0) | (io.KeyCtrl ? GLFW_MOD_CONTROL : 0) |
         (io.KeyAlt ? GLFW_MOD_ALT : 0) | (io.KeySuper ? GLFW_MOD_SUPER : 0);
}

FieldKind nextField(FieldKind field) {
  const auto it = std::find(kFieldKinds.begin(), kFieldKinds.end(), field);
  return kFieldKinds[static_cast<size_t>((it - kFieldKinds.begin() + 1) % kFieldKinds.size())];
}

}  // namespace

SculptApp::SculptApp(GLFWwindow* window, const Options& options, Clock::time_point started,
                     LoadedPreferences preferences, std::filesystem::path preferencesFile,
                     std::unique_ptr<SceneController> controller)
    : window_(window),
      options_(options),
      started_(started),
      navigator_(options.stylusPreset ? NavigationPreset::Stylus : NavigationPreset::Blender),
      preferences_(std::move(preferences.preferences)),
      preferencesFile_(std::move(preferencesFile)),
      document_(preferencesFile_.parent_path(), kAutosaveIntervalS, [] {
        return std::chrono::duration<double>(Clock::now().time_since_epoch()).count();
      }) {
  // startSceneBuild's controller builds options.scene already, with the settings below.
  const bool buildingAlready = controller != nullptr;
  controller_ = buildingAlready ? std::move(controller)
                                : std::make_unique<SceneController>(!options.headless);
  if (!preferences.warning.empty()) model_.toast(preferences.warning, true, 8.0);
  if (!preferences_.keyMap.empty()) {  // the user's key map; bad lines are reported and skipped
    std::string problems;
    keys_ = KeyMap::fromText(preferences_.keyMap, &problems);
    if (!problems.empty()) model_.toast("preferences key map: " + problems, true, 8.0);
  }
  model_.recentScenes = preferences_.recentFiles;
  restoreBrushRadii(model_.tools, preferences_.brushRadii);  // a project opened later has its own
  model_.display = options.display;
  model_.preset = navigator_.preset();
  applyCommandLineSettings(options_, model_.settings);
  model_.sceneFile = options.scene;
  model_.showPanels = !options.noUi;
  model_.showHelp = options.showHelp;
  stylus_.setSimulated(options.simulatedDevice);
  if (!options.headless) stylus_.enableHid();
  model_.screenshot.supersample = options.supersample;
  model_.screenshot.transparent = options.transparent;
  model_.record.fps = options.recordFps;

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // layout is fixed; preferences come with the next issue
  ImGui_ImplGlfw_InitForOpenGL(window_, true);
  ImGui_ImplOpenGL3_Init("#version 330 core");
  imguiReady_ = true;
  float sx = 1.0f, sy = 1.0f;
  glfwGetWindowContentScale(window_, &sx, &sy);
  // --ui-scale for this run, else the user's saved choice, else the monitor's content scale.
  model_.uiScale = uiScale(
      sx, sy, options.uiScale > 0.0f ? options.uiScale : static_cast<float>(preferences_.uiScale));
  applyUiScale();
  // Moving the window to a monitor of another scale re-scales the UI (unless --ui-scale is given).
  glfwSetWindowUserPointer(window_, this);
  glfwSetWindowContentScaleCallback(window_, [](GLFWwindow* w, float x, float y) {
    auto* app = static_cast<SculptApp*>(glfwGetWindowUserPointer(w));
    if (app->options_.uiScale > 0.0f) return;
    app->model_.uiScale = uiScale(x, y, 0.0f);
    app->model_.requests.uiScaleChanged = true;
  });

  if (!options.headless) controller_->setChangeNotifier([] { glfwPostEmptyEvent(); });
  if (std::filesystem::path(options.scene).extension() == kProjectExtension) {
    openProject(options.scene, options.scene);  // FileError: main reports it, exit 2
  } else {
    documentSource_ = sceneSourceFor(options.scene);
    if (!buildingAlready) controller_->load(documentSource_, model_.settings);
  }
  if (!options.script.empty()) {
    scriptPath_ = options.script;
    startScript(loadSessionScript(options.script), false);  // FileError: main reports it
  }
  // A lost display ends the process from inside an X call; the unsaved work is kept first.
  onDisplayLoss(
      [](void* app) { static_cast<SculptApp*>(app)->keepUnsavedWork("display lost"); }, this);
  lastFrameTime_ = rateMark_.at = Clock::now();
  windowReadySeconds_ = secondsSince(started_);
}

SculptApp::~SculptApp() {
  onDisplayLoss(nullptr, nullptr);
  if (!options_.headless) savePreferencesOnClose();
  export_.reset();     // cancels an export in flight
  stylus_.stop();      // its session's thread queues strokes on the controller's loop
  recording_.reset();  // its recorder observes the controller's loop
  controller_.reset();  // stop the simulation before the GL objects go
  if (imguiReady_) {
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
  }
}

void SculptApp::applyUiScale() { sculpt::app::applyUiScale(model_.uiScale); }

float SculptApp::viewAspect() const {
  const float w = lastView_.max.x - lastView_.min.x, h = lastView_.max.y - lastView_.min.y;
  return w > 0 && h > 0 ? w / h : 1.6f;
}

void SculptApp::frameModel(bool withCage) {
  if (!view_.hasGeometry()) return;
  glm::vec3 centre = view_.centre();
  float radius = view_.radius();
  if (withCage) {  // the control points as well (Home: frame all)
    const Points& control = view_.frame().control;
    if (control.rows() > 0) {
      const Eigen::Vector3d lo = control.colwise().minCoeff().transpose();
      const Eigen::Vector3d hi = control.colwise().maxCoeff().transpose();
      const glm::vec3 l(lo.x(), lo.y(), lo.z()), h(hi.x(), hi.y(), hi.z());
      const glm::vec3 all = glm::min(l, view_.boxLow()), allHigh = glm::max(h, view_.boxHigh());
      centre = 0.5f * (all + allHigh);
      radius = 0.5f * glm::length(allHigh - all);
    }
  }
  camera_.frame(centre, radius, viewAspect());
  camera_.setSceneBounds(view_.centre(), 3.0f * view_.radius());
}

void SculptApp::syncScene() {
  // Headless: build and step here (a no-op with worker threads); the first frame shows the rest
  // shape as soon as the display data exist, like the window, and the physics follows.
  controller_->advance(!view_.hasGeometry());
  if (std::shared_ptr<const SceneGeometry> geometry = controller_->takeNewGeometry()) {
    sceneChanged_ = true;
    liveGeometry_ = geometry;
    const auto uploadStart = Clock::now();
    view_.setGeometry(geometry);
    geometryUploadSeconds_ = secondsSince(uploadStart);
    geometryArrivedSeconds_ = secondsSince(started_);
    model_.status.description = geometry->description;
    boundaryFacesOfScene_ =
        geometry->controlMesh ? boundaryFaces(*geometry->controlMesh) : std::vector<FaceRef>{};
    hoverFace_.reset();
    firstFace_.reset();
    if (awaitingEditedScene_) {  // the scene the script's topology events made
      awaitingEditedScene_ = false;
      scriptSceneId_ = geometry->sceneId;
    }
    if (documentFromNextScene_) {  // a scene from a file: the user's work starts from it
      documentFromNextScene_ = false;
      startDocumentFromScene(*geometry);
      lastGoodSource_ = documentSource_;
      if (scriptTopology_) applyScriptTopology();
      if (!recoveryChecked_ && !options_.headless) {  // work a crash left behind
        recoveryChecked_ = true;
        std::filesystem::path project = document_.recoveryPath();
        project.replace_extension();  // ".../untitled.sculpt.recovery" -> ".../untitled.sculpt"
        if (const auto recovery = findRecovery(project)) {
          recoveryFile_ = *recovery;
          model_.document.recoveryOffer = recovery->string();
        }
      }
    }
    if (!model_.sceneFile.empty()) {  // a scene that built is worth offering again
      std::error_code ignored;
      const std::filesystem::path absolute = std::filesystem::absolute(model_.sceneFile, ignored);
      preferences_.addRecentFile(absolute.empty() ? model_.sceneFile : absolute.string());
      model_.recentScenes = preferences_.recentFiles;
    }
    model_.status.elementCounts = geometry->elementCounts;
    model_.status.triangles = view_.numTriangles();
    if (!cameraFramed_) {
      camera_.setOrientation(0.5f, 0.3f);
      frameModel(false);
      cameraFramed_ = true;
    }
  }
  if (controller_->fetchNewer(latest_)) {
    sceneChanged_ = true;
    if (recording_->isLive()) view_.setFrame(latest_, model_.display);
    // The last step's time until a window of this scene's steps gives their mean (below).
    if (latest_.sceneId != rateMark_.sceneId) model_.status.simulationMs = latest_.stepMs;
    model_.status.simulatedTime = latest_.simulatedTime;
    model_.status.physicsReady = latest_.physicsReady;
    if (latest_.physicsReady && !physicsReported_) {
      physicsReported_ = true;
      std::printf("simulation running after %.2f s\n", secondsSince(started_));
      runMark_ = paceMark(latest_, Clock::now());
      runMarkFrame_ = frameIndex_;
      std::fflush(stdout);
    }
    if (deferredScript_ && latest_.physicsReady && scriptSceneId_ != 0 &&
        latest_.sceneId == scriptSceneId_)
      controller_->loop().playScript(*std::exchange(deferredScript_, std::nullopt));
    model_.status.uploadBytes = view_.lastUploadBytes();
    model_.status.uploadMs = view_.lastUploadMs();
    if (!latest_.lastStep.message.empty() &&
        latest_.lastStep.message != model_.status.lastStepMessage)
      model_.toast(latest_.lastStep.message, !latest_.lastStep.ok);
    model_.status.lastStepMessage = latest_.lastStep.message;
  }
  // The strain energy costs the simulation an element pass a step: only while it is shown.
  controller_->loop().setStrainEnergyShown(model_.display.field == FieldKind::StrainEnergy);
  stylus_.attach(controller_->loop(), view_.sharedGeometry(), controller_->settings(),
                 latest_.physicsReady);
  stylus_.setView(camera_);
  if (secondsSince(rateMark_.at) > 1.0) {
    const PaceMark mark = paceMark(latest_, Clock::now());
    const Pace pace = paceBetween(rateMark_, mark);
    if (pace.stepsPerSecond) model_.status.stepsPerSecond = *pace.stepsPerSecond;
    model_.status.realTimeFactor = pace.realTimeFactor;
    if (pace.meanStepMs) model_.status.simulationMs = *pace.meanStepMs;
    rateMark_ = mark;
  }
  const BuildStatus build = controller_->buildStatus();
  if (!build.error.empty() && build.error != model_.status.build.error) {
    model_.toast(build.error, true, 8.0);
    if (documentFromNextScene_ && view_.hasGeometry()) {  // the document stays with its scene
      documentFromNextScene_ = false;
      documentSource_ = lastGoodSource_;
    }
  }
  model_.status.build = build;
  model_.status.playing = controller_->loop().playing();
  model_.status.nodes = view_.hasGeometry() ? view_.geometry()->cellMesh.numNodes() : 0;
  syncDocument();
}

void SculptApp::runAction(Action action) {
  Requests& r = model_.requests;
  DisplaySettings& d = model_.display;
  switch (action) {
    case Action::FrameModel: r.frameModel = true; break;
    case Action::FrameAll: r.frameAll = true; break;
    case Action::PlayPause: r.togglePlay = true; break;
    case Action::StepOnce: r.stepOnce = true; break;
    case Action::ResetSimulation: r.reset = true; break;
    case Action::ToggleRecord: r.record.toggleRecord = true; break;
    case Action::ToggleWireframe: d.wireframe = !d.wireframe; break;
    case Action::ToggleFlatShading: d.flatShading = !d.flatShading; break;
    case Action::ToggleCellEdges: d.showCells = !d.showCells; break;
    case Action::ToggleSlice: d.clip = !d.clip; break;
    case Action::CycleField: d.field = nextField(d.field); break;
    case Action::CycleDeformation:
      d.method = static_cast<InterpolationMethod>((static_cast<int>(d.method) + 1) % 4);
      model_.toast("deformation: " + std::string(methodName(d.method)));
      break;
    case Action::ToggleHelp: model_.showHelp = !model_.showHelp; break;
    case Action::Screenshot: r.screenshot = true; break;
    case Action::Quit: r.quit = true; break;
    case Action::Undo: r.undo = true; break;
    case Action::Redo:
    case Action::RedoAlternative: r.redo = true; break;
    case Action::Save: r.save = true; break;
    case Action::SaveAs: model_.openSaveAsDialog = true; break;
    case Action::Open: model_.openOpenDialog = true; break;
    case Action::BrushSmaller: {
      float& radius = model_.tools.brush().radiusPixels;
      radius = std::max(kMinBrushRadiusPixels, radius / 1.25f);
      break;
    }
    case Action::BrushLarger: {
      float& radius = model_.tools.brush().radiusPixels;
      radius = std::min(kMaxBrushRadiusPixels, radius * 1.25f);
      break;
    }
    default: applyCameraAction(action, camera_); break;
  }
}

void SculptApp::handleInput(const ViewRect& view) {
  const ImGuiIO& io = ImGui::GetIO();
  // Shortcuts act whenever no text is being typed and either the panels do not want the keys
  // or the pointer is over the 3D view (a panel clicked last keeps ImGui's focus otherwise).
  const bool overView = !io.WantCaptureMouse && io.MousePos.x >= view.min.x &&
                        io.MousePos.x < view.max.x && io.MousePos.y >= view.min.y &&
                        io.MousePos.y < view.max.y;
  viewHasKeys_ = !io.WantTextInput && (!io.WantCaptureKeyboard || overView);
  const bool brushKeyHeld = brushKeys(io, io.MousePos.x - lastCursorX_);
  if (viewHasKeys_) {
    for (int key = GLFW_KEY_SPACE; key <= GLFW_KEY_LAST; ++key)
      if (ImGui::IsKeyPressed(key, false) && !(brushKeyHeld && key == brushKey_))
        if (const std::optional<Action> action = keys_.actionFor(key, glfwModifiers(io)))
          runAction(*action);
  }
  if (navigator_.preset() != model_.preset) navigator_.setPreset(model_.preset);
  PointerInput input;
  input.x = io.MousePos.x - view.min.x;
  input.y = io.MousePos.y - view.min.y;
  input.dx = io.MousePos.x - lastCursorX_;
  input.dy = io.MousePos.y - lastCursorY_;
  lastCursorX_ = io.MousePos.x, lastCursorY_ = io.MousePos.y;
  input.left = io.MouseDown[0], input.right = io.MouseDown[1], input.middle = io.MouseDown[2];
  input.modifiers = glfwModifiers(io);
  input.wheel = io.MouseWheel;
  if (stroke_ != 0 && strokeTool_ == ToolKind::Pull && input.wheel != 0.0f &&
      !io.WantCaptureMouse) {
    // While pulling, the wheel sets the target's depth (a tenth of the distance per notch).
    grabDistance_ *= std::pow(1.1f, -input.wheel);
    input.wheel = 0.0f;
  }
  input.doubleClick = io.MouseDoubleClicked[0] || io.MouseDoubleClicked[2];
  input.overObject = cursorDepth_ < 1.0f;
  input.uiWantsMouse = io.WantCaptureMouse;
  const int width = std::max(1, static_cast<int>(view.max.x - view.min.x));
  const int height = std::max(1, static_cast<int>(view.max.y - view.min.y));
  const PointerResult result = navigator_.update(input, camera_, width, height);
  if (result.cameraChanged || result.gesture != Gesture::None) sceneChanged_ = true;
  if (!brushKeyHeld && recording_->isLive()) toolStroke(result, input.x, input.y, width, height);
  if (model_.tools.tool == ToolKind::Topology && !io.WantCaptureMouse &&
      result.gesture == Gesture::None)
    hoverFace_ = pickFace(input.x, input.y, width, height);
  model_.topologySelection =
      firstFace_ ? "first face: cell " + std::to_string(firstFace_->face.cell) + ", face " +
                       std::to_string(firstFace_->face.face)
                 : std::string();
  if (result.setPivotRequested && !io.WantCaptureMouse) {
    if (const std::optional<glm::vec3> pivot =
            camera_.unproject(input.x, input.y, cursorDepth_, width, height))
      camera_.setPivot(*pivot);
  }
}


void SculptApp::carryOutRequests() {
  Requests r = std::exchange(model_.requests, Requests{});
  carryOutRecordRequests(r.record);
  if (r.screenshot || r.frameModel || r.frameAll || r.standardView || r.toggleOrthographic ||
      r.togglePlay || r.stepOnce || r.reset || r.applySettings || !r.loadScene.empty())
    sceneChanged_ = true;
  if (r.quit) {
    glfwSetWindowShouldClose(window_, 1);
    askBeforeClosingUnsaved();  // the loop ends before the next frame could ask
  }
  if (r.frameModel) frameModel(false);
  if (r.frameAll) frameModel(true);
  if (r.standardView) camera_.setStandardView(*r.standardView);
  if (r.toggleOrthographic) camera_.toggleOrthographic();
  if (r.togglePlay) controller_->loop().setPlaying(!controller_->loop().playing());
  if (r.stepOnce) {
    controller_->loop().setPlaying(false);
    controller_->loop().stepOnce();
  }
  if (r.reset) controller_->loop().reset();
  try {
    if (r.applySettings) {
      const SceneSettings current = controller_->settings();
      if (model_.settings.cageCellsAcross != current.cageCellsAcross &&
          documentSource_.kind != SceneKind::ControlMesh) {
        // A new cage is a new control mesh: the work starts again from the surface.
        if (document_.dirty())
          model_.toast("a new cage starts a new project (the old one is autosaved)");
        loadScene(documentSource_.kind == SceneKind::DefaultBunny ? std::string()
                                                                  : documentSource_.path);
      } else if (model_.settings.needsRebuild(current)) {
        loadDocumentScene();  // the edited control mesh, materials and pins at the new level
      } else {
        const Material before = controller_->settings().material;
        controller_->applySettings(model_.settings);
        // The body material fills every sample: an edit of the project (one undo entry, made
        // when the slider is let go).
        if (model_.settings.material != before) materialEditPending_ = true;
      }
    }
    if (!r.loadScene.empty()) openFile(r.loadScene == "<default>" ? std::string() : r.loadScene);
    if (!r.replayScript.empty()) replayScript(r.replayScript);
  } catch (const std::invalid_argument& error) {
    model_.toast(error.what(), true, 8.0);
  }
  if (r.undo) undoRedo(false);
  if (r.redo) undoRedo(true);
  if (r.save) saveDocument({});
  if (!r.saveAs.empty()) saveDocument(r.saveAs);
  if (r.closeSave && saveDocument({})) {
    closeConfirmed_ = true;
    glfwSetWindowShouldClose(window_, 1);
  }
  if (r.closeDiscard) {
    document_.discardRecovery();
    closeConfirmed_ = true;
    glfwSetWindowShouldClose(window_, 1);
  }
  if (r.recover || r.discardRecovery) {
    const std::filesystem::path recovery = recoveryFile_;
    model_.document.recoveryOffer.clear();
    recoveryFile_.clear();
    if (r.recover) {
      try {  // the recovery of an untitled project stays untitled; of a project, its file
        std::filesystem::path original = recovery;
        original.replace_extension();  // "x.sculpt.recovery" -> "x.sculpt"
        openProject(original.filename() == "untitled.sculpt" ? std::filesystem::path() : original,
                    recovery);
      } catch (const std::exception& error) {
        model_.toast(std::string("cannot recover: ") + error.what(), true, 8.0);
      }
    } else {
      std::error_code ignored;
      std::filesystem::remove(recovery, ignored);
    }
  }
  if (r.cancelBuild) controller_->cancelBuild();
  if (r.uiScaleChanged) {
    applyUiScale();
    preferences_.uiScale = model_.uiScale;  // a choice in the menu is remembered
  }
  if (r.screenshot) {
    const std::string path = nextScreenshotPath();
    try {
      writeScreenshot(path, model_.screenshot);
      model_.toast("wrote " + path);
    } catch (const std::exception& error) {
      model_.toast(std::string("screenshot failed: ") + error.what(), true, 8.0);
    }
  }
}

void SculptApp::loadScene(const std::string& path) {
  model_.sceneFile = path;
  cameraFramed_ = false;
  documentSource_ = sceneSourceFor(path);
  documentFromNextScene_ = true;
  controller_->load(documentSource_, model_.settings);
}

void SculptApp::drawScene(const ViewRect& view, int fbWidth, int fbHeight, float pixelScale) {
  // The 3D view's rectangle in framebuffer pixels (GL's origin is the bottom left).
  const int x = static_cast<int>(std::lround(view.min.x * pixelScale));
  const int w = std::max(1, static_cast<int>(std::lround((view.max.x - view.min.x) * pixelScale)));
  const int h = std::max(1, static_cast<int>(std::lround((view.max.y - view.min.y) * pixelScale)));
  const int y = fbHeight - static_cast<int>(std::lround(view.max.y * pixelScale));
  (void)fbWidth;
  glViewport(x, y, w, h);
  glEnable(GL_DEPTH_TEST);
  if (!view_.hasGeometry()) return;
  const DisplaySettings& display = model_.display;
  FieldRange range = view_.fieldRange(display.field);
  if (!display.autoRange) range = {display.rangeLow, display.rangeHigh};
  model_.fieldRange = range;
  sceneTimer_.begin();
  view_.draw(camera_.view(), camera_.projection(static_cast<float>(w) / static_cast<float>(h)),
             display, range);
  sceneTimer_.end();
  model_.status.sceneDrawMs = sceneTimer_.lastMilliseconds();
}

void SculptApp::frame(int fbWidth, int fbHeight, bool interactive) {
  const auto now = Clock::now();
  model_.status.frameMs = std::chrono::duration<double, std::milli>(now - lastFrameTime_).count();
  lastFrameTime_ = now;
  syncScene();
  updateRecording();

  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  if (inputHook_) {
    inputHook_(ImGui::GetIO(), frameIndex_);
    interactive = true;
  }
  ++frameIndex_;
  ImGui::NewFrame();
  ViewRect view;
  if (options_.noUi) {
    const ImGuiViewport* viewport = ImGui::GetMainViewport();
    view = {viewport->Pos,
            ImVec2(viewport->Pos.x + viewport->Size.x, viewport->Pos.y + viewport->Size.y)};
  } else {
    view = drawPanels(model_);
    drawColourBar(model_.display.field, model_.fieldRange, view.min, view.max);
    drawBuildProgress(model_, view);
    if (model_.showStylus || stylus_.simulated()) stylus_.drawPanel(view.min, view.max);
    if (stylus_.active() && !ImGui::GetIO().WantTextInput &&
        ImGui::IsKeyPressed(GLFW_KEY_ESCAPE, false))
      stylus_.panic();  // the panic key: the stylus' force goes to zero until re-armed
    drawToasts(model_, view);
    if (model_.showHelp) drawHelpOverlay(keys_, model_.preset, &model_.showHelp);
  }
  lastView_ = view;
  if (interactive) handleInput(view);
  drawToolOverlay(view);
  ImGui::Render();

  const float pixelScale = ImGui::GetIO().DisplayFramebufferScale.x;
  glViewport(0, 0, fbWidth, fbHeight);
  glDisable(GL_SCISSOR_TEST);
  clearBackground(false, stylus_.backgroundTint());
  drawScene(view, fbWidth, fbHeight, pixelScale);
  if (interactive && view_.hasGeometry()) {
    // Depth under the cursor, for the pivot (double click) and the Stylus preset's
    // object-or-background test in the next frame.
    const ImVec2 mouse = ImGui::GetIO().MousePos;
    const int px = static_cast<int>(mouse.x * pixelScale);
    const int py = fbHeight - 1 - static_cast<int>(mouse.y * pixelScale);
    cursorDepth_ = 1.0f;
    if (px >= 0 && py >= 0 && px < fbWidth && py < fbHeight)
      glReadPixels(px, py, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &cursorDepth_);
  }
  glViewport(0, 0, fbWidth, fbHeight);
  if (!options_.noUi) ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  lastFbWidth_ = fbWidth, lastFbHeight_ = fbHeight;
  carryOutRequests();
  renderExportFrame();
  if (view_.hasGeometry() && !firstFrameReported_) reportFirstFrame();
}

void SculptApp::savePreferencesOnClose() {
  int x = 0, y = 0;
  glfwGetWindowPos(window_, &x, &y);
  preferences_.window.maximized = glfwGetWindowAttrib(window_, GLFW_MAXIMIZED) == GLFW_TRUE;
  if (!preferences_.window.maximized) {
    preferences_.window.x = x, preferences_.window.y = y;
    glfwGetWindowSize(window_, &preferences_.window.width, &preferences_.window.height);
  }
  preferences_.brushRadii = brushRadii(model_.tools);
  try {
    savePreferences(preferences_, preferencesFile_);
  } catch (const std::exception& error) {  // never lose the session over preferences
    std::cerr << "warning: preferences not saved: " << error.what() << '\n';
  }
}

}  // namespace sculpt::app
