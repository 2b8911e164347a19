// sculpt: the application window (first version: views an embedded surface; the live simulation,
// panels and tools of issues 5 and 6 build on it).
//
//   sculpt [--surface FILE] [--headless] [--frames N] [--screenshot OUT.png] [--size WxH]
//
// Without --surface it shows the default scene: the Stanford bunny (assets/bunny.obj, refined
// twice with Loop subdivision) embedded in a hexahedral cage simulated under gravity, deformed on
// the GPU with Phong deformation. With --surface it shows that surface as it is. --headless renders N frames (default 1) into an offscreen
// framebuffer of a hidden window and writes the screenshot; it still needs an X display (run it
// under xvfb-run on a machine without one).

// GL entry points come from render/gl.h; GLFW must not include its own GL header first.
#include "render/gl.h"
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "embed/recomputed_normals.h"
#include "io/surface_file.h"
#include "render/offscreen_target.h"
#include "render/png_image.h"
#include "render/phong_gpu_deformer.h"
#include "render/surface_renderer.h"
#include "sculpt/live_scene.h"
#include "sculpt/simulation_worker.h"

namespace {

struct Options {
  std::string surface;
  bool headless = false;
  int frames = 1;
  std::string screenshot;
  int width = 1280, height = 800;
  double quitAfter = 0.0;  ///< window mode: close after this many seconds (smoke tests)
};

constexpr const char* kUsage =
    "usage: sculpt [--surface FILE.obj|.gltf|.glb] [--headless] [--frames N]\n"
    "              [--screenshot OUT.png] [--size WxH] [--quit-after SECONDS]\n";

Options parseOptions(int argc, char** argv) {
  Options options;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw std::invalid_argument(arg + " needs a value");
      return argv[++i];
    };
    if (arg == "--surface") {
      options.surface = value();
    } else if (arg == "--headless") {
      options.headless = true;
    } else if (arg == "--frames") {
      options.frames = std::stoi(value());
      if (options.frames < 1 || options.frames > 100000)
        throw std::invalid_argument("--frames must be in 1..100000");
    } else if (arg == "--screenshot") {
      options.screenshot = value();
    } else if (arg == "--size") {
      const std::string size = value();
      if (std::sscanf(size.c_str(), "%dx%d", &options.width, &options.height) != 2 ||
          options.width < 64 || options.height < 64 || options.width > 8192 ||
          options.height > 8192)
        throw std::invalid_argument("--size must be WxH between 64 and 8192");
    } else if (arg == "--quit-after") {
      options.quitAfter = std::stod(value());
      if (!(options.quitAfter > 0.0 && options.quitAfter < 1e6))
        throw std::invalid_argument("--quit-after must be a positive number of seconds");
    } else if (arg == "--help" || arg == "-h") {
      std::cout << kUsage;
      std::exit(0);
    } else {
      throw std::invalid_argument("unknown option '" + arg + "'");
    }
  }
  if (options.headless && options.screenshot.empty())
    throw std::invalid_argument("--headless needs --screenshot OUT.png");
  return options;
}

/// What the window shows: something to advance each frame and to draw.
class View {
 public:
  virtual ~View() = default;
  virtual void advance() {}
  virtual void draw(const glm::mat4& view, const glm::mat4& projection) const = 0;
  virtual std::string status() const = 0;
  glm::vec3 centre{0.0f};
  float radius = 1.0f;
};

const glm::vec3 kSurfaceColour(0.80f, 0.62f, 0.45f);

void frameBounds(View& view, const sculpt::Points& positions) {
  const Eigen::Vector3d lo = positions.colwise().minCoeff().transpose();
  const Eigen::Vector3d hi = positions.colwise().maxCoeff().transpose();
  const Eigen::Vector3d centre = 0.5 * (lo + hi);
  view.centre = glm::vec3(centre.x(), centre.y(), centre.z());
  view.radius = static_cast<float>(0.5 * (hi - lo).norm());
}

std::vector<float> floats(const sculpt::Points& points) {
  std::vector<float> out;
  out.reserve(static_cast<size_t>(points.size()));
  for (Eigen::Index r = 0; r < points.rows(); ++r)
    for (int d = 0; d < 3; ++d) out.push_back(static_cast<float>(points(r, d)));
  return out;
}

