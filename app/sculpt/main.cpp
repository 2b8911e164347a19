// sculpt: the application window (first version: views an embedded surface; the live simulation,
// panels and tools of issues 5 and 6 build on it).
//
//   sculpt [--surface FILE] [--headless] [--frames N] [--screenshot OUT.png] [--size WxH]
//
// Without --surface it shows the default model, the Stanford bunny (assets/bunny.obj) refined
// twice with Loop subdivision. --headless renders N frames (default 1) into an offscreen
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
#include <optional>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "embed/recomputed_normals.h"
#include "io/surface_file.h"
#include "render/offscreen_target.h"
#include "render/png_image.h"
#include "render/surface_renderer.h"
#include "subdiv/loop_surface.h"

namespace {

struct Options {
  std::string surface;
  bool headless = false;
  int frames = 1;
  std::string screenshot;
  int width = 1280, height = 800;
};

constexpr const char* kUsage =
    "usage: sculpt [--surface FILE.obj|.gltf|.glb] [--headless] [--frames N]\n"
    "              [--screenshot OUT.png] [--size WxH]\n";

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

/// The surface to show, triangulated, with area-weighted vertex normals, as float arrays.
struct DisplaySurface {
  std::vector<float> positions, normals;
  std::vector<uint32_t> triangles;
  glm::vec3 centre{0.0f};
  float radius = 1.0f;
};

DisplaySurface loadDisplaySurface(const Options& options) {
  sculpt::SurfaceMesh surface;
  if (options.surface.empty()) {
    const sculpt::SurfaceMesh bunny =
        sculpt::readSurfaceFile(SCULPT_SOURCE_DIR "/assets/bunny.obj").surface();
    surface = sculpt::loopRefine(bunny, 2, true);
  } else {
    surface = sculpt::readSurfaceFile(options.surface).surface();
  }
  // One normal per position, recomputed from the faces.
  surface.normals.setZero(surface.positions.rows(), 3);
  for (auto& corner : surface.faces.values) corner.normal = corner.position;
  const sculpt::Points normals = sculpt::recomputedNormals(surface, surface.positions,
                                                           sculpt::normalAnchors(surface));
  DisplaySurface display;
  const Eigen::Vector3d lo = surface.positions.colwise().minCoeff().transpose();
  const Eigen::Vector3d hi = surface.positions.colwise().maxCoeff().transpose();
  const Eigen::Vector3d centre = 0.5 * (lo + hi);
  display.centre = glm::vec3(centre.x(), centre.y(), centre.z());
  display.radius = static_cast<float>(0.5 * (hi - lo).norm());
  for (Eigen::Index v = 0; v < surface.positions.rows(); ++v)
    for (int d = 0; d < 3; ++d) {
      display.positions.push_back(static_cast<float>(surface.positions(v, d)));
      display.normals.push_back(static_cast<float>(normals(v, d)));
    }
  for (uint32_t f = 0; f < surface.numFaces(); ++f) {
    const auto corners = surface.faces.row(f);
    for (size_t k = 1; k + 1 < corners.size(); ++k)  // fan: polygons from OBJ files
      display.triangles.insert(display.triangles.end(), {corners[0].position,
                                                         corners[k].position,
                                                         corners[k + 1].position});
  }
  return display;
}

/// A turntable camera around the model: yaw and pitch in radians, distance in model radii.
struct OrbitCamera {
  float yaw = 0.5f, pitch = 0.3f, distance = 2.8f;
  glm::mat4 view(const DisplaySurface& s) const {
    const glm::vec3 direction(std::cos(pitch) * std::sin(yaw), std::sin(pitch),
                              std::cos(pitch) * std::cos(yaw));
    return glm::lookAt(s.centre + direction * distance * s.radius, s.centre,
                       glm::vec3(0.0f, 1.0f, 0.0f));
  }
  glm::mat4 projection(const DisplaySurface& s, int width, int height) const {
    return glm::perspective(glm::radians(35.0f), static_cast<float>(width) / static_cast<float>(height),
                            0.05f * s.radius, 20.0f * s.radius);
  }
};

const glm::vec3 kSurfaceColour(0.80f, 0.62f, 0.45f);

void clearBackground() {
  glClearColor(0.16f, 0.17f, 0.19f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
}

int runHeadless(GLFWwindow*, const Options& options, const DisplaySurface& surface) {
  sculpt::render::OffscreenTarget target(options.width, options.height);
  sculpt::render::SurfaceRenderer renderer;
  renderer.setTriangles(surface.triangles);
  renderer.setVertices(surface.positions, surface.normals);
  const OrbitCamera camera;
  for (int frame = 0; frame < options.frames; ++frame) {
    target.bind();
    clearBackground();
    renderer.draw(camera.view(surface), camera.projection(surface, options.width, options.height),
                  kSurfaceColour);
  }
  glFinish();
  sculpt::render::writePng(options.screenshot, options.width, options.height, target.readPixels());
  std::cout << "wrote " << options.screenshot << " (" << options.width << "x" << options.height
            << ", " << surface.triangles.size() / 3 << " triangles, " << options.frames
            << " frames)\n";
  return 0;
}

int runWindow(GLFWwindow* window, const Options& options, const DisplaySurface& surface) {
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::StyleColorsDark();
  ImGui_ImplGlfw_InitForOpenGL(window, true);
  ImGui_ImplOpenGL3_Init("#version 330 core");
  sculpt::render::SurfaceRenderer renderer;
  renderer.setTriangles(surface.triangles);
  renderer.setVertices(surface.positions, surface.normals);
  OrbitCamera camera;
  double lastX = 0, lastY = 0;
  bool dragging = false;
  auto last = std::chrono::steady_clock::now();
  double frameMs = 0.0;
  while (!glfwWindowShouldClose(window)) {
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
    ImGui::Text("frame %.2f ms   %zu triangles   left drag: orbit, wheel: zoom", frameMs,
                surface.triangles.size() / 3);
    ImGui::End();
    ImGui::Render();
    int width, height;
    glfwGetFramebufferSize(window, &width, &height);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, width, height);
    clearBackground();
    if (width > 0 && height > 0)
      renderer.draw(camera.view(surface), camera.projection(surface, width, height), kSurfaceColour);
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    glfwSwapBuffers(window);
    const auto now = std::chrono::steady_clock::now();
    frameMs = std::chrono::duration<double, std::milli>(now - last).count();
    last = now;
  }
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  (void)options;
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
    const DisplaySurface surface = loadDisplaySurface(options);
    status = options.headless ? runHeadless(window, options, surface)
                              : runWindow(window, options, surface);
  } catch (const std::exception& error) {
    std::cerr << "error: " << error.what() << '\n';
    status = 2;
  }
  glfwDestroyWindow(window);
  glfwTerminate();
  return status;
}
