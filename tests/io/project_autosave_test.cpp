// Autosave writes a recovery file on a (fake) clock while there are unsaved changes; after a
// simulated crash findRecovery offers it; a clean save removes it. Preferences round-trip and a
// damaged preferences file gives defaults with a warning.

#include <gtest/gtest.h>

#include "support/scratch_directory.h"
#include <unistd.h>

#include <filesystem>
#include <optional>

#include "io/atomic_file.h"
#include "project/autosave.h"
#include "project/preferences.h"
#include "project/project_file.h"

namespace sculpt {
namespace {

class AutosaveTest : public ::testing::Test {
 protected:
  test::ScratchDirectory scratch_{"sculpt_autosave_test"};
  const std::filesystem::path& dir_ = scratch_.path();
};

Project smallProject(double x) {
  Project project;
  project.controlMesh.positions.resize(1, 3);
  project.controlMesh.positions << x, 0.0, 0.0;
  return project;
}

TEST_F(AutosaveTest, WritesOnlyWhenDirtyAndTheIntervalPassed) {
  const auto path = dir_ / "work.sculpt";
  double now = 100.0;
  Autosave autosave(recoveryPathFor(path), 300.0, [&] { return now; });
  EXPECT_EQ(autosave.recoveryPath(), dir_ / "work.sculpt.recovery");

  now = 399.0;
  EXPECT_FALSE(autosave.tick(smallProject(1), true));  // too early
  now = 400.0;
  EXPECT_FALSE(autosave.tick(smallProject(1), false));  // nothing unsaved
  EXPECT_FALSE(std::filesystem::exists(autosave.recoveryPath()));
  EXPECT_TRUE(autosave.tick(smallProject(1), true));
  EXPECT_EQ(readFile(autosave.recoveryPath()), serializeProject(smallProject(1)));
  now = 500.0;
  EXPECT_FALSE(autosave.tick(smallProject(2), true));  // the interval restarted at 400
  now = 700.0;
  EXPECT_TRUE(autosave.tick(smallProject(2), true));
  EXPECT_EQ(readFile(autosave.recoveryPath()), serializeProject(smallProject(2)));
}

TEST_F(AutosaveTest, CrashAfterAutosaveOffersRecoveryAndCleanSaveRemovesIt) {
  const auto path = dir_ / "work.sculpt";
  saveProject(smallProject(1), path);
  EXPECT_FALSE(findRecovery(path).has_value());

  double now = 0.0;
  {
    Autosave autosave(recoveryPathFor(path), 60.0, [&] { return now; });
    now = 61.0;
    ASSERT_TRUE(autosave.tick(smallProject(2), true));
    // The process "crashes" here: the Autosave goes away without savedCleanly().
  }
  const std::optional<std::filesystem::path> recovery = findRecovery(path);
  ASSERT_TRUE(recovery.has_value());
  EXPECT_EQ(*recovery, recoveryPathFor(path));
  // The recovered project is the autosaved one, not the saved one.
  EXPECT_EQ(loadProject(*recovery).controlMesh.positions(0, 0), 2.0);
  EXPECT_EQ(loadProject(path).controlMesh.positions(0, 0), 1.0);

  // The next session recovers, then saves cleanly: the recovery file is gone.
  Autosave next(recoveryPathFor(path), 60.0, [&] { return now; });
  saveProject(loadProject(*recovery), path);
  next.savedCleanly();
  EXPECT_FALSE(std::filesystem::exists(recoveryPathFor(path)));
  EXPECT_FALSE(findRecovery(path).has_value());
  EXPECT_EQ(loadProject(path).controlMesh.positions(0, 0), 2.0);
}

TEST_F(AutosaveTest, StaleRecoveryOlderThanTheProjectIsNotOffered) {
  const auto path = dir_ / "work.sculpt";
  saveProject(smallProject(1), path);
  saveProject(smallProject(0), recoveryPathFor(path));
  std::filesystem::last_write_time(recoveryPathFor(path),
                                   std::filesystem::last_write_time(path) - std::chrono::hours(1));
  EXPECT_FALSE(findRecovery(path).has_value());
  // Without the project file (never saved, or deleted) the recovery file is offered.
  std::filesystem::remove(path);
  EXPECT_TRUE(findRecovery(path).has_value());
}

TEST_F(AutosaveTest, SaveAsMovesTheRecoveryFile) {
  double now = 0.0;
  Autosave autosave(recoveryPathFor(dir_ / "a.sculpt"), 10.0, [&] { return now; });
  now = 10.0;
  ASSERT_TRUE(autosave.tick(smallProject(1), true));
  autosave.setRecoveryPath(recoveryPathFor(dir_ / "b.sculpt"));
  EXPECT_FALSE(std::filesystem::exists(recoveryPathFor(dir_ / "a.sculpt")));
  now = 20.0;
  ASSERT_TRUE(autosave.tick(smallProject(1), true));
  EXPECT_TRUE(std::filesystem::exists(recoveryPathFor(dir_ / "b.sculpt")));
  EXPECT_THROW(Autosave(dir_ / "x", 0.0, [] { return 0.0; }), std::invalid_argument);
}

TEST(PreferencesPath, FollowsXdgThenHome) {
  EXPECT_EQ(preferencesPath("/cfg", "/home/u"), "/cfg/sculpt/preferences.json");
  EXPECT_EQ(preferencesPath("relative", "/home/u"), "/home/u/.config/sculpt/preferences.json");
  EXPECT_EQ(preferencesPath(nullptr, "/home/u"), "/home/u/.config/sculpt/preferences.json");
  EXPECT_EQ(preferencesPath(nullptr, nullptr), "sculpt-preferences.json");
}

TEST(PreferencesRecentFiles, MostRecentFirstDeduplicatedAtMostTen) {
  Preferences p;
  for (int i = 0; i < 12; ++i) p.addRecentFile(std::string("f").append(std::to_string(i)));
  p.addRecentFile("f5");
  ASSERT_EQ(p.recentFiles.size(), 10u);
  EXPECT_EQ(p.recentFiles[0], "f5");
  EXPECT_EQ(p.recentFiles[1], "f11");
  EXPECT_EQ(p.recentFiles[9], "f2");  // f0 and f1 fell off; f5 moved, not repeated
  EXPECT_EQ(std::count(p.recentFiles.begin(), p.recentFiles.end(), "f5"), 1);
}

TEST_F(AutosaveTest, PreferencesRoundTripAndDamagedFilesGiveDefaults) {
  const auto path = dir_ / "config" / "sculpt" / "preferences.json";
  LoadedPreferences missing = loadPreferences(path);
  EXPECT_EQ(missing.preferences, Preferences{});
  EXPECT_EQ(missing.warning, "");

  Preferences p;
  p.keyMap = "undo=Ctrl+Z\nredo=Ctrl+Shift+Z";
  p.uiScale = 1.5;
  p.window = {10, 20, 1600, 900, true};
  p.addRecentFile("/a.sculpt");
  p.addRecentFile("/b.sculpt");
  savePreferences(p, path);  // creates config/sculpt
  const LoadedPreferences loaded = loadPreferences(path);
  EXPECT_EQ(loaded.preferences, p);
  EXPECT_EQ(loaded.warning, "");

  writeFileAtomically(path, "{\"format\": \"sculpt-pref");
  LoadedPreferences damaged = loadPreferences(path);
  EXPECT_EQ(damaged.preferences, Preferences{});
  EXPECT_NE(damaged.warning.find("not valid JSON"), std::string::npos) << damaged.warning;

  // One bad field loses only itself.
  writeFileAtomically(path, R"({"format": "sculpt-preferences", "version": 1, "uiScale": "big",
                                "recentFiles": ["/x.sculpt"]})");
  damaged = loadPreferences(path);
  EXPECT_EQ(damaged.preferences.uiScale, 0.0);  // the default: automatic
  EXPECT_EQ(damaged.preferences.recentFiles, std::vector<std::string>{"/x.sculpt"});
  EXPECT_NE(damaged.warning.find("uiScale"), std::string::npos) << damaged.warning;

  writeFileAtomically(path, R"({"format": "sculpt-preferences", "version": 9})");
  EXPECT_NE(loadPreferences(path).warning.find("newer"), std::string::npos);
  writeFileAtomically(path, "[1, 2]");
  EXPECT_NE(loadPreferences(path).warning.find("not a sculpt preferences file"), std::string::npos);
}

}  // namespace
}  // namespace sculpt
