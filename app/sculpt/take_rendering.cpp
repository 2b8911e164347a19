// SculptApp::runRecording: sculpt --headless --record-seconds T --record-out OUT... records the
// scene (after --script starts) by stepping the non-threaded loop, then writes every output:
// geometry formats through anim/take_export.h, and name_####.png / name.mp4 by playing each
// frame back and rendering it offscreen as the headless screenshot does.

#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "anim/take_export.h"
#include "anim/take_surface.h"
#include "io/file_error.h"
#include "render/offscreen_target.h"
#include "render/png_image.h"
#include "sculpt/sculpt_app.h"
#include "sculpt/rendered_frames.h"
#include "util/shell_command.h"

namespace sculpt::app {

namespace {

struct Output {
  std::filesystem::path path;
  ExportFormat format = ExportFormat::Glb;
};

// Progress on stderr: a line per tenth.
class StderrProgress {
 public:
  explicit StderrProgress(std::string what) : what_(std::move(what)) {}
  bool operator()(double fraction, std::string_view) {
    const int tenth = static_cast<int>(std::floor(fraction * 10.0));
    if (tenth > shown_) {
      shown_ = tenth;
      std::fprintf(stderr, "%s: %d%%\n", what_.c_str(), 10 * tenth);
    }
    return true;
  }

 private:
  std::string what_;
  int shown_ = -1;
};

}  // namespace

int SculptApp::runRecording() {
  std::vector<Output> outputs;
  std::vector<std::filesystem::path> pngs, videos;
  for (const std::string& out : options_.recordOut) {
    const ExportTarget target = exportTargetFor(out);
    if (!target.format) {
      std::cerr << "error: " << target.problem << '\n';
      return 2;
    }
    if (*target.format == ExportFormat::Mp4 && !programOnPath("ffmpeg")) {
      std::cerr
          << "error: " << out
          << ": writing .mp4 needs the ffmpeg program (scripts/install-deps.sh installs it)\n";
      return 2;
    }
    if (*target.format == ExportFormat::PngSequence) pngs.push_back(out);
    if (*target.format == ExportFormat::Mp4) videos.push_back(out);
    outputs.push_back({out, *target.format});
  }
  const double fps = options_.recordFps;
  const uint32_t wanted = static_cast<uint32_t>(std::lround(options_.recordSeconds * fps)) + 1;

  // Build, start the script and record by stepping (headless: the loop is not threaded).
  int width = 0, height = 0;
  glfwGetFramebufferSize(window_, &width, &height);
  render::OffscreenTarget target(width, height);
  target.bind();
  recording_->setFps(fps);
  recording_->start(controller_->loop());
  // A script with topology events plays on the scene they make: the take starts with it.
  bool scriptPending = scriptTopology_ || deferredScript_ || awaitingEditedScene_;
  int shownTenth = -1;
  for (uint64_t iteration = 0; recording_->frameCount() < wanted; ++iteration) {
    syncScene();
    const BuildStatus build = controller_->buildStatus();
    if (!build.error.empty()) {
      std::cerr << "error: " << build.error << '\n';
      return 2;
    }
    if (scriptPending && !(scriptTopology_ || deferredScript_ || awaitingEditedScene_)) {
      scriptPending = false;
      recording_->start(controller_->loop());
    }
    const int tenth = static_cast<int>(10 * recording_->frameCount() / wanted);
    if (tenth > shownTenth) {
      shownTenth = tenth;
      std::fprintf(stderr, "recording: %u of %u frames\n", recording_->frameCount(), wanted);
    }
    if (iteration > 100 * static_cast<uint64_t>(wanted) + 100000) {
      std::cerr << "error: the simulation did not advance (recorded " << recording_->frameCount()
                << " of " << wanted << " frames)\n";
      return 2;
    }
  }
  recording_->stop();
  const std::shared_ptr<const Take> take = recording_->take();
  const FrameRange range{0, wanted};
  const TakeSurface surface(take, range);
  uint64_t bytes = 0, keys = 0;
  try {
    for (const Output& output : outputs) {
      if (isRenderedFormat(output.format)) continue;
      std::fprintf(stderr, "writing %s (%s)\n", output.path.c_str(),
                   exportFormatName(output.format));
      ProgressReporter progress(StderrProgress(output.path.string()));
      const ExportResult result =
          exportAnimation(surface, output.path, output.format, TakeExportOptions{}, &progress);
      bytes += result.bytes;
      keys += result.keys;
    }
    if (!pngs.empty() || !videos.empty()) bytes += renderTake(pngs, videos, wanted);
  } catch (const std::exception& error) {
    std::cerr << "error: " << error.what() << '\n';
    return 2;
  }
  std::cout << "frames=" << wanted << " seconds=" << (wanted - 1) / fps
            << " vertices=" << surface.maxVertices() << " keys=" << keys << " bytes=" << bytes
            << std::endl;
  return 0;
}

uint64_t SculptApp::renderTake(const std::vector<std::filesystem::path>& pngs,
                               const std::vector<std::filesystem::path>& videos, uint32_t frames) {
  int width = 0, height = 0;
  glfwGetFramebufferSize(window_, &width, &height);
  render::OffscreenTarget target(width, height);
  ScreenshotSettings settings = model_.screenshot;
  settings.includePanels = !options_.noUi;
  RenderedFrames out(pngs, videos, recording_->take()->fps());  // removed unless finished
  int shownTenth = -1;
  leaveLive();  // the simulation pauses; the view shows the take's frames
  for (uint32_t k = 0; k < frames; ++k) {
    recording_->setPlayhead(k);
    // The first frame twice more: windows that size themselves appear one frame late.
    for (int pass = 0; pass < (k == 0 ? 3 : 1); ++pass) {
      target.bind();
      frame(width, height, false);
    }
    glFinish();
    int w = 0, h = 0;
    const std::vector<uint8_t> pixels = captureFrame(settings, w, h);
    out.write(k + 1, pixels, w, h);
    const int tenth = static_cast<int>(10 * (k + 1) / frames);
    if (tenth > shownTenth) {
      shownTenth = tenth;
      std::fprintf(stderr, "rendering: %u of %u frames\n", k + 1, frames);
    }
  }
  return out.finish();
}

}  // namespace sculpt::app
