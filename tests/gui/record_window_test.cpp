// Recording in the window: Record, the timeline's playhead (the view shows the take's frame, not
// the simulation's) and the export dialog's worker, cancelled once and then run to the end while
// the window keeps drawing at its usual pace. The screenshot goes to $SCULPT_SESSION_IMAGES.

#include "render/gl.h"

#include <GLFW/glfw3.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <filesystem>
#include <string>
#include <vector>

#include "sculpt/sculpt_app.h"
#include "support/gl_context.h"
#include "support/scratch_directory.h"

namespace sculpt::app {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

struct FrameTimes {
  std::vector<double> ms;
  double median() const {
    std::vector<double> sorted = ms;
    std::sort(sorted.begin(), sorted.end());
    return sorted.empty() ? 0.0 : sorted[sorted.size() / 2];
  }
  double max() const { return ms.empty() ? 0.0 : *std::max_element(ms.begin(), ms.end()); }
  size_t argmax() const {
    return static_cast<size_t>(std::max_element(ms.begin(), ms.end()) - ms.begin());
  }
};

double timedFrame(SculptApp& app) {
  const auto start = Clock::now();
  app.headlessFrame();
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

bool hasToast(const AppModel& model, const std::string& part) {
  return std::any_of(model.toasts.begin(), model.toasts.end(),
                     [&](const Toast& t) { return t.text.find(part) != std::string::npos; });
}

std::vector<std::string> filesIn(const fs::path& folder) {
  std::vector<std::string> names;
  for (const fs::directory_entry& entry : fs::directory_iterator(folder))
    names.push_back(entry.path().filename().string());
  return names;
}

TEST(RecordWindow, RecordsScrubsAndExportsWithoutStallingTheWindow) {
  ASSERT_NE(std::getenv("DISPLAY"), nullptr) << "no X display: run under xvfb-run";
  ASSERT_TRUE(glfwInit());
  GLFWwindow* window = sculpt::testing::hiddenGlWindow(1280, 800);
  ASSERT_NE(window, nullptr);
  test::ScratchDirectory scratch("record_window");
  {
    Options options;
    options.headless = false;  // the simulation on its own thread, as in the window
    options.width = 1280, options.height = 800;
    options.cage = 4;  // a coarser cage: quicker steps and exports
    SculptApp app(window, options, Clock::now(), LoadedPreferences{},
                  scratch.path() / "preferences.json");
    for (int k = 0;
         k < 400 && !(app.sceneView().hasGeometry() && app.sceneView().frame().physicsReady); ++k)
      app.headlessFrame();
    ASSERT_TRUE(app.sceneView().frame().physicsReady);

    // Record (the bottom strip's button) 2 s of simulated time at the default 30 fps, then Stop.
    app.model().requests.record.toggleRecord = true;
    app.headlessFrame();
    ASSERT_TRUE(app.recording().recording());
    EXPECT_TRUE(app.model().record.recording) << "the strip shows the red dot";
    for (int k = 0; k < 3000 && app.recording().frameCount() < 61; ++k) app.headlessFrame();
    app.model().requests.record.toggleRecord = true;
    app.headlessFrame();
    ASSERT_FALSE(app.recording().recording());
    const std::shared_ptr<const Take> take = app.recording().take();
    ASSERT_NE(take, nullptr);
    ASSERT_GE(take->frameCount(), 60u);
    EXPECT_DOUBLE_EQ(take->fps(), 30.0);
    EXPECT_TRUE(app.recording().isLive());
    std::printf("[ measured ] take: %u frames, %.2f s, %zu bytes\n", take->frameCount(),
                take->duration(), take->memoryBytes());

    // Scrub back to frame 10 (what the timeline's slider asks for): the view shows that frame.
    app.model().requests.record.playhead = 10u;
    app.headlessFrame();
    EXPECT_FALSE(app.recording().isLive());
    EXPECT_EQ(app.recording().playhead(), 10u);
    Points expected;
    take->controlPoints(10, expected);
    const Points& shown = app.sceneView().frame().control;
    ASSERT_EQ(shown.rows(), expected.rows());
    EXPECT_EQ((shown - expected).cwiseAbs().maxCoeff(), 0.0) << "the take's frame 10, exactly";
    app.headlessFrame();
    EXPECT_FALSE(app.model().status.playing) << "reviewing pauses the simulation";

    // The export dialog, as File > Export recording... opens it.
    const fs::path folder = scratch.path() / "exports";
    fs::create_directories(folder);
    ExportDialog& dialog = app.model().exportDialog;
    dialog.show = true;
    app.headlessFrame();
    EXPECT_NE(std::string(dialog.path.data()).find("bunny_take.glb"), std::string::npos)
        << dialog.path.data();
    const std::string glb = (folder / "take.glb").string();
    std::snprintf(dialog.path.data(), dialog.path.size(), "%s", glb.c_str());
    app.headlessFrame();
    EXPECT_EQ(dialog.problem, "");
    EXPECT_GT(dialog.estimateBytes, 0u);
    EXPECT_EQ(dialog.first, 1);
    EXPECT_EQ(dialog.last, static_cast<int>(take->frameCount()));

    // The same view without an export: llvmpipe's own frame-to-frame spread on this machine.
    FrameTimes idle;
    for (int k = 0; k < 60; ++k) idle.ms.push_back(timedFrame(app));
    std::printf("[ measured ] no export: %zu frames, median %.1f ms, max %.1f ms\n", idle.ms.size(),
                idle.median(), idle.max());

    // Once cancelled after its first progress: nothing under the name, no temporary file.
    ASSERT_TRUE(app.startExport());
    EXPECT_FALSE(app.startExport()) << "a second export is refused while one runs";
    FrameTimes cancelled;
    bool cancelAsked = false;
    for (int k = 0; k < 2000 && app.exportJob().busy(); ++k) {
      cancelled.ms.push_back(timedFrame(app));
      if (!cancelAsked && app.exportJob().fraction() > 0.0) {
        app.model().requests.record.cancelExport = true;  // the dialog's Cancel
        cancelAsked = true;
      }
    }
    ASSERT_FALSE(app.exportJob().busy());
    ASSERT_TRUE(app.lastExport().has_value());
    EXPECT_EQ(app.lastExport()->kind, ExportJob::Outcome::Kind::Cancelled)
        << app.lastExport()->error;
    EXPECT_FALSE(fs::exists(glb));
    EXPECT_TRUE(filesIn(folder).empty()) << "left behind: " << filesIn(folder).front();
    EXPECT_TRUE(hasToast(app.model(), "Export cancelled; nothing was written"));

    // Then to the end.
    ASSERT_TRUE(app.startExport());
    FrameTimes written;
    for (int k = 0; k < 20000 && app.exportJob().busy(); ++k) written.ms.push_back(timedFrame(app));
    ASSERT_FALSE(app.exportJob().busy());
    ASSERT_TRUE(app.lastExport().has_value());
    const ExportJob::Outcome& outcome = *app.lastExport();
    ASSERT_EQ(outcome.kind, ExportJob::Outcome::Kind::Written) << outcome.error;
    ASSERT_TRUE(fs::exists(glb));
    EXPECT_GT(fs::file_size(glb), 0u);
    EXPECT_GE(outcome.result.keys, 2u);
    EXPECT_EQ(outcome.result.frames, take->frameCount());
    EXPECT_TRUE(hasToast(app.model(), "wrote " + glb));
    EXPECT_EQ(filesIn(folder).size(), 1u);

    // No frame over three times the median of its export, nor over half again the slowest
    // frame without an export: the worker runs below the window's priority, on its own thread,
    // and never holds what the frame needs, so a frame that waited for it would wait for all of
    // its writing (over a second; 13x the median when the window waited for the second half).
    // What the bound leaves room for is the cost of sharing two cores with the export's writing:
    // up to 2.2x a 25-29 ms median in the export's first frames, on the programs' heap as here
    // (glibc's heap as it comes added page faults on the UI thread: 1,000-2,000 in some frames,
    // 12-21 ms of kernel time); under AddressSanitizer 2.4x, and the idle frames 1.8x their
    // median. (ctest runs this test with nothing beside it: another process on the second core
    // would be measured too.)
    for (const auto& [name, times] :
         {std::pair{"cancelled export", &cancelled}, std::pair{"export", &written}}) {
      const double median = times->median();
      size_t over = 0;
      std::string all;
      for (const double ms : times->ms) {
        over += ms > 3.0 * median;
        all += std::to_string(static_cast<int>(ms)) + " ";
      }
      std::printf("[ measured ] %s: %zu frames, median %.1f ms, max %.1f ms (%.2fx, frame %zu), "
                  "%zu over 3x (idle: median %.1f ms, max %.1f ms)\n[ measured ] %s\n",
                  name, times->ms.size(), median, times->max(), times->max() / median,
                  times->argmax(), over, idle.median(), idle.max(), all.c_str());
      EXPECT_LE(times->max(), std::max(3.0 * median, 1.5 * idle.max())) << name << ": " << all;
    }
    EXPECT_GE(written.ms.size(), 3u) << "the export ran over several frames";

    // Every other frame of the take, as a point cache: half the frames, the same file layout.
    dialog.every = 2;
    const std::string pc2 = (folder / "half.pc2").string();
    std::snprintf(dialog.path.data(), dialog.path.size(), "%s", pc2.c_str());
    app.headlessFrame();
    ASSERT_TRUE(app.startExport());
    for (int k = 0; k < 20000 && app.exportJob().busy(); ++k) app.headlessFrame();
    ASSERT_TRUE(app.lastExport().has_value());
    ASSERT_EQ(app.lastExport()->kind, ExportJob::Outcome::Kind::Written) << app.lastExport()->error;
    const uint32_t half = (take->frameCount() - 1) / 2 + 1;
    EXPECT_EQ(app.lastExport()->result.frames, half);
    std::ifstream cache(pc2, std::ios::binary);
    char header[32];
    ASSERT_TRUE(cache.read(header, sizeof header));
    int32_t points = 0, samples = 0;
    std::memcpy(&points, header + 16, 4);
    std::memcpy(&samples, header + 28, 4);
    EXPECT_EQ(static_cast<uint32_t>(samples), half);
    EXPECT_EQ(fs::file_size(pc2), 32u + 12u * static_cast<uint64_t>(points) * half);

    // The view's frames as PNG files (every 20th: 4 frames) and as an H.264 video (every 10th),
    // rendered one per window frame; a PNG export cancelled after two frames leaves none.
    const fs::path rendered = folder / "rendered";
    fs::create_directories(rendered);
    const auto exportTo = [&](const fs::path& path, int every, int maxFrames) {
      dialog.every = every;
      dialog.format = 0;  // the name decides the format
      std::snprintf(dialog.path.data(), dialog.path.size(), "%s", path.c_str());
      app.headlessFrame();
      if (!app.startExport()) return false;
      for (int k = 0; k < maxFrames && app.exporting(); ++k) app.headlessFrame();
      return true;
    };
    ASSERT_TRUE(exportTo(rendered / "cancel_####.png", 20, 2));
    EXPECT_TRUE(app.exporting());
    EXPECT_TRUE(dialog.rendering);
    app.model().requests.record.cancelExport = true;
    app.headlessFrame();
    EXPECT_FALSE(app.exporting());
    EXPECT_EQ(app.lastExport()->kind, ExportJob::Outcome::Kind::Cancelled);
    EXPECT_TRUE(filesIn(rendered).empty()) << "left behind: " << filesIn(rendered).front();
    ASSERT_TRUE(exportTo(rendered / "view_####.png", 20, 100));
    ASSERT_EQ(app.lastExport()->kind, ExportJob::Outcome::Kind::Written) << app.lastExport()->error;
    const uint32_t pngFrames = (take->frameCount() - 1) / 20 + 1;
    EXPECT_EQ(app.lastExport()->result.frames, pngFrames);
    EXPECT_EQ(filesIn(rendered).size(), pngFrames);
    for (uint32_t f = 1; f <= pngFrames; ++f) {
      char name[32];
      std::snprintf(name, sizeof name, "view_%04u.png", f);
      EXPECT_GT(fs::file_size(rendered / name), 1000u) << name;
    }
    if (const char* images = std::getenv("SCULPT_SESSION_IMAGES"))
      fs::copy_file(rendered / "view_0002.png", fs::path(images) / "record-view-frame-21.png",
                    fs::copy_options::overwrite_existing);
    const ViewRect view = app.viewRect();
    ASSERT_TRUE(exportTo(rendered / "view.mp4", 10, 100));
    ASSERT_EQ(app.lastExport()->kind, ExportJob::Outcome::Kind::Written) << app.lastExport()->error;
    const std::string probe =
        "ffprobe -v error -select_streams v:0 -count_frames -show_entries "
        "stream=codec_name,width,height,pix_fmt,nb_read_frames -of csv=p=0 " +
        (rendered / "view.mp4").string() + " > " + (rendered / "probe.txt").string();
    ASSERT_EQ(std::system(probe.c_str()), 0)
        << "ffprobe is missing: scripts/install-deps.sh installs ffmpeg";
    std::ifstream probed(rendered / "probe.txt");
    std::string streams;
    std::getline(probed, streams);
    const int w = static_cast<int>(view.max.x - view.min.x) & ~1,
              h = static_cast<int>(view.max.y - view.min.y) & ~1;
    EXPECT_EQ(streams, "h264," + std::to_string(w) + "," + std::to_string(h) + ",yuv420p," +
                           std::to_string((take->frameCount() - 1) / 10 + 1));
    std::printf("[ measured ] rendered: %u PNG frames, video %s\n", pngFrames, streams.c_str());
    EXPECT_FALSE(app.recording().isLive());
    dialog.every = 1;
    dialog.format = 0;
    std::snprintf(dialog.path.data(), dialog.path.size(), "%s", glb.c_str());

    // The window with the timeline at frame 10, the dialog and the toast.
    const char* images = std::getenv("SCULPT_SESSION_IMAGES");
    const fs::path shot = (images ? fs::path(images) : scratch.path()) / "record-timeline.png";
    app.headlessFrame();
    app.headlessFrame(shot.string());
    std::printf("[ image ] %s\n", shot.c_str());
    EXPECT_TRUE(fs::exists(shot));

    // Live again: the simulation resumes.
    app.model().requests.record.goLive = true;
    app.headlessFrame();
    app.headlessFrame();
    EXPECT_TRUE(app.recording().isLive());
    EXPECT_TRUE(app.model().status.playing);
  }
  glfwDestroyWindow(window);
  glfwTerminate();
}

}  // namespace
}  // namespace sculpt::app
