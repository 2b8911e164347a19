// SculptApp: the run modes (the interactive loop, headless frames and screenshots, the draw
// benchmark) and frame capture (screenshots at a supersampled size, with or without panels).

#include <imgui.h>
#include <imgui_impl_opengl3.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <iostream>

#include "allocator/program_allocator.h"
#include "render/image_downsample.h"
#include "render/offscreen_target.h"
#include "render/png_image.h"
#include "scene/control_export.h"
#include "sculpt/app_clock.h"
#include "sculpt/draw_benchmark.h"
#include "sculpt/sculpt_app.h"
#include "sculpt/termination_signals.h"

namespace sculpt::app {

std::string SculptApp::nextScreenshotPath() const {
  const std::time_t now = std::time(nullptr);
  char stamp[32];
  std::strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", std::localtime(&now));
  std::filesystem::path path = std::filesystem::path(model_.screenshot.folder) /
                               (std::string("sculpt-") + stamp + ".png");
  for (int k = 2; std::filesystem::exists(path); ++k)
    path = std::filesystem::path(model_.screenshot.folder) /
           (std::string("sculpt-") + stamp + "-" + std::to_string(k) + ".png");
  return path.string();
}

void SculptApp::reportFirstFrame() {
  firstFrameReported_ = true;
  firstFrameSeconds_ = secondsSince(started_);
  char text[160];
  std::snprintf(
      text, sizeof text,
      "first frame with the scene after %.2f s (window, OpenGL and UI ready after %.2f s, "
      "scene data after %.2f s, GPU upload %.2f s)",
      firstFrameSeconds_, windowReadySeconds_, geometryArrivedSeconds_ - geometryUploadSeconds_,
      geometryUploadSeconds_);
  std::cout << text << std::endl;
}

void SculptApp::writeScreenshot(const std::string& path, const ScreenshotSettings& settings) {
  int width = 0, height = 0;
  const std::vector<uint8_t> pixels = captureFrame(settings, width, height);
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  if (!parent.empty()) std::filesystem::create_directories(parent);
  render::writePng(path, width, height, pixels);
}

std::vector<uint8_t> SculptApp::captureFrame(const ScreenshotSettings& settings, int& width,
                                             int& height) {
  const int s = settings.supersample;
  const float pixelScale = ImGui::GetIO().DisplayFramebufferScale.x;
  const bool panels = settings.includePanels && !options_.noUi;
  // Without panels the image is the 3D view alone, at its framebuffer size.
  ViewRect view = lastView_;
  width = lastFbWidth_, height = lastFbHeight_;
  if (!panels) {
    width = static_cast<int>(std::lround((view.max.x - view.min.x) * pixelScale));
    height = static_cast<int>(std::lround((view.max.y - view.min.y) * pixelScale));
    view = {ImVec2(0, 0), ImVec2(view.max.x - view.min.x, view.max.y - view.min.y)};
  }
  render::OffscreenTarget target(width * s, height * s);
  target.bind();
  glViewport(0, 0, width * s, height * s);
  clearBackground(settings.transparent, stylus_.backgroundTint());
  drawScene(view, width * s, height * s, pixelScale * static_cast<float>(s));
  if (panels) {
    ImDrawData* drawData = ImGui::GetDrawData();
    const ImVec2 saved = drawData->FramebufferScale;
    drawData->FramebufferScale =
        ImVec2(saved.x * static_cast<float>(s), saved.y * static_cast<float>(s));
    glViewport(0, 0, width * s, height * s);
    ImGui_ImplOpenGL3_RenderDrawData(drawData);
    drawData->FramebufferScale = saved;
  }
  std::vector<uint8_t> pixels = target.readPixels();
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  if (s > 1) pixels = render::downsample(pixels, width * s, height * s, s);
  if (!settings.transparent)
    for (size_t i = 3; i < pixels.size(); i += 4) pixels[i] = 255;
  return pixels;
}

int SculptApp::runWindow() {
  // --quit-after counts from the first frame with the scene (or from a failed build), so that a
  // slow machine or a sanitizer build still shows the scene before closing.
  std::optional<Clock::time_point> quitClockStart;
  // Frames are drawn while something changes (a new simulation state, input, a build) and a few
  // more after it (ImGui settles hover states); otherwise the loop sleeps until an event or a
  // short timeout, so that an idle window leaves the CPU to the builder and the simulation.
  int busyFrames = 3;
  double lastDeviceTime = glfwGetTime();
  // SIGTERM, SIGINT and SIGHUP close the window through the frame loop
  // (closeOnTerminationSignal); an idle loop sees them within its wait timeout.
  installTerminationHandlers();
  struct DefaultTermination {
    ~DefaultTermination() { restoreDefaultTermination(); }
  } defaultTermination;
  while (!glfwWindowShouldClose(window_)) {
    if (options_.quitAfter > 0.0) {
      if (!quitClockStart && (firstFrameReported_ || !model_.status.build.error.empty()))
        quitClockStart = Clock::now();
      if (quitClockStart && secondsSince(*quitClockStart) > options_.quitAfter)
        glfwSetWindowShouldClose(window_, 1);
    }
    // The stylus moves and its force changes between simulation frames: keep drawing.
    if (stylus_.active()) busyFrames = std::max(busyFrames, 1);
    const double now = glfwGetTime();
    if (stylus_.driveCamera(camera_, static_cast<float>(now - lastDeviceTime), lastFbHeight_))
      busyFrames = std::max(busyFrames, 2);
    lastDeviceTime = now;
    stylus_.setFocused(glfwGetWindowAttrib(window_, GLFW_FOCUSED) != 0);
    // While a scene builds behind the one shown, frames come only from events (input, the
    // builder's progress, new states): llvmpipe draws on the CPU, and a busy loop's frames took
    // the cores from the build (the default scene simulated 0.1 s later).
    const bool building = view_.hasGeometry() && controller_->buildStatus().running;
    if (busyFrames > 0 && !building) {
      glfwPollEvents();
    } else {
      const double timeout = 0.25;
      const double before = glfwGetTime();
      glfwWaitEventsTimeout(timeout);
      if (glfwGetTime() - before < 0.9 * timeout) busyFrames = 3;  // woken by an event
    }
    int width = 0, height = 0;
    glfwGetFramebufferSize(window_, &width, &height);
    if (width <= 0 || height <= 0) {  // minimised
      glfwWaitEventsTimeout(0.1);
      continue;
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    sceneChanged_ = false;
    frame(width, height, true);
    glfwSwapBuffers(window_);
    busyFrames = sceneChanged_ || !model_.toasts.empty() ? 3 : busyFrames - 1;
  }
  reportRun();
  return terminatedBy_ != 0 ? 128 + terminatedBy_ : 0;  // as a shell reports a signal's end
}

void SculptApp::reportRun() {
  controller_->fetchNewer(latest_);
  if (!runMark_) return;
  const Pace pace = paceBetween(*runMark_, paceMark(latest_, Clock::now()));
  if (!pace.meanStepMs) return;  // another scene since, or no step
  char factor[48] = "reset meanwhile";
  if (pace.realTimeFactor)
    std::snprintf(factor, sizeof factor, "%.3fx real time", *pace.realTimeFactor);
  const int frames = frameIndex_ - runMarkFrame_;
  std::printf("simulation ran %.2f s: %llu steps, %.1f ms each on average, %s; %d frames drawn, "
              "%.1f a second\n",
              pace.wallSeconds, static_cast<unsigned long long>(pace.steps), *pace.meanStepMs,
              factor, frames, pace.wallSeconds > 0 ? frames / pace.wallSeconds : 0.0);
  std::fflush(stdout);
}

void SculptApp::headlessFrame(const std::string& screenshot) {
  int width = 0, height = 0;
  glfwGetFramebufferSize(window_, &width, &height);
  render::OffscreenTarget target(width, height);
  target.bind();
  frame(width, height, false);
  glFinish();
  if (!screenshot.empty()) screenshotLastFrame(screenshot);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void SculptApp::screenshotLastFrame(const std::string& path) {
  ScreenshotSettings settings = model_.screenshot;
  settings.includePanels = !options_.noUi;
  writeScreenshot(path, settings);
}

int SculptApp::runHeadless() {
  int width = 0, height = 0;
  glfwGetFramebufferSize(window_, &width, &height);
  render::OffscreenTarget target(width, height);
  for (int k = 0; k < options_.frames; ++k) {
    target.bind();
    frame(width, height, false);
    const BuildStatus build = controller_->buildStatus();
    if (!build.error.empty() && !view_.hasGeometry()) {
      std::cerr << "error: " << build.error << '\n';
      return 2;
    }
  }
  glFinish();
  if (!options_.out.empty()) {
    if (!view_.hasGeometry() || !view_.geometry()->controlMesh) {
      std::cerr << "error: no scene to write to " << options_.out << '\n';
      return 2;
    }
    writeDeformedControlVtk(*view_.geometry()->controlMesh, latest_.control, options_.out);
    std::cout << "wrote " << options_.out << " (" << latest_.control.rows()
              << " control points, simulated " << latest_.simulatedTime << " s)\n";
  }
  if (options_.screenshot.empty()) return 0;
  ScreenshotSettings settings = model_.screenshot;
  settings.includePanels = !options_.noUi;
  writeScreenshot(options_.screenshot, settings);
  std::cout << "wrote " << options_.screenshot << " (" << width << "x" << height << ", "
            << options_.frames << " frames, " << model_.status.triangles << " triangles, "
            << model_.status.description << ", simulated " << model_.status.simulatedTime
            << " s)\n";
  return 0;
}


int SculptApp::runBenchmark() {
  int width = 0, height = 0;
  glfwGetFramebufferSize(window_, &width, &height);
  render::OffscreenTarget target(width, height);
  std::vector<double> frameMs, stepMs, uploadMs;
  for (int k = 0; k < options_.benchFrames; ++k) {
    target.bind();
    const auto start = Clock::now();
    frame(width, height, false);
    glFinish();
    frameMs.push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
    stepMs.push_back(latest_.stepMs);
    uploadMs.push_back(view_.lastUploadMs());
    if (!view_.hasGeometry()) {
      std::cerr << "error: " << controller_->buildStatus().error << '\n';
      return 2;
    }
  }
  const auto median = [](std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v[v.size() / 2];
  };
  target.bind();
  const float aspect = viewAspect();
  const DrawMeasurement draw =
      measureDrawing(*view_.deformer(), view_.frame().nodes, view_.frame().gradients,
                     model_.display.method, view_.geometry()->triangles, camera_.view(),
                     camera_.projection(aspect), 15);
  const SceneGeometry& g = *view_.geometry();
  for (const auto& [stage, ms] : controller_->buildStatus().stageMs)
    std::cout << "stage " << stage << ": " << ms << " ms\n";
  std::cout << allocatorLine() << '\n';
  std::cout << "first_frame_s=" << firstFrameSeconds_ << " frames=" << options_.benchFrames
            << " size=" << width << "x" << height << " triangles=" << view_.numTriangles()
            << " vertices=" << g.restPositions.rows() << " nodes=" << g.cellMesh.numNodes()
            << " cells=" << g.cellMesh.numCells() << " upload_bytes=" << view_.lastUploadBytes()
            << " cpu_path_bytes=" << 24 * g.restPositions.rows()
            << " upload_ms=" << median(uploadMs) << " step_ms=" << median(stepMs)
            << " frame_ms=" << median(frameMs) << " deformed_draw_ms=" << draw.deformedMs
            << " static_draw_ms=" << draw.staticMs << " draw_ratio=" << draw.ratio() << '\n';
  return 0;
}

}  // namespace sculpt::app

