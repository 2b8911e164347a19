#pragma once
// The window driven like a person would, for tests: the real SculptApp, offscreen and
// deterministic (simulation stepped once per frame), with mouse and keys fed through ImGui's IO.
// With SCULPT_SESSION_IMAGES set to a folder, frames(n, name) writes its last frame there.

#include "render/gl.h"
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <thread>

#include "sculpt/sculpt_app.h"
#include "support/gl_context.h"
#include "support/scratch_directory.h"

namespace sculpt::app {

struct Pointer {
  float x = -1e6f, y = -1e6f;  // window coordinates; far away: not over the view
  bool left = false, ctrl = false, shift = false;
  int key = -1;  // held this frame
};

class SculptSession : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_NE(std::getenv("DISPLAY"), nullptr) << "no X display: run under xvfb-run";
    ASSERT_TRUE(glfwInit());
    window_ = sculpt::testing::hiddenGlWindow(1280, 800);
    ASSERT_NE(window_, nullptr);
    if (const char* images = std::getenv("SCULPT_SESSION_IMAGES")) images_ = images;
  }
  // The application on `scene` (empty: the default bunny), as `sculpt --headless` would run it.
  void open(const std::string& scene = {}, bool headless = true) {
    Options options;
    options.headless = headless;
    options.scene = scene;
    open(options);
  }
  // The application with `options`, in the 1280 x 800 window.
  void open(Options options) {
    app_.reset();
    options.width = 1280, options.height = 800;
    app_ = std::make_unique<SculptApp>(window_, options, std::chrono::steady_clock::now(),
                                       LoadedPreferences{}, folder_ / "preferences.json");
    app_->setInputHook([this](ImGuiIO& io, int) {
      io.MousePos = ImVec2(pointer_.x, pointer_.y);
      io.MouseDown[0] = pointer_.left;
      io.KeyCtrl = pointer_.ctrl;
      io.KeyShift = pointer_.shift;
      for (bool& down : io.KeysDown) down = false;
      if (pointer_.key >= 0) io.KeysDown[pointer_.key] = true;
      for (const char c : typing_) io.AddInputCharacter(static_cast<unsigned char>(c));
      typing_.clear();
    });
  }
  void TearDown() override {
    app_.reset();
    if (window_) glfwDestroyWindow(window_);
    glfwTerminate();
  }

  void frames(int count, const std::string& screenshot = {}) {
    for (int k = 0; k < count; ++k) {
      const bool last = k + 1 == count;
      app_->headlessFrame(last && !screenshot.empty() && !images_.empty()
                              ? (std::filesystem::path(images_) / screenshot).string()
                              : std::string());
    }
  }
  // Window coordinates of a world point in the 3D view.
  ImVec2 screen(const Eigen::Vector3d& world) const {
    const ViewRect view = app_->viewRect();
    const int w = static_cast<int>(view.max.x - view.min.x),
              h = static_cast<int>(view.max.y - view.min.y);
    const glm::vec3 p = app_->camera().project(glm::vec3(world.x(), world.y(), world.z()), w, h);
    return ImVec2(view.min.x + p.x, view.min.y + p.y);
  }
  // A drag from `from` by (dx, dy) pixels over `steps` frames, holding the button at the end.
  void drag(ImVec2 from, float dx, float dy, int steps) {
    pointer_.x = from.x, pointer_.y = from.y;
    frames(1);  // hover: the depth under the cursor is read
    pointer_.left = true;
    for (int k = 1; k <= steps; ++k) {
      pointer_.x = from.x + dx * static_cast<float>(k) / static_cast<float>(steps);
      pointer_.y = from.y + dy * static_cast<float>(k) / static_cast<float>(steps);
      frames(1);
    }
  }
  void release() {
    pointer_.left = false;
    frames(1);
  }
  void press(int key, bool ctrl) {
    pointer_.key = key, pointer_.ctrl = ctrl;
    frames(1);
    pointer_.key = -1, pointer_.ctrl = false;
    frames(1);
  }
  // `text` typed in one frame, into the text field that has the keyboard.
  void type(const std::string& text) {
    typing_ = text;
    frames(1);
  }
  const SceneGeometry& geometry() const { return *app_->sceneView().geometry(); }
  // Frames 10 ms apart (for the window's worker threads) until `done` holds, at most 600.
  bool framesUntil(const std::function<bool()>& done) {
    for (int k = 0; k < 600 && !done(); ++k) {
      frames(1);
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return done();
  }
  bool framesUntilPhysics() {
    return framesUntil([this] {
      return app_->sceneView().hasGeometry() && app_->sceneView().frame().physicsReady;
    });
  }
  // The paint tool at full strength, painting Young's modulus `youngs` (Pa).
  void usePaintBrush(double youngs, float radiusPixels) {
    ToolState& tools = app_->model().tools;
    tools.tool = ToolKind::Paint;
    tools.field = PaintField::Youngs;
    tools.paint.youngs = youngs;
    tools.brush().strength = 1.0f;
    tools.brush().radiusPixels = radiusPixels;
  }
  // A finished stroke of Young's modulus 3e8 Pa across the middle of the view: one undo entry.
  void paintStrokeAcrossTheMiddle() {
    const ViewRect view = app_->viewRect();
    const ImVec2 middle(0.5f * (view.min.x + view.max.x), 0.5f * (view.min.y + view.max.y));
    usePaintBrush(3.0e8, 60.0f);
    drag(ImVec2(middle.x - 20, middle.y), 40.0f, 0.0f, 6);
    release();
  }

  GLFWwindow* window_ = nullptr;
  test::ScratchDirectory scratch_{"sculpt_session"};  // preferences, recovery and saved files
  const std::filesystem::path& folder_ = scratch_.path();
  std::string images_;
  std::unique_ptr<SculptApp> app_;
  Pointer pointer_;
  std::string typing_;  // characters for the next frame (type())
};

}  // namespace sculpt::app
