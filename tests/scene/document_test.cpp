// The window's document (scene/document.h): undo entries, the dirty marker (clean again when
// undo returns to the saved state), Save / Save As, autosave and what a crash leaves behind.

#include "scene/document.h"

#include <gtest/gtest.h>

#include "support/scratch_directory.h"

#include <filesystem>
#include <fstream>

#include "io/control_mesh_json.h"
#include "project/project_file.h"

namespace sculpt {
namespace {

namespace fs = std::filesystem;

class DocumentTest : public ::testing::Test {
 protected:
  Document make() {
    return Document(folder_, 60.0, [this] { return now_; });
  }
  static Project block() {
    Project p;
    p.controlMesh = loadControlMeshJson(std::string(SCULPT_SOURCE_DIR) + "/assets/block3.json");
    p.pins = {0, 1};
    return p;
  }
  test::ScratchDirectory scratch_{"sculpt_document"};
  const fs::path& folder_ = scratch_.path();
  double now_ = 0.0;
};

TEST_F(DocumentTest, DirtyFollowsTheHistoryAndUndoToTheSavedStateIsClean) {
  Document d = make();
  d.start(block());
  EXPECT_FALSE(d.dirty());
  EXPECT_EQ(d.title(), "untitled");
  Project moved = d.project();
  moved.controlMesh.positions(0, 0) += 0.25;
  ASSERT_TRUE(d.commit("Move point", moved));
  EXPECT_TRUE(d.dirty());
  EXPECT_EQ(d.title(), "untitled *");
  EXPECT_EQ(d.undoLabel(), "Move point");
  // A commit that changes nothing undoable records nothing.
  Project cameraOnly = d.project();
  cameraOnly.camera.distance = 99.0;
  EXPECT_FALSE(d.commit("Camera", cameraOnly));
  const auto change = d.undo();
  ASSERT_TRUE(change.has_value());
  EXPECT_TRUE(change->controlMesh);
  EXPECT_FALSE(change->materialsOrPins);
  EXPECT_FALSE(d.dirty()) << "undo back to the state it started in";
  EXPECT_EQ(serializeProject(d.project()), serializeProject(block()));
  ASSERT_TRUE(d.redo().has_value());
  EXPECT_TRUE(d.dirty());
  EXPECT_FALSE(d.redo().has_value());
}

TEST_F(DocumentTest, SaveAsNamesTheDocumentAndSaveLoadGivesTheSameBytes) {
  Document d = make();
  d.start(block());
  Project pinned = d.project();
  pinned.pins = {0, 1, 5};
  ASSERT_TRUE(d.commit("Pin", pinned));
  const auto change = d.undo();
  ASSERT_TRUE(change && change->materialsOrPins && !change->controlMesh);
  ASSERT_TRUE(d.redo());
  EXPECT_THROW(d.save(), std::invalid_argument) << "an untitled document needs Save As";
  const fs::path path = folder_ / "work.sculpt";
  d.saveAs(path);
  EXPECT_FALSE(d.dirty());
  EXPECT_EQ(d.title(), "work.sculpt");
  EXPECT_EQ(loadProject(path).pins, (std::vector<uint32_t>{0, 1, 5}));
  std::ifstream in(path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), {});
  EXPECT_EQ(serializeProject(loadProject(path)), bytes);
  // Undo after saving makes it dirty; redo back to the saved state makes it clean.
  ASSERT_TRUE(d.undo());
  EXPECT_TRUE(d.dirty());
  ASSERT_TRUE(d.redo());
  EXPECT_FALSE(d.dirty());
}

TEST_F(DocumentTest, AutosaveWhileDirtyLeavesARecoveryFileThatACleanSaveRemoves) {
  Document d = make();
  d.start(block(), folder_ / "a.sculpt");
  d.saveAs(folder_ / "a.sculpt");
  Project moved = d.project();
  moved.controlMesh.positions(3, 2) -= 0.5;
  ASSERT_TRUE(d.commit("Move point", moved));
  now_ = 30.0;
  EXPECT_EQ(d.tick(), "");
  EXPECT_FALSE(fs::exists(d.recoveryPath())) << "not before the interval";
  now_ = 61.0;
  EXPECT_EQ(d.tick(), "");
  ASSERT_TRUE(fs::exists(d.recoveryPath()));
  EXPECT_EQ(d.recoveryPath(), folder_ / "a.sculpt.recovery");
  // "Crash": a new document on the same file finds the recovery file with the edit in it.
  const auto recovery = findRecovery(folder_ / "a.sculpt");
  ASSERT_TRUE(recovery.has_value());
  EXPECT_EQ(loadProject(*recovery).controlMesh.positions(3, 2), moved.controlMesh.positions(3, 2));
  Document recovered = make();
  recovered.start(loadProject(*recovery), folder_ / "a.sculpt", true);
  EXPECT_TRUE(recovered.dirty()) << "recovered work is not saved yet";
  d.save();
  EXPECT_FALSE(fs::exists(d.recoveryPath())) << "a clean save removes the recovery file";
}

TEST_F(DocumentTest, UntitledAutosavesInTheRecoveryFolderAndFailedSavesReport) {
  Document d = make();
  d.start(block());
  Project moved = d.project();
  moved.controlMesh.positions(1, 1) += 0.5;
  ASSERT_TRUE(d.commit("Move point", moved));
  now_ = 100.0;
  EXPECT_EQ(d.tick(), "");
  EXPECT_TRUE(fs::exists(folder_ / "untitled.sculpt.recovery"));
  EXPECT_THROW(d.saveAs(folder_ / "no" / "such" / "dir" / "x.sculpt"), std::exception);
  EXPECT_TRUE(d.dirty()) << "a failed save leaves the document dirty";
  EXPECT_EQ(d.title(), "untitled *");
}

TEST_F(DocumentTest, AFreshConfigurationGetsItsRecoveryFolderAtTheFirstAutosave) {
  const fs::path recoveryFolder = folder_ / "fresh-config" / "sculpt";
  Document d(recoveryFolder, 60.0, [this] { return now_; });
  d.start(block());
  Project moved = d.project();
  moved.controlMesh.positions(1, 1) += 0.5;
  ASSERT_TRUE(d.commit("Move point", moved));
  now_ = 100.0;
  EXPECT_EQ(d.tick(), "") << "no 'autosave failed' on a configuration without its folder";
  EXPECT_TRUE(fs::exists(recoveryFolder / "untitled.sculpt.recovery"));
}

}  // namespace
}  // namespace sculpt
