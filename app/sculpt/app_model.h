#pragma once
// The window's state as the panels see it: what they show, what they edit, and the requests they
// leave for the application to carry out after the UI pass (the panels never call the simulation
// or the renderer directly).

#include <array>
#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "render/camera.h"
#include "scene/scene_controller.h"
#include "sculpt/display_settings.h"
#include "sculpt/file_browser.h"
#include "sculpt/navigation.h"
#include "sculpt/record_state.h"
#include "sculpt/scene_view.h"
#include "sculpt/tool_state.h"

namespace sculpt::app {

struct ScreenshotSettings {
  int supersample = 1;         ///< 1, 2 or 4
  bool transparent = false;    ///< clear to alpha 0
  bool includePanels = false;  ///< the whole window rather than the 3D view
  std::string folder = "screenshots";
};

/// What the panels ask for; cleared every frame after the application has acted on it.
struct Requests {
  bool screenshot = false, frameModel = false, frameAll = false, toggleOrthographic = false;
  std::optional<render::StandardView> standardView;
  bool togglePlay = false, stepOnce = false, reset = false;
  bool applySettings = false;  ///< the edited SceneSettings (rebuilds when needed)
  std::string loadScene;       ///< a path to load (a scene or a .sculpt project); empty: none
  std::string replayScript;    ///< a session script to play on the scene shown; empty: none
  bool cancelBuild = false, quit = false, uiScaleChanged = false;
  // Edit history and files (document.h)
  bool undo = false, redo = false, save = false;
  std::string saveAs;            ///< a path to save the project to; empty: none
  bool closeSave = false, closeDiscard = false;  ///< answers to the unsaved-changes prompt
  bool recover = false, discardRecovery = false;  ///< answers to the recovery offer
  RecordRequests record;  ///< recording, the timeline and the export dialog
};

/// The document as the panels show it (document.h keeps the real state).
struct DocumentStatus {
  std::string title = "untitled";  ///< with " *" when there are unsaved changes
  std::string name = "untitled";   ///< the file name alone
  bool dirty = false, hasPath = false;
  bool canUndo = false, canRedo = false;
  std::string undoLabel, redoLabel;
  std::string recoveryOffer;  ///< a recovery file to offer after a crash; empty: none
  bool closePrompt = false;   ///< the window is closing with unsaved changes
};

/// Figures for the status strip.
struct Status {
  double frameMs = 0, simulationMs = 0, sceneDrawMs = 0, uploadMs = 0;
  size_t uploadBytes = 0, triangles = 0, nodes = 0;
  std::array<uint32_t, 3> elementCounts{};  ///< tricubic, trilinear, pyramid
  double simulatedTime = 0, stepsPerSecond = 0;
  std::optional<double> realTimeFactor;  ///< simulated seconds per second, over the last second
  bool physicsReady = false, playing = true;
  std::string description, lastStepMessage;
  BuildStatus build;
};

struct Toast {
  std::string text;
  std::chrono::steady_clock::time_point until;
  bool error = false;
};

struct AppModel {
  SceneSettings settings;  ///< as edited in the panels (applied on request)
  DisplaySettings display;
  NavigationPreset preset = NavigationPreset::Blender;
  ScreenshotSettings screenshot;
  Status status;
  FieldRange fieldRange;  ///< the colour map's range this frame
  std::string sceneFile;  ///< the scene shown (empty: the default bunny)
  bool controlMeshScene = false;  ///< its surface is the control mesh's boundary (no cage)
  std::array<char, 1024> scenePathInput{};
  std::vector<std::string> recentScenes;  ///< most recent first (File > Recent)
  bool showHelp = false, showPanels = true;
  bool showStylus = false;  ///< the stylus (haptic device) panel
  float uiScale = 1.0f;
  std::vector<Toast> toasts;
  Requests requests;
  ToolState tools;
  DocumentStatus document;
  FileBrowser fileBrowser;        ///< Open, Import surface, Save As and the export path
  bool openSaveAsDialog = false;  ///< Ctrl+Shift+S, or Save of an untitled project (next frame)
  bool openOpenDialog = false;    ///< Ctrl+O (next frame)
  /// The topology tool's face selection and hover, as "cell c, face f" for the panel.
  std::string topologySelection;
  RecordStatus record;
  ExportDialog exportDialog;

  void toast(std::string text, bool error = false, double seconds = 4.0) {
    toasts.push_back({std::move(text),
                      std::chrono::steady_clock::now() +
                          std::chrono::milliseconds(static_cast<int>(seconds * 1000)),
                      error});
  }
};

}  // namespace sculpt::app
