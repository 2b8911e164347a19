#pragma once
// The window application: one frame = take the newest scene state from the SceneController,
// handle the pointer and the keys (unless ImGui wants them), draw the panels and the 3D view.
// The same frame code serves the interactive window (simulation on worker threads) and the
// headless mode (offscreen, simulation stepped once per frame on this thread, reproducible).

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <chrono>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "edit/topology_edit.h"
#include "project/preferences.h"
#include "render/gpu_timer.h"
#include "sculpt/app_model.h"
#include "sculpt/export_job.h"
#include "sculpt/recording.h"
#include "sculpt/rendered_frames.h"
#include "scene/document.h"
#include "sculpt/navigation.h"
#include "sculpt/options.h"
#include "sculpt/panels.h"
#include "sculpt/real_time_factor.h"
#include "scene/scene_controller.h"
#include "sculpt/scene_view.h"
#include "sculpt/stylus_device.h"
#include "scene/material_picker.h"
#include "tools/session_script.h"
#include "tools/strokes.h"

namespace sculpt::app {

class SculptApp {
 public:
  /// `window` has a current OpenGL 3.3 core context; ImGui is set up here. `started`: when the
  /// process started (for the time to the first frame). `preferences` (key map, UI scale, recent
  /// scenes) come from `preferencesFile`, which the interactive window rewrites when it closes.
  /// `controller`: one from startSceneBuild(options) (scene_start.h); null, the app makes its
  /// own and starts the build itself.
  SculptApp(GLFWwindow* window, const Options& options,
            std::chrono::steady_clock::time_point started, LoadedPreferences preferences,
            std::filesystem::path preferencesFile,
            std::unique_ptr<SceneController> controller = nullptr);
  ~SculptApp();
  SculptApp(const SculptApp&) = delete;
  SculptApp& operator=(const SculptApp&) = delete;

  /// The interactive loop until the window closes. Returns the exit status.
  int runWindow();
  /// Renders options.frames frames offscreen and writes options.screenshot. Returns the exit
  /// status (2 when the scene cannot be built).
  int runHeadless();
  /// Times options.benchFrames frames offscreen and prints key=value figures.
  int runBenchmark();
  /// Records options.recordSeconds of simulated time and writes every options.recordOut
  /// (take_rendering.cpp). Returns the exit status.
  int runRecording();

  /// Tests and the documentation's screenshots drive the window through this: called every
  /// frame after the platform input and before the UI, it may set the mouse and keys of
  /// ImGui's IO; frames are then handled as interactive (input, tools, depth under the cursor).
  void setInputHook(std::function<void(ImGuiIO&, int frame)> hook) { inputHook_ = std::move(hook); }
  /// Renders one frame offscreen as runHeadless does (after setInputHook) and, when `screenshot`
  /// is not empty, writes it there.
  void headlessFrame(const std::string& screenshot = {});
  /// Writes the frame last drawn by headlessFrame() to `path`, as its `screenshot` would have.
  void screenshotLastFrame(const std::string& path);
  /// For tests and the scripted screenshots: the panels' model (tools can be chosen in it), the
  /// document, the camera, the 3D view's rectangle and what it shows.
  AppModel& model() { return model_; }
  const Document& document() const { return document_; }
  const render::Camera& camera() const { return camera_; }
  render::Camera& camera() { return camera_; }  ///< to place the view (tests, scripts)
  ViewRect viewRect() const { return lastView_; }
  const SceneView& sceneView() const { return view_; }
  StylusDevice& stylus() { return stylus_; }
  /// The recording and its timeline (the bottom strip's Record, playhead and Live).
  Recording& recording() { return *recording_; }
  /// What the export dialog's Export button does: exports the take as model().exportDialog says,
  /// geometry on a worker thread, PNG frames and video one frame per window frame (the view
  /// plays the take as it renders). False (with a toast) when it cannot start.
  bool startExport();
  ExportJob& exportJob() { return *export_; }
  /// An export started and not yet finished, of either kind.
  bool exporting() const { return export_->busy() || rendered_.has_value(); }
  /// The last export that finished (written, failed or cancelled).
  const std::optional<ExportJob::Outcome>& lastExport() const { return lastExport_; }

