#pragma once
// The window application: one frame = take the newest scene state from the SceneController,
// handle the pointer and the keys (unless ImGui wants them), draw the panels and the 3D view.
// The same frame code serves the interactive window (simulation on worker threads) and the
// headless mode (offscreen, simulation stepped once per frame on this thread, reproducible).

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <chrono>
#include <memory>
#include <optional>
#include <string>

#include "project/preferences.h"
#include "render/gpu_timer.h"
#include "sculpt/app_model.h"
#include "sculpt/navigation.h"
#include "sculpt/options.h"
#include "sculpt/panels.h"
#include "sculpt/scene_controller.h"
#include "sculpt/scene_view.h"

namespace sculpt::app {

class SculptApp {
 public:
  /// `window` has a current OpenGL 3.3 core context; ImGui is set up here. `started`: when the
  /// process started (for the time to the first frame). `preferences` (key map, UI scale, recent
  /// scenes) come from `preferencesFile`, which the interactive window rewrites when it closes.
  SculptApp(GLFWwindow* window, const Options& options,
            std::chrono::steady_clock::time_point started, LoadedPreferences preferences,
            std::filesystem::path preferencesFile);
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

 private:
  /// Builds the UI and draws the scene into the bound framebuffer (fbWidth x fbHeight pixels).
  void frame(int fbWidth, int fbHeight, bool interactive);
  void syncScene();
  void handleInput(const ViewRect& view);
  void pullStroke(const PointerResult& stroke, float x, float y, int width, int height);
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
  float grabDepth_ = 1.0f;    ///< depth of the point grabbed by the pull tool
  bool grabbing_ = false;
  float lastCursorX_ = 0.0f, lastCursorY_ = 0.0f;
  bool cameraFramed_ = false;
  bool firstFrameReported_ = false, physicsReported_ = false;
  bool sceneChanged_ = false;  ///< this frame showed something new (the window loop keeps drawing)
  double firstFrameSeconds_ = 0.0, windowReadySeconds_ = 0.0;
  double geometryArrivedSeconds_ = 0.0, geometryUploadSeconds_ = 0.0;
  SceneFrame latest_;
  render::GpuTimer sceneTimer_;
  std::chrono::steady_clock::time_point lastFrameTime_;
  std::chrono::steady_clock::time_point rateWindowStart_;
  uint64_t rateWindowVersion_ = 0;
  bool imguiReady_ = false;
};

}  // namespace sculpt::app
