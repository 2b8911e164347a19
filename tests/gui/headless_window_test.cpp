// The window program under a real X display (Xvfb in scripts/test.sh): it opens an OpenGL 3.3
// core context, renders the default scene offscreen and writes a screenshot that shows the
// background and the object, centred, without black (NaN) pixels.

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <unistd.h>

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
    const std::string command = kSculpt + " " + args + " > " + (dir_ / "out.txt").string() +
                                " 2> " + (dir_ / "err.txt").string();
    const int status = std::system(command.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }
  fs::path dir_;
};

TEST_F(HeadlessWindow, DefaultSceneScreenshotShowsTheCentredObject) {
  const fs::path shot = dir_ / "default.png";
  ASSERT_EQ(run("--headless --frames 3 --size 640x400 --screenshot " + shot.string()), 0);
  const Image image = load(shot);
  ASSERT_EQ(image.width, 640);
  ASSERT_EQ(image.height, 400);
  // Background in the corners.
  for (auto [x, y] : {std::pair{2, 2}, {637, 2}, {2, 397}, {637, 397}})
    EXPECT_TRUE(isBackground(image.at(x, y))) << x << ',' << y;
  // The object: enough non-background pixels, none black, centred.
  double count = 0;
  double sx = 0, sy = 0;
  int black = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const unsigned char* p = image.at(x, y);
      if (isBackground(p)) continue;
      ++count, sx += x, sy += y;
      if (p[0] + p[1] + p[2] < 15) ++black;
    }
  const double fraction = static_cast<double>(count) / (image.width * image.height);
  std::printf("[ measured ] object covers %.1f%% of the image, centroid (%.0f, %.0f), %d black\n",
              100 * fraction, sx / count, sy / count, black);
  EXPECT_GT(fraction, 0.10);
  EXPECT_LT(fraction, 0.80);
  EXPECT_EQ(black, 0);
  EXPECT_NEAR(sx / count, image.width / 2.0, 0.12 * image.width);
  EXPECT_NEAR(sy / count, image.height / 2.0, 0.12 * image.height);
}

// The interactive window with its simulation worker thread runs (ImGui, GPU deformation, the
// worker publishing states) and closes cleanly.
TEST_F(HeadlessWindow, WindowWithSimulationWorkerRunsAndQuits) {
  EXPECT_EQ(run("--quit-after 2 --size 800x600"), 0);
}

TEST_F(HeadlessWindow, BadInputIsExit2) {
  EXPECT_EQ(run("--frobnicate"), 2);
  EXPECT_EQ(run("--headless"), 2);  // needs --screenshot
  EXPECT_EQ(run("--quit-after -1"), 2);
  EXPECT_EQ(run("--headless --surface /nonexistent.obj --screenshot " +
                (dir_ / "x.png").string()),
            2);
  EXPECT_FALSE(fs::exists(dir_ / "x.png"));
}

}  // namespace
