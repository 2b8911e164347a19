// The window program under a real X display (Xvfb in scripts/test.sh): it opens an OpenGL 3.3
// core context, simulates the default scene for 60 frames, renders offscreen and writes
// screenshots that show the background and the object, centred, without black (NaN) pixels; the
// panels; and the colour bar exactly when a field is shown.

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

#include "render/colour_map.h"

#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#include <stb_image.h>

namespace {

namespace fs = std::filesystem;
const std::string kSculpt = SCULPT_BINARY_DIR "/bin/sculpt";

struct Image {
  int width = 0, height = 0;
  std::vector<unsigned char> rgba;
  const unsigned char* at(int x, int y) const { return rgba.data() + 4 * (y * width + x); }
};

Image load(const fs::path& path) {
  Image image;
  int channels = 0;
  unsigned char* data = stbi_load(path.c_str(), &image.width, &image.height, &channels, 4);
  if (data) {
    image.rgba.assign(data, data + 4 * image.width * image.height);
    stbi_image_free(data);
  }
  return image;
}

bool isBackground(const unsigned char* p) {
  // glClearColor(0.16, 0.17, 0.19): (41, 43, 48) in 8 bits.
  return std::abs(p[0] - 41) <= 2 && std::abs(p[1] - 43) <= 2 && std::abs(p[2] - 48) <= 2;
}

class HeadlessWindow : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_NE(std::getenv("DISPLAY"), nullptr)
        << "no X display: run the GUI tests under xvfb-run (scripts/test.sh does)";
    dir_ = fs::temp_directory_path() / ("sculpt_gui_test_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  int run(const std::string& args) const {
    // Preferences go to the test's folder, never to the user's configuration.
    const std::string command = "XDG_CONFIG_HOME=" + dir_.string() + " " + kSculpt + " " + args +
                                " > " + (dir_ / "out.txt").string() +
                                " 2> " + (dir_ / "err.txt").string();
    const int status = std::system(command.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }
  /// stderr of the last run.
  std::string errors() const {
    std::ifstream err(dir_ / "err.txt");
    return {std::istreambuf_iterator<char>(err), std::istreambuf_iterator<char>()};
  }
  fs::path dir_;
};

struct Coverage {
  double fraction = 0, cx = 0, cy = 0;
  int black = 0;
};

/// Non-background pixels of an image: how much, where, and how many are black.
Coverage coverage(const Image& image) {
  Coverage c;
  double count = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const unsigned char* p = image.at(x, y);
      if (isBackground(p)) continue;
      ++count, c.cx += x, c.cy += y;
      if (p[0] + p[1] + p[2] < 15) ++c.black;
    }
  c.fraction = count / (image.width * image.height);
  if (count > 0) c.cx /= count, c.cy /= count;
  return c;
}

/// Pixels within `tolerance` (per channel, 8 bits) of the colour map's value at t.
int colourMapPixels(const Image& image, float t, int x0, int y0, int x1, int y1, int tolerance) {
  const glm::vec3 c = sculpt::render::colourMap(t);
  const int r = static_cast<int>(c.x * 255 + 0.5f), g = static_cast<int>(c.y * 255 + 0.5f),
            b = static_cast<int>(c.z * 255 + 0.5f);
  int count = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) {
      const unsigned char* p = image.at(x, y);
      if (std::abs(p[0] - r) <= tolerance && std::abs(p[1] - g) <= tolerance &&
          std::abs(p[2] - b) <= tolerance)
        ++count;
    }
  return count;
}

TEST_F(HeadlessWindow, DefaultSceneAfter60FramesShowsTheCentredObject) {
  const fs::path shot = dir_ / "default.png";
  ASSERT_EQ(run("--headless --no-ui --no-grid --frames 60 --size 640x400 --screenshot " +
                shot.string()),
            0);
  const Image image = load(shot);
  ASSERT_EQ(image.width, 640);
  ASSERT_EQ(image.height, 400);
  for (auto [x, y] : {std::pair{2, 2}, {637, 2}, {2, 397}, {637, 397}})
    EXPECT_TRUE(isBackground(image.at(x, y))) << x << ',' << y;
  const Coverage c = coverage(image);
  std::printf("[ measured ] object covers %.1f%% of the image, centroid (%.0f, %.0f), %d black\n",
              100 * c.fraction, c.cx, c.cy, c.black);
  // The framed bounding sphere spans 80 % of the height: a disc of 31 % of the image, of which
  // the bunny covers about a third.
  EXPECT_GT(c.fraction, 0.08);
  EXPECT_LT(c.fraction, 0.80);
  EXPECT_EQ(c.black, 0);
  EXPECT_NEAR(c.cx, image.width / 2.0, 0.12 * image.width);
  EXPECT_NEAR(c.cy, image.height / 2.0, 0.12 * image.height);
}

