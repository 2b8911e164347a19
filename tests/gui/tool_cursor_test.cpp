// Every tool shows where it acts: with the pointer over the model, the rendered window has the
// tool's cursor in its colour around the pointer (pull: grab point and depth ring; curve: a
// point; topology: the face highlighted; inflate, paint, pin: the brush circle), compared with
// the same view without the pointer; over a panel no cursor is drawn, and off the model only the
// brush circles are (they show the brush's size anywhere in the view). With
// SCULPT_SESSION_IMAGES set, the frames are also written there (cursor-pull.png, ...).

#include <gtest/gtest.h>
#include <stb_image.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include "gui/sculpt_session.h"
#include "sculpt/tool_state.h"

namespace sculpt::app {
namespace {

namespace fs = std::filesystem;

const std::string kBlock3 = std::string(SCULPT_SOURCE_DIR) + "/assets/block3.json";

struct Rgb {
  int r, g, b;
};

struct CursorCase {
  ToolKind tool;
  Rgb colour;     ///< of the cursor's strokes where they are opaque
  float extent;   ///< the cursor lies within this many pixels of the pointer
  bool offModel;  ///< also drawn with the pointer over the background
};

void PrintTo(const CursorCase& c, std::ostream* out) { *out << toolKey(c.tool); }

std::string fileName(ToolKind tool) { return std::string("cursor-") + toolKey(tool) + ".png"; }

class ToolCursor : public SculptSession, public ::testing::WithParamInterface<CursorCase> {
 protected:
  struct Image {
    int width = 0, height = 0;
    std::vector<unsigned char> rgb;
    const unsigned char* at(int x, int y) const { return rgb.data() + 3 * (y * width + x); }
  };

  // The next frame as written to a PNG (panels included, as the window shows it).
  Image shot(const std::string& name) {
    const fs::path path = folder_ / name;
    app_->headlessFrame(path.string());
    if (!images_.empty())
      fs::copy_file(path, fs::path(images_) / name, fs::copy_options::overwrite_existing);
    Image image;
    int channels = 0;
    unsigned char* pixels =
        stbi_load(path.string().c_str(), &image.width, &image.height, &channels, 3);
    EXPECT_NE(pixels, nullptr) << path;
    if (pixels) {
      image.rgb.assign(pixels, pixels + 3 * image.width * image.height);
      stbi_image_free(pixels);
    }
    return image;
  }

  // The pointer moved to `at`: one frame reads the depth under it, the next draws the cursor.
  void hover(ImVec2 at) {
    pointer_.x = at.x, pointer_.y = at.y;
    frames(2);
  }