 private:
  /// Builds the UI and draws the scene into the bound framebuffer (fbWidth x fbHeight pixels).
  void frame(int fbWidth, int fbHeight, bool interactive);
  void syncScene();
  /// Holds a close of the window with unsaved changes and shows the prompt instead.
  void askBeforeClosingUnsaved();
  /// After SIGTERM, SIGINT or SIGHUP: writes the recovery file of unsaved work and closes, unasked.
  void closeOnTerminationSignal();
  /// Writes the recovery file of unsaved work (no GLFW or GL calls); `reason` starts its message.
  void keepUnsavedWork(const char* reason);
  /// At the window's close: how fast the simulation ran since it started, and how many frames
  /// the window drew meanwhile, on stdout.
  void reportRun();
  void handleInput(const ViewRect& view);
  // Tools (sculpt_tools.cpp)
  struct SurfaceHit {
    glm::vec3 world;       ///< the point under the cursor (deformed)
    Eigen::Vector3d rest;  ///< its material point's rest position (nearest surface vertex)
  };
  std::optional<SurfaceHit> surfaceHit(float x, float y, float depth, int width, int height);
  double brushWorldRadius(float x, float y, float depth, int width, int height) const;
  Eigen::Vector3d mirrorCentre() const;
  void toolStroke(const PointerResult& stroke, float x, float y, int width, int height);
  ToolInput toolInput(const glm::vec3& world, const std::optional<Eigen::Vector3d>& rest) const;
  void endToolStroke();
  void takeEyedropperResult();
  void pullStroke(const PointerResult& stroke, float x, float y, int width, int height);
  void stylusStroke(const PointerResult& stroke, float x, float y, int width, int height);
  struct CursorRay {
    glm::vec3 origin, direction;  ///< from the near plane, unit
  };
  std::optional<CursorRay> cursorRay(float x, float y, int width, int height) const;
  void brushStroke(const PointerResult& stroke, float x, float y, int width, int height);
  void curveStroke(const PointerResult& stroke, float x, float y, int width, int height);
  void topologyClick(const PointerResult& stroke, float x, float y, int width, int height);
  void applyTopology(const std::vector<FaceRef>& picked);
  std::vector<FaceRef> withMirroredFaces(const std::vector<FaceRef>& faces) const;
  bool brushKeys(const ImGuiIO& io, float dx);  // F / Shift+F drag; true while it owns the mouse
  bool viewHasKeys_ = true;  // this frame's shortcuts go to the view (handleInput)
  void drawToolOverlay(const ViewRect& view);
  // Document (sculpt_document.cpp)
  void startDocumentFromScene(const SceneGeometry& geometry);
  void loadDocumentScene();
  void openFile(const std::string& path);
  void openProject(const std::filesystem::path& path, const std::filesystem::path& from);
  bool saveDocument(const std::string& saveAsPath);
  void undoRedo(bool redo);
  void syncDocument();
  void storeSettingsInProject();
  void runAction(Action action);
  void carryOutRequests();
  void drawScene(const ViewRect& view, int fbWidth, int fbHeight, float pixelScale);
  void frameModel(bool withCage);
  void writeScreenshot(const std::string& path, const ScreenshotSettings& settings);
  std::string nextScreenshotPath() const;
  void loadScene(const std::string& path);
  void applyUiScale();
  void reportFirstFrame();
  void savePreferencesOnClose();
  float viewAspect() const;

  GLFWwindow* window_;
  Options options_;
  std::chrono::steady_clock::time_point started_;
  std::unique_ptr<SceneController> controller_;
  SceneView view_;
  render::Camera camera_;
  Navigator navigator_;
  KeyMap keys_ = KeyMap::defaults();
  AppModel model_;
  Preferences preferences_;
  std::filesystem::path preferencesFile_;
  ViewRect lastView_{};
  int lastFbWidth_ = 0, lastFbHeight_ = 0;
  float cursorDepth_ = 1.0f;  ///< depth under the cursor in the last drawn frame
  float grabDistance_ = 0.0f;  ///< the pull target's distance along the cursor ray (wheel)
  float lastCursorX_ = 0.0f, lastCursorY_ = 0.0f;
  bool cameraFramed_ = false;
  bool firstFrameReported_ = false, physicsReported_ = false;
  bool sceneChanged_ = false;  ///< this frame showed something new (the window loop keeps drawing)
  double firstFrameSeconds_ = 0.0, windowReadySeconds_ = 0.0;
  double geometryArrivedSeconds_ = 0.0, geometryUploadSeconds_ = 0.0;
  SceneFrame latest_;
  render::GpuTimer sceneTimer_;
  std::chrono::steady_clock::time_point lastFrameTime_;
  PaceMark rateMark_;  // the start of the status strip's one-second window
  std::optional<PaceMark> runMark_;  // the simulation as first seen running
  int runMarkFrame_ = 0;             // frameIndex_ then
  bool imguiReady_ = false;
  std::function<void(ImGuiIO&, int)> inputHook_;
  int frameIndex_ = 0;
  StylusDevice stylus_;  ///< the haptic stylus (simulated-device mode: driven by the mouse)
  bool stylusHeld_ = false;