// The full window: panels around the 3D view, and the colour bar in the view's lower right
// corner exactly when a field is shown (its top and bottom colours are the ends of the map).
TEST_F(HeadlessWindow, PanelsAndColourBarWhenAFieldIsShown) {
  const fs::path withField = dir_ / "field.png", without = dir_ / "plain.png";
  ASSERT_EQ(run("--headless --frames 60 --field displacement --size 1280x800 --screenshot " +
                withField.string()),
            0);
  ASSERT_EQ(run("--headless --frames 60 --size 1280x800 --screenshot " + without.string()), 0);
  const Image field = load(withField), plain = load(without);
  ASSERT_EQ(field.width, 1280);
  ASSERT_EQ(plain.width, 1280);
  // The left panel (x < 170) and the right panel (x > 960) are ImGui windows, not the 3D view's
  // background colour.
  EXPECT_FALSE(isBackground(field.at(60, 400)));
  EXPECT_FALSE(isBackground(field.at(1200, 700)));
  // The legend sits in the 3D view's lower right corner: x in [820, 960), y in [450, 775).
  const int x0 = 760, x1 = 960, y0 = 420, y1 = 775;
  const int highWith = colourMapPixels(field, 1.0f, x0, y0, x1, y1, 6);
  const int lowWith = colourMapPixels(field, 0.0f, x0, y0, x1, y1, 6);
  const int highWithout = colourMapPixels(plain, 1.0f, x0, y0, x1, y1, 6);
  const int lowWithout = colourMapPixels(plain, 0.0f, x0, y0, x1, y1, 6);
  std::printf(
      "[ measured ] colour bar ends: %d high, %d low pixels with the field; %d, %d without\n",
      highWith, lowWith, highWithout, lowWithout);
  // The bar is 18 px wide; its end slices hold a few dozen pixels within 6/255 of each end colour.
  EXPECT_GE(highWith, 20);
  EXPECT_GE(lowWith, 20);
  EXPECT_EQ(highWithout, 0);
  EXPECT_EQ(lowWithout, 0);
  // The object is drawn, with the field's colours and no black pixels.
  const Coverage c = coverage(field);
  EXPECT_EQ(c.black, 0);
}

// Supersampled screenshots keep the requested size; a transparent one has alpha 0 in the corners
// and an opaque object.
TEST_F(HeadlessWindow, SupersampledTransparentScreenshot) {
  const fs::path shot = dir_ / "transparent.png";
  ASSERT_EQ(run("--headless --no-ui --no-grid --frames 2 --supersample 2 --transparent --size "
                "320x200 --screenshot " + shot.string()),
            0);
  const Image image = load(shot);
  ASSERT_EQ(image.width, 320);
  ASSERT_EQ(image.height, 200);
  EXPECT_EQ(image.at(1, 1)[3], 0);
  EXPECT_EQ(image.at(318, 198)[3], 0);
  EXPECT_EQ(image.at(160, 100)[3], 255);
}

TEST_F(HeadlessWindow, ControlMeshSceneBuildsAndSteps) {
  const fs::path shot = dir_ / "block3.png";
  ASSERT_EQ(run("--headless --no-ui --frames 5 --size 320x200 --scene " SCULPT_SOURCE_DIR
                "/assets/block3.json --screenshot " + shot.string()),
            0);
  const Coverage c = coverage(load(shot));
  EXPECT_GT(c.fraction, 0.05);
  EXPECT_EQ(c.black, 0);
}