  // Pixels of the 3D view within `extent` of `at` that are of `colour` (each channel within
  // 40 / 255) in `with` and differ from `without` (a channel by more than 24 / 255).
  int cursorPixels(const Image& with, const Image& without, ImVec2 at, float extent,
                   Rgb colour) const {
    const auto changed = [&with, &without](int x, int y) {
      const unsigned char *a = with.at(x, y), *b = without.at(x, y);
      return std::abs(a[0] - b[0]) > 24 || std::abs(a[1] - b[1]) > 24 || std::abs(a[2] - b[2]) > 24;
    };
    const auto near = [&colour](const unsigned char* p) {
      return std::abs(p[0] - colour.r) <= 40 && std::abs(p[1] - colour.g) <= 40 &&
             std::abs(p[2] - colour.b) <= 40;
    };
    const ViewRect view = app_->viewRect();
    int count = 0;
    for (int y = static_cast<int>(view.min.y); y < static_cast<int>(view.max.y); ++y)
      for (int x = static_cast<int>(view.min.x); x < static_cast<int>(view.max.x); ++x)
        if (std::hypot(static_cast<float>(x) - at.x, static_cast<float>(y) - at.y) <= extent &&
            near(with.at(x, y)) && changed(x, y))
          ++count;
    return count;
  }
};

TEST_P(ToolCursor, DrawnOverTheModelNotOverAPanel) {
  const CursorCase c = GetParam();
  open(kBlock3);
  frames(30);
  ASSERT_TRUE(app_->sceneView().frame().physicsReady);
  app_->model().requests.togglePlay = true;  // a still scene: frames differ by the cursor only
  frames(2);
  ASSERT_FALSE(app_->model().status.playing);
  app_->model().tools.tool = c.tool;

  const ViewRect view = app_->viewRect();
  const ImVec2 model(0.5f * (view.min.x + view.max.x), 0.5f * (view.min.y + view.max.y));
  const ImVec2 background(view.min.x + 120.0f, view.min.y + 120.0f);
  const ImVec2 panel(view.min.x - 15.0f, model.y);  // the left panel, beside the view
  hover(ImVec2(-1e6f, -1e6f));
  const Image none = shot(std::string("no-") + fileName(c.tool));
  hover(model);
  const Image over = shot(fileName(c.tool));
  hover(background);
  const Image off = shot(std::string("off-") + fileName(c.tool));
  hover(panel);
  ASSERT_TRUE(ImGui::GetIO().WantCaptureMouse) << "the pointer is over the panel";
  const Image overPanel = shot(std::string("panel-") + fileName(c.tool));

  const int onModel = cursorPixels(over, none, model, c.extent, c.colour);
  const int onBackground = cursorPixels(off, none, background, c.extent, c.colour);
  const int nextToPanel =
      cursorPixels(overPanel, none, ImVec2(view.min.x, model.y), 100.0f, c.colour);
  std::printf(
      "[ measured ] %s cursor pixels: %d over the model, %d over the background, %d by the panel\n",
      toolName(c.tool), onModel, onBackground, nextToPanel);
  EXPECT_GE(onModel, 40) << "the cursor is drawn at the pointer over the model";
  if (c.offModel)
    EXPECT_GE(onBackground, 40) << "the brush circle shows over the background too";
  else
    EXPECT_EQ(onBackground, 0) << "no cursor off the model";
  EXPECT_EQ(nextToPanel, 0) << "no cursor while the pointer is over a panel";
  // The cursor is the tool's: none of its colour away from the pointer.
  EXPECT_EQ(cursorPixels(over, none, background, 60.0f, c.colour), 0);
}

// While a curve is drawn, the curve so far shows with the point cursor at its end.
TEST_F(ToolCursor, CurveShowsWhileDrawnWithThePointAtItsEnd) {
  open(kBlock3);
  frames(30);
  app_->model().requests.togglePlay = true;
  frames(2);
  app_->model().tools.tool = ToolKind::Curve;
  const ViewRect view = app_->viewRect();
  const ImVec2 start(0.5f * (view.min.x + view.max.x) - 90.0f,
                     0.5f * (view.min.y + view.max.y) + 40.0f);
  hover(ImVec2(-1e6f, -1e6f));
  const Image none = shot("no-cursor-curve-drawn.png");
  drag(start, 170.0f, -90.0f, 12);
  frames(1);
  const ImVec2 end(start.x + 170.0f, start.y - 90.0f);
  const Image drawing = shot("cursor-curve-drawn.png");
  release();
  const Rgb cyan{80, 220, 255};
  const int atEnd = cursorPixels(drawing, none, end, 12.0f, cyan);
  const int alongCurve =
      cursorPixels(drawing, none, ImVec2(start.x + 85.0f, start.y - 45.0f), 30.0f, cyan);
  std::printf("[ measured ] curve being drawn: %d pixels at its end, %d around its middle\n", atEnd,
              alongCurve);
  EXPECT_GE(atEnd, 40) << "the point cursor at the pointer";
  EXPECT_GE(alongCurve, 60) << "the curve drawn so far";
}

INSTANTIATE_TEST_SUITE_P(
    EveryTool, ToolCursor,
    ::testing::Values(CursorCase{ToolKind::Pull, {255, 89, 51}, 90.0f, false},
                      CursorCase{ToolKind::Inflate, {255, 255, 255}, 60.0f, true},
                      CursorCase{ToolKind::Curve, {80, 220, 255}, 15.0f, false},
                      CursorCase{ToolKind::Paint, {255, 255, 255}, 60.0f, true},
                      CursorCase{ToolKind::Pin, {255, 90, 80}, 60.0f, true},
                      CursorCase{ToolKind::Topology, {80, 220, 255}, 400.0f, false}),
    [](const ::testing::TestParamInfo<CursorCase>& param) {
      return std::string(toolKey(param.param.tool));
    });

}  // namespace
}  // namespace sculpt::app
