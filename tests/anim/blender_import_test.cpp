// Blender imports the .glb morph animation: the shape keys are named after the keys, an action
// drives them, and stepping the scene cross-fades them (tests/anim/blender_import_check.py).

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "anim/fake_animated_surface.h"
#include "anim/glb_animation_writer.h"
#include "io/atomic_file.h"
#include "support/scratch_directory.h"
#include "support/shell_quote.h"

namespace sculpt {
namespace {

// Runs the check script on `glb`; returns the exit status and fills `log` with its output.
int runBlenderCheck(const std::filesystem::path& glb, uint32_t expectedKeys, std::string& log) {
  const auto logPath = glb.parent_path() / (glb.stem().string() + ".blender.log");
  const std::string script = SCULPT_SOURCE_DIR "/tests/anim/blender_import_check.py";
  const std::string command =
      "blender --background --factory-startup --python-exit-code 1 --python " +
      test::shellQuote(script) + " -- " + test::shellQuote(glb.string()) + " " +
      std::to_string(expectedKeys) + " > " + test::shellQuote(logPath.string()) + " 2>&1";
  const int status = std::system(command.c_str());
  log = readFile(logPath);
  return status;
}

class BlenderImportTest : public ::testing::Test {
 protected:
  BlenderImportTest() : dir_("sculpt_blender_import_test") {}
  void SetUp() override {
    ASSERT_EQ(std::system("command -v blender > /dev/null 2>&1"), 0)
        << "blender is not on PATH: scripts/install-deps.sh installs it";
  }
  std::filesystem::path file(const std::string& name) const { return dir_.path() / name; }

 private:
  test::ScratchDirectory dir_;
};

TEST_F(BlenderImportTest, OneSegmentPlaysAsShapeKeys) {
  const test::FakeAnimatedSurface take(60, 30.0, 1, 0.01);
  const ExportResult result = writeGlbAnimation(take, file("take.glb"), {}, nullptr);
  std::string log;
  ASSERT_EQ(runBlenderCheck(file("take.glb"), result.keys, log), 0) << log;
  std::printf("%s", log.c_str());
  char keys[64];
  std::snprintf(keys, sizeof keys, "12 vertices, %u shape keys (take_key_0001 .. take_key_%04u)",
                result.keys, result.keys);
  EXPECT_NE(log.find(keys), std::string::npos) << log;
  EXPECT_NE(log.find("shape keys: " + std::to_string(result.keys) + "\n"), std::string::npos)
      << log;
  EXPECT_NE(log.find("blender import check: ok"), std::string::npos) << log;
}

TEST_F(BlenderImportTest, SegmentsImportAsMeshesOfTheirOwn) {
  const test::FakeAnimatedSurface take(60, 30.0, 2, 0.01);
  const ExportResult result = writeGlbAnimation(take, file("segments.glb"), {}, nullptr);
  std::string log;
  ASSERT_EQ(runBlenderCheck(file("segments.glb"), result.keys, log), 0) << log;
  std::printf("%s", log.c_str());
  EXPECT_NE(log.find("mesh take_segment_1: 12 vertices"), std::string::npos) << log;
  EXPECT_NE(log.find("mesh take_segment_2: 15 vertices"), std::string::npos) << log;
  EXPECT_NE(log.find("blender import check: ok"), std::string::npos) << log;
  // The wrong count fails the script.
  EXPECT_NE(runBlenderCheck(file("segments.glb"), result.keys + 1, log), 0) << log;
}

}  // namespace
}  // namespace sculpt