/// A surface file shown as it is (no simulation).
class StaticSurfaceView : public View {
 public:
  explicit StaticSurfaceView(const std::string& path) {
    const sculpt::SurfaceMesh surface = sculpt::readSurfaceFile(path).surface();
    const sculpt::Points normals = sculpt::vertexNormals(surface);
    std::vector<uint32_t> triangles;
    for (uint32_t f = 0; f < surface.numFaces(); ++f) {
      const auto corners = surface.faces.row(f);
      for (size_t k = 1; k + 1 < corners.size(); ++k)  // fan: polygons from OBJ files
        triangles.insert(triangles.end(),
                         {corners[0].position, corners[k].position, corners[k + 1].position});
    }
    triangleCount_ = triangles.size() / 3;
    renderer_.setTriangles(triangles);
    renderer_.setVertices(floats(surface.positions), floats(normals));
    frameBounds(*this, surface.positions);
  }
  void draw(const glm::mat4& view, const glm::mat4& projection) const override {
    renderer_.draw(view, projection, kSurfaceColour);
  }
  std::string status() const override {
    return std::to_string(triangleCount_) + " triangles (static)";
  }

 private:
  sculpt::render::SurfaceRenderer renderer_;
  size_t triangleCount_ = 0;
};

/// The default scene: the bunny embedded in a simulated solid, Phong-deformed on the GPU.
class LiveSceneView : public View {
 public:
  /// `threaded`: the simulation runs on a worker thread (the window); otherwise each frame steps
  /// once on the calling thread (headless screenshots, reproducible).
  explicit LiveSceneView(bool threaded)
      : scene_(sculpt::app::LiveScene::buildDefault(SCULPT_SOURCE_DIR)) {
    std::vector<float> local;
    for (uint32_t p = 0; p < scene_->embedding().numPoints(); ++p)
      for (int d = 0; d < 3; ++d) local.push_back(static_cast<float>(scene_->embedding().local(p, d)));
    deformer_ = std::make_unique<sculpt::render::PhongGpuDeformer>(
        scene_->cellMesh(), scene_->embedding().cells, local, floats(scene_->restNormals()));
    deformer_->setTriangles(scene_->triangles());
    deformer_->setFrame(scene_->nodes(), scene_->nodeGradients(), 0.5f);
    frameBounds(*this, scene_->restPositions());
    if (threaded) worker_ = std::make_unique<sculpt::app::SimulationWorker>(*scene_);
  }
  ~LiveSceneView() override { worker_.reset(); }  // stop the worker before the scene goes
  void advance() override {
    if (worker_) {
      if (worker_->fetchNewer(latest_))
        deformer_->setFrame(latest_.nodes, latest_.gradients, 0.5f);
      return;
    }
    scene_->step();
    latest_.stepMs = scene_->lastStepMs();
    deformer_->setFrame(scene_->nodes(), scene_->nodeGradients(), 0.5f);
  }
  void draw(const glm::mat4& view, const glm::mat4& projection) const override {
    deformer_->draw(view, projection, kSurfaceColour);
  }
  std::string status() const override {
    char text[160];
    std::snprintf(text, sizeof text, "%zu triangles, %u elements, simulation %.1f ms/step",
                  scene_->triangles().size() / 3, scene_->numElements(), latest_.stepMs);
    return text;
  }

 private:
  std::unique_ptr<sculpt::app::LiveScene> scene_;
  std::unique_ptr<sculpt::render::PhongGpuDeformer> deformer_;
  std::unique_ptr<sculpt::app::SimulationWorker> worker_;
  sculpt::app::PublishedState latest_;
};

std::unique_ptr<View> makeView(const Options& options) {
  if (options.surface.empty()) return std::make_unique<LiveSceneView>(!options.headless);
  return std::make_unique<StaticSurfaceView>(options.surface);
}

/// A turntable camera around the model: yaw and pitch in radians, distance in model radii.
struct OrbitCamera {
  float yaw = 0.5f, pitch = 0.3f, distance = 2.8f;
  glm::mat4 view(const View& s) const {
    const glm::vec3 direction(std::cos(pitch) * std::sin(yaw), std::sin(pitch),
                              std::cos(pitch) * std::cos(yaw));
    return glm::lookAt(s.centre + direction * distance * s.radius, s.centre,
                       glm::vec3(0.0f, 1.0f, 0.0f));
  }
  glm::mat4 projection(const View& s, int width, int height) const {
    return glm::perspective(glm::radians(35.0f), static_cast<float>(width) / static_cast<float>(height),
                            0.05f * s.radius, 20.0f * s.radius);
  }
};