// The interactive window with its builder and simulation threads runs (ImGui, GPU deformation,
// the worker publishing states) and closes cleanly.
TEST_F(HeadlessWindow, WindowWithSimulationWorkerRunsAndQuits) {
#ifdef SCULPT_SANITIZED
  // A step of the default scene takes about 1.8 s under AddressSanitizer and UBSan (12 ms
  // otherwise), the first after the window opens 2.3 s: open long enough to count some.
  EXPECT_EQ(run("--quit-after 8 --size 800x600"), 0);
#else
  EXPECT_EQ(run("--quit-after 1 --size 800x600"), 0);
#endif
  std::ifstream out(dir_ / "out.txt");
  const std::string text((std::istreambuf_iterator<char>(out)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("first frame with the scene after"), std::string::npos) << text;
  // At the close, how fast it ran: the steps of 1/60 s it counted are the simulated time it
  // reports, the window at least the second it was open after the first frame.
  const size_t ran = text.find("simulation ran ");
  ASSERT_NE(ran, std::string::npos) << text;
  double seconds = 0, meanMs = 0, factor = 0, frameRate = 0;
  unsigned long long steps = 0;
  int frames = 0;
  ASSERT_EQ(std::sscanf(text.c_str() + ran,
                        "simulation ran %lf s: %llu steps, %lf ms each on average, %lfx real time; "
                        "%d frames drawn, %lf a second",
                        &seconds, &steps, &meanMs, &factor, &frames, &frameRate),
            6)
      << text;
  EXPECT_GE(seconds, 1.0);
  EXPECT_GT(steps, 0u);
  EXPECT_GT(meanMs, 0.0);
  EXPECT_NEAR(factor * seconds, static_cast<double>(steps) / 60.0, 0.01) << text;
  EXPECT_GT(frames, 0);  // the simulation's states are drawn as they come
  // To the digits printed: the rate to 0.05, the seconds to 0.005.
  EXPECT_NEAR(frameRate, frames / seconds, 0.05 + 0.005 * frames / (seconds * seconds)) << text;
}

// The window remembers the user's things: after a session with a scene, the preferences file
// lists the scene among the recent ones with the window's size; a damaged file does not stop
// the window (defaults and a warning), and headless runs leave preferences alone.
TEST_F(HeadlessWindow, WindowKeepsPreferencesAndSurvivesADamagedFile) {
  const fs::path prefs = dir_ / "sculpt" / "preferences.json";
  const std::string block = SCULPT_SOURCE_DIR "/assets/block3.json";
  ASSERT_EQ(run("--headless --frames 2 --no-ui --size 320x200 --scene " + block +
                " --screenshot " + (dir_ / "h.png").string()),
            0);
  EXPECT_FALSE(fs::exists(prefs));
  ASSERT_EQ(run("--quit-after 0.5 --size 640x480 --scene " + block), 0);
  ASSERT_TRUE(fs::exists(prefs));
  std::ifstream in(prefs);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("block3.json"), std::string::npos) << text;
  EXPECT_NE(text.find("\"width\": 640"), std::string::npos) << text;
  std::ofstream(prefs) << "{\"format\": \"sculpt-preferences\", \"version\": 1, \"uiScale\": [";
  EXPECT_EQ(run("--quit-after 0.5 --size 640x480 --scene " + block), 0);
}

TEST_F(HeadlessWindow, BadInputIsExit2) {
  EXPECT_EQ(run("--frobnicate"), 2);
  EXPECT_EQ(run("--headless"), 2);  // needs --screenshot
  EXPECT_EQ(run("--quit-after -1"), 2);
  EXPECT_EQ(run("--field pressure"), 2);
  EXPECT_EQ(run("--supersample 3"), 2);
  EXPECT_EQ(run("--headless --scene /nonexistent.obj --screenshot " + (dir_ / "x.png").string()),
            2);
  EXPECT_FALSE(fs::exists(dir_ / "x.png"));
  const fs::path bad = dir_ / "bad.json";
  std::ofstream(bad) << "{\"format\": \"sculpt-control-mesh\", \"vertices\": [[0,0,";
  EXPECT_EQ(
      run("--headless --scene " + bad.string() + " --screenshot " + (dir_ / "y.png").string()), 2);
  EXPECT_NE(errors().find("bad.json"), std::string::npos) << errors();
  const fs::path script = dir_ / "script.json";
  std::ofstream(script)
      << R"({"format": "sculpt-session", "version": 1, "events": [{"t": 0, "type": "grab"}]})";
  EXPECT_EQ(run("--headless --script " + script.string() + " --screenshot " +
                (dir_ / "z.png").string()),
            2);
  EXPECT_FALSE(fs::exists(dir_ / "z.png"));
  EXPECT_NE(errors().find("script.json: events[0] (grab)"), std::string::npos) << errors();
  // A damaged project file: one sentence naming it, exit 2, no image.
  const fs::path project = dir_ / "damaged.sculpt";
  std::ofstream(project, std::ios::binary) << std::string("SCULPT\0\1\0\0\0", 11);
  EXPECT_EQ(run("--headless --scene " + project.string() + " --screenshot " +
                (dir_ / "w.png").string()),
            2);
  EXPECT_FALSE(fs::exists(dir_ / "w.png"));
  EXPECT_NE(errors().find("damaged.sculpt: the file is truncated"), std::string::npos) << errors();
}

}  // namespace
