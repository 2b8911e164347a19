// sculpt: the application window. See app/sculpt/options.h (or `sculpt --help`) for the command
// line and README.md for the window's panels, navigation and keys.
//
// Without --scene it shows the default scene: the Stanford bunny (assets/bunny.obj, refined three
// times with Loop subdivision) embedded in a hexahedral cage and hanging under gravity,
// Phong-deformed on the GPU. --headless renders offscreen (still through a hidden GLFW window: run
// it under xvfb-run on a machine without a display) and writes a screenshot or prints benchmark
// figures.

// GL entry points come from render/gl.h; GLFW must not include its own GL header first.
#include "render/gl.h"
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <chrono>
#include <exception>
#include <filesystem>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <utility>

#include "allocator/huge_page_heap.h"
#include "project/preferences.h"
#include "sculpt/display_loss.h"
#include "sculpt/options.h"
#include "sculpt/scene_start.h"
#include "sculpt/sculpt_app.h"

int main(int argc, char** argv) {
  // Timed from the first main(), before the heap's re-execution.
  const auto started = sculpt::app::useHugePageHeap(argv);
  sculpt::app::Options options;
  try {
    bool help = false;
    options = sculpt::app::parseOptions(argc, argv, &help);
    if (help) return 0;
  } catch (const std::exception& error) {
    std::cerr << "error: " << error.what() << '\n' << sculpt::app::kUsage;
    return 2;
  }
  // The scene builds on the other core while the window is made. Settings it refuses are
  // refused again, with the usual message, when the app loads the scene itself.
  std::unique_ptr<sculpt::SceneController> scene;
  try {
    scene = sculpt::app::startSceneBuild(options);
  } catch (const std::invalid_argument&) {
    scene.reset();
  }
  // From the display's opening on (the scene builds meanwhile); the app adds its unsaved work.
  sculpt::app::onDisplayLoss(nullptr, nullptr);
  if (!glfwInit()) {
    std::cerr << "error: cannot open a window (no display? run under xvfb-run)\n";
    return 1;
  }
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_SCALE_TO_MONITOR, GLFW_TRUE);  // HiDPI: the window grows with the scale
  if (options.headless) glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);
  // The window comes back where and as large as it was (headless runs use --size or defaults).
  const std::filesystem::path preferencesFile = sculpt::preferencesPath();
  sculpt::LoadedPreferences preferences = sculpt::loadPreferences(preferencesFile);
  const sculpt::WindowGeometry& saved = preferences.preferences.window;
  if (!options.headless && !options.sizeGiven) {
    options.width = saved.width, options.height = saved.height;
    if (saved.maximized) glfwWindowHint(GLFW_MAXIMIZED, GLFW_TRUE);
  }
  GLFWwindow* window = glfwCreateWindow(options.width, options.height, "Subdivision Sculpt",
                                        nullptr, nullptr);
  if (!window) {
    std::cerr << "error: cannot create an OpenGL 3.3 core context\n";
    glfwTerminate();
    return 1;
  }
  if (!options.headless && !options.sizeGiven && saved.x >= 0 && saved.y >= 0)
    glfwSetWindowPos(window, saved.x, saved.y);
  glfwMakeContextCurrent(window);
  glfwSwapInterval(1);
  int status = 0;
  try {
    sculpt::app::SculptApp app(window, options, started, std::move(preferences), preferencesFile,
                               std::move(scene));
    status = options.benchFrames > 0      ? app.runBenchmark()
             : options.recordSeconds > 0.0 ? app.runRecording()
             : options.headless            ? app.runHeadless()
                                           : app.runWindow();
  } catch (const std::exception& error) {
    std::cerr << "error: " << error.what() << '\n';
    status = 2;
  }
  glfwDestroyWindow(window);
  glfwTerminate();
  return status;
}