void clearBackground() {
  glClearColor(0.16f, 0.17f, 0.19f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
}

int runHeadless(GLFWwindow*, const Options& options, View& view) {
  sculpt::render::OffscreenTarget target(options.width, options.height);
  const OrbitCamera camera;
  for (int frame = 0; frame < options.frames; ++frame) {
    view.advance();
    target.bind();
    clearBackground();
    view.draw(camera.view(view), camera.projection(view, options.width, options.height));
  }
  glFinish();
  sculpt::render::writePng(options.screenshot, options.width, options.height, target.readPixels());
  std::cout << "wrote " << options.screenshot << " (" << options.width << "x" << options.height
            << ", " << options.frames << " frames; " << view.status() << ")\n";
  return 0;
}

int runWindow(GLFWwindow* window, const Options& options, View& view) {
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::StyleColorsDark();
  ImGui_ImplGlfw_InitForOpenGL(window, true);
  ImGui_ImplOpenGL3_Init("#version 330 core");
  OrbitCamera camera;
  double lastX = 0, lastY = 0;
  bool dragging = false;
  auto last = std::chrono::steady_clock::now();
  const auto started = last;
  double frameMs = 0.0;
  while (!glfwWindowShouldClose(window)) {
    if (options.quitAfter > 0.0 &&
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count() >
            options.quitAfter)
      glfwSetWindowShouldClose(window, 1);
    glfwPollEvents();
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    const ImGuiIO& io = ImGui::GetIO();
    // Orbit with the left button, zoom with the wheel, unless ImGui wants the mouse.
    double x, y;
    glfwGetCursorPos(window, &x, &y);
    const bool pressed = glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
    if (!io.WantCaptureMouse) {
      if (pressed && dragging) {
        camera.yaw -= 0.01f * static_cast<float>(x - lastX);
        camera.pitch = glm::clamp(camera.pitch + 0.01f * static_cast<float>(y - lastY), -1.5f, 1.5f);
      }
      camera.distance = glm::clamp(camera.distance * std::pow(0.9f, io.MouseWheel), 0.3f, 50.0f);
    }
    dragging = pressed && !io.WantCaptureMouse;
    lastX = x, lastY = y;
    if (ImGui::BeginMainMenuBar()) {
      if (ImGui::BeginMenu("File")) {
        if (ImGui::MenuItem("Quit", "Ctrl+Q")) glfwSetWindowShouldClose(window, 1);
        ImGui::EndMenu();
      }
      if (ImGui::BeginMenu("View")) {
        if (ImGui::MenuItem("Reset view", "Home")) camera = OrbitCamera{};
        ImGui::EndMenu();
      }
      ImGui::EndMainMenuBar();
    }
    ImGui::SetNextWindowPos(ImVec2(0, io.DisplaySize.y - 28));
    ImGui::SetNextWindowSize(ImVec2(io.DisplaySize.x, 28));
    ImGui::Begin("status", nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                     ImGuiWindowFlags_NoSavedSettings);
    ImGui::Text("frame %.2f ms   %s   left drag: orbit, wheel: zoom", frameMs,
                view.status().c_str());
    ImGui::End();
    ImGui::Render();
    int width, height;
    glfwGetFramebufferSize(window, &width, &height);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, width, height);
    clearBackground();
    view.advance();
    if (width > 0 && height > 0)
      view.draw(camera.view(view), camera.projection(view, width, height));
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    glfwSwapBuffers(window);
    const auto now = std::chrono::steady_clock::now();
    frameMs = std::chrono::duration<double, std::milli>(now - last).count();
    last = now;
  }
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  try {
    options = parseOptions(argc, argv);
  } catch (const std::exception& error) {
    std::cerr << "error: " << error.what() << '\n' << kUsage;
    return 2;
  }
  if (!glfwInit()) {
    std::cerr << "error: cannot open a window (no display? run under xvfb-run)\n";
    return 1;
  }
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  if (options.headless) glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);
  GLFWwindow* window = glfwCreateWindow(options.width, options.height, "Subdivision Sculpt",
                                        nullptr, nullptr);
  if (!window) {
    std::cerr << "error: cannot create an OpenGL 3.3 core context\n";
    glfwTerminate();
    return 1;
  }
  glfwMakeContextCurrent(window);
  glfwSwapInterval(1);
  int status = 0;
  try {
    const std::unique_ptr<View> view = makeView(options);
    status = options.headless ? runHeadless(window, options, *view) : runWindow(window, options, *view);
  } catch (const std::exception& error) {
    std::cerr << "error: " << error.what() << '\n';
    status = 2;
  }
  glfwDestroyWindow(window);
  glfwTerminate();
  return status;
}
