// The window's scene starts building before the window exists (startSceneBuild): the app takes
// that build over instead of starting another, and opens projects itself.

#include <chrono>

#include "sculpt/scene_start.h"
#include "sculpt_session.h"

namespace sculpt::app {
namespace {

TEST_F(SculptSession, ABuildStartedBeforeTheWindowIsTakenOverNotRepeated) {
  Options options;
  options.headless = false;  // the window's threaded builder and simulation
  options.width = 1280, options.height = 800;
  options.scene = SCULPT_SOURCE_DIR "/assets/block3.json";
  options.level = 1;
  std::unique_ptr<SceneController> early = startSceneBuild(options);
  ASSERT_NE(early, nullptr);
  app_ = std::make_unique<SculptApp>(window_, options, std::chrono::steady_clock::now(),
                                     LoadedPreferences{}, folder_ / "preferences.json",
                                     std::move(early));
  framesUntil([this] { return app_->sceneView().hasGeometry(); });
  ASSERT_TRUE(app_->sceneView().hasGeometry());
  // The first build's scene: a second load would have cancelled it and shown scene 2.
  EXPECT_EQ(geometry().sceneId, 1u);
  EXPECT_EQ(geometry().description.rfind("block3.json", 0), 0u) << geometry().description;
  EXPECT_EQ(app_->model().settings.level, 1);

  options.scene = (folder_ / "work.sculpt").string();
  EXPECT_EQ(startSceneBuild(options), nullptr);
}

}  // namespace
}  // namespace sculpt::app