  // The user's work and the tools
  Document document_;
  SceneSource documentSource_;          ///< where the document's surface comes from
  bool documentFromNextScene_ = true;   ///< the next scene built starts a new document
  bool recoveryChecked_ = false;
  std::filesystem::path recoveryFile_;  ///< offered after a crash
  bool closeConfirmed_ = false;
  std::optional<std::chrono::steady_clock::time_point> terminationNoted_;  ///< SIGTERM or SIGINT
  int terminatedBy_ = 0;  ///< the signal the window closed for; 0: none
  enum class Capture { None, Materials, Pins };
  Capture pendingCapture_ = Capture::None;  ///< a stroke waiting for the simulation's state
  std::string pendingLabel_;
  bool materialEditPending_ = false;  ///< the body material changed: record it once let go
  std::string lastTitle_;
  ToolKind strokeTool_ = ToolKind::Pull;
  uint64_t stroke_ = 0;  ///< the tool stroke in progress (SimulationLoop::beginStroke); 0: none
  std::unique_ptr<MaterialPicker> picker_;  ///< over the frame last picked in
  uint64_t pickerFrame_ = 0, pickerScene_ = 0;
  std::shared_ptr<Eyedropper::Result> eyedropper_;  ///< a pick on its way back
  bool strokeInverted_ = false;  ///< Ctrl at the stroke's start: push, deflate, unpin
  float lastDabX_ = 0, lastDabY_ = 0;
  int brushKey_ = -1;            ///< the frame key held for F / Shift+F drag
  bool brushKeyDragged_ = false, brushKeyStrength_ = false;
  std::vector<Eigen::Vector3d> curveRest_;  ///< the drawn curve (rest positions)
  std::vector<glm::vec3> curveWorld_;       ///< and where it was drawn
  bool curveGrabbed_ = false;
  float curveDepth_ = 1.0f;
  struct PickedFace {
    FaceRef face;
    std::vector<uint32_t> loop;  ///< its vertices, outward
  };
  std::optional<PickedFace> pickFace(float x, float y, int width, int height) const;
  std::optional<PickedFace> hoverFace_, firstFace_;
  std::vector<FaceRef> boundaryFacesOfScene_;  ///< of the control mesh shown
  SceneSource lastGoodSource_;                 ///< the document's source before a load
  // A script with topology events (--script, or File > Replay session script): they edit the
  // control mesh (the document starts from the edited mesh), and the rest of the script plays
  // once that scene simulates. Without them it plays at once.
  std::optional<SessionScript> scriptTopology_, deferredScript_;
  std::string scriptPath_;  ///< of the script being replayed, for its messages
  bool awaitingEditedScene_ = false;
  uint64_t scriptSceneId_ = 0;
  void startScript(SessionScript script, bool documentReady);
  void replayScript(const std::string& path);
  void applyScriptTopology();

  // Recording, the timeline and export (sculpt_recording.cpp)
  void updateRecording();
  void publishRecordStatus();
  void carryOutRecordRequests(const RecordRequests& requests);
  void leaveLive();
  void goLive();
  void showPlayhead();
  void updateExportDialog();
  std::string defaultExportPath() const;
  std::unique_ptr<Recording> recording_ = std::make_unique<Recording>();
  std::unique_ptr<ExportJob> export_ = std::make_unique<ExportJob>();
  std::optional<ExportJob::Outcome> lastExport_;
  /// A PNG or video export in progress: take frame range.first + k x every is rendered on the
  /// k-th window frame after the start.
  struct RenderedExport {
    std::unique_ptr<RenderedFrames> out;
    std::filesystem::path path;
    FrameRange range;
    uint32_t every = 1, count = 0, next = 0;
  };
  std::optional<RenderedExport> rendered_;
  void renderExportFrame();  ///< after a frame is drawn: the shown take frame to the export
  void finishExport(ExportJob::Outcome outcome);  ///< its toast; kept as lastExport()
  bool resumePlaying_ = false;  ///< the simulation played when the playhead left Live
  std::shared_ptr<const SceneGeometry> liveGeometry_;  ///< the controller's newest scene
  const Take* shownTake_ = nullptr;  ///< the take the view shows a frame of (null: live)
  uint32_t shownFrame_ = 0;
  const SceneGeometry* shownGeometry_ = nullptr;  ///< the view's geometry when it was shown
  const Take* dialogTake_ = nullptr;  ///< the take the export dialog's range and estimate are for
  int estimatedFirst_ = -1, estimatedLast_ = -1, estimatedEvery_ = -1, estimatedFormat_ = -1;
  // Headless recording (take_rendering.cpp)
  /// The frame last drawn as writeScreenshot captures it (RGBA8, top row first).
  std::vector<uint8_t> captureFrame(const ScreenshotSettings& settings, int& width, int& height);
  /// Renders frames [0, frames) of the recording's take into name_####.png files and videos;
  /// returns the bytes written. Throws (leaving none of them behind).
  uint64_t renderTake(const std::vector<std::filesystem::path>& pngs,
                      const std::vector<std::filesystem::path>& videos, uint32_t frames);
};

}  // namespace sculpt::app
