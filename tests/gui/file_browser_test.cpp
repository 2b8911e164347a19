// The file browser through the real window (gui/sculpt_session.h): File > Open takes a typed
// project path, arrow keys and Enter walk through folders to a control mesh, Tab completes a
// typed name, and Save As over an existing file asks first: No keeps the old bytes, Yes
// replaces them and the document takes the file's name. The export dialog's Browse... names a
// sequence and asks before replacing one. With SCULPT_SESSION_IMAGES set, the
// browser's screenshots (scale 1 and 2) are written there.

#include "render/gl.h"
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <gtest/gtest.h>
#include <imgui.h>
#include <imgui_internal.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "gui/sculpt_session.h"
#include "sculpt/record_panel.h"
#include "sculpt/sculpt_app.h"

namespace sculpt::app {
namespace {

namespace fs = std::filesystem;

const fs::path kAssets = fs::path(SCULPT_SOURCE_DIR) / "assets";

std::string bytesOf(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), {});
}

class FileBrowserWindow : public SculptSession {
 protected:
  // Whether the ImGui window of this name was drawn in the last frame.
  static bool showing(const char* name) {
    const ImGuiWindow* window = ImGui::FindWindowByName(name);
    return window && window->Active;
  }
  static bool browserShowing(const char* title) {
    return showing((std::string(title) + "###file browser").c_str());
  }
  void enter() { press(GLFW_KEY_ENTER, false); }
  void down() { press(GLFW_KEY_DOWN, false); }
  std::string field() { return std::string(app_->model().fileBrowser.typed.data()); }
};

TEST_F(FileBrowserWindow, OpensAProjectByATypedPath) {
  open((kAssets / "block3.json").string());
  frames(3);
  const fs::path first = folder_ / "first.sculpt", second = folder_ / "second.sculpt";
  app_->model().requests.saveAs = first.string();
  frames(1);
  app_->model().requests.saveAs = second.string();
  frames(1);
  ASSERT_TRUE(fs::exists(first));
  ASSERT_EQ(app_->document().path(), second);

  press(GLFW_KEY_O, true);  // Ctrl+O
  frames(2);
  ASSERT_TRUE(browserShowing("Open"));
  EXPECT_TRUE(ImGui::GetIO().WantTextInput) << "the path field takes the keyboard as it opens";
  type(first.string());
  EXPECT_EQ(field(), first.string());
  enter();
  frames(3);
  EXPECT_FALSE(browserShowing("Open"));
  EXPECT_EQ(app_->document().path(), first);
  EXPECT_EQ(app_->document().title(), "first.sculpt");
  EXPECT_EQ(app_->model().sceneFile, first.string());
  EXPECT_EQ(app_->model().recentScenes.front(), first.string());
}

// File > Replay session script...: the browser lists the scripts, and the chosen one plays on
// the scene shown (its paint reaches the material the view draws).
TEST_F(FileBrowserWindow, ReplaysASessionScriptChosenInTheBrowser) {
  open((kAssets / "block3.json").string());
  frames(10);
  ASSERT_TRUE(app_->sceneView().hasGeometry());
  const auto largestYoungs = [&] {
    const std::vector<float>& youngs = app_->sceneView().frame().cellYoungs;
    return youngs.empty() ? 0.0f : *std::max_element(youngs.begin(), youngs.end());
  };
  const float before = largestYoungs();
  const fs::path script = folder_ / "stiff_corner.json";
  std::ofstream(script) << R"({"format": "sculpt-session", "version": 1, "events": [
    {"t": 0.0, "type": "paint", "centre": [0.5, 0.5, 0.5], "radius": 1.0, "youngs": 3e9}]})";
  openFileBrowser(app_->model().fileBrowser, FileBrowserUse::ReplayScript, folder_.string());
  frames(2);
  ASSERT_TRUE(browserShowing("Replay session script"));
  // The script is listed under the session-script filter.
  const std::vector<FileEntry>& entries = app_->model().fileBrowser.listing.entries;
  EXPECT_TRUE(std::any_of(entries.begin(), entries.end(),
                          [](const FileEntry& e) { return e.name == "stiff_corner.json"; }));
  type("stiff_corner.json");
  enter();
  frames(20);
  EXPECT_FALSE(browserShowing("Replay session script"));
  const float after = largestYoungs();
  std::printf("[ replay ] largest Young's modulus drawn: %.3g Pa before, %.3g Pa after\n", before,
              after);
  EXPECT_LT(before, 1e8f);
  // A cell's value is its samples' mean: the brush's falloff leaves the corner cell below 3e9.
  EXPECT_GT(after, 1e9f) << "the script's paint reached the drawn material";
  EXPECT_LE(after, 3e9f);
  // A missing script is one message, and the scene keeps running.
  app_->model().requests.replayScript = (folder_ / "missing.json").string();
  frames(2);
  ASSERT_FALSE(app_->model().toasts.empty());
  EXPECT_NE(app_->model().toasts.back().text.find("missing.json"), std::string::npos);
  EXPECT_TRUE(app_->model().toasts.back().error);
}

TEST_F(FileBrowserWindow, ArrowKeysAndEnterWalkThroughFoldersToAControlMesh) {
  const fs::path browse = folder_ / "browse", mesh = browse / "meshes" / "block3.json";
  fs::create_directories(mesh.parent_path());
  fs::copy_file(kAssets / "block3.json", mesh);
  std::ofstream(browse / "notes.txt") << "not a scene";  // filtered out of Openable
  open((kAssets / "cube.json").string());
  frames(3);
  ASSERT_TRUE(app_->model().controlMeshScene);

  press(GLFW_KEY_O, true);
  frames(1);
  type(browse.string() + "/");
  enter();  // a typed folder is entered
  const FileBrowser& browser = app_->model().fileBrowser;
  EXPECT_EQ(browser.folder, browse);
  ASSERT_EQ(browser.listing.entries.size(), 1u) << "only meshes/: notes.txt is not openable";
  down();  // ".."
  EXPECT_EQ(field(), "..");
  down();  // meshes/
  EXPECT_EQ(field(), "meshes/");
  enter();
  EXPECT_EQ(browser.folder, browse / "meshes");
  EXPECT_TRUE(browserShowing("Open"));
  down();
  down();
  EXPECT_EQ(field(), "block3.json");
  enter();
  frames(3);
  EXPECT_FALSE(browserShowing("Open"));
  EXPECT_EQ(app_->model().sceneFile, mesh.string());
  EXPECT_TRUE(app_->model().controlMeshScene);
  EXPECT_EQ(app_->document().project().controlMesh.numCells(), 27u) << "block3: 3 x 3 x 3 cells";

  // Backspace (the field not being edited) goes up, Escape cancels: nothing more is loaded.
  press(GLFW_KEY_O, true);
  frames(1);
  EXPECT_EQ(browser.folder, browse / "meshes") << "the browser opens where it was left";
  drag(ImVec2(640.0f, 400.0f), 0, 0, 1);  // a click in the listing (the browser is centred)
  release();
  frames(1);  // (ImGui reports the field's state a frame late)
  pointer_ = Pointer{};
  ASSERT_FALSE(ImGui::GetIO().WantTextInput) << "the click left the path field";
  press(GLFW_KEY_BACKSPACE, false);
  EXPECT_EQ(browser.folder, browse);
  press(GLFW_KEY_ESCAPE, false);
  frames(2);
  EXPECT_FALSE(browserShowing("Open"));
  EXPECT_EQ(app_->model().sceneFile, mesh.string());
}

TEST_F(FileBrowserWindow, TabCompletesATypedNameAndListsTheCandidates) {
  open((kAssets / "block3.json").string());
  frames(3);
  press(GLFW_KEY_O, true);
  frames(1);
  type(kAssets.string() + "/");
  enter();
  frames(1);  // the field takes the keyboard again
  ASSERT_EQ(app_->model().fileBrowser.folder, kAssets);
  type("bl");
  press(GLFW_KEY_TAB, false);
  EXPECT_EQ(field(), "block");
  EXPECT_EQ(app_->model().fileBrowser.candidates,
            (std::vector<std::string>{"block10.json", "block12.json", "block3.json"}));
  frames(2, "file-browser.png");
  // At UI scale 2 everything still fits (the screenshot shows it).
  app_->model().uiScale = 2.0f;
  app_->model().requests.uiScaleChanged = true;
  frames(3, "file-browser-scale2.png");
  type("3");
  press(GLFW_KEY_TAB, false);
  EXPECT_EQ(field(), "block3.json");
  EXPECT_TRUE(app_->model().fileBrowser.candidates.empty());
  press(GLFW_KEY_ESCAPE, false);
  frames(1);
  EXPECT_FALSE(browserShowing("Open"));
}

TEST_F(FileBrowserWindow, SaveAsOverAnExistingFileAsksFirst) {
  open((kAssets / "block3.json").string());
  frames(3);
  const fs::path old = folder_ / "old.sculpt";
  std::ofstream(old, std::ios::binary) << "the old bytes";
  ASSERT_NE(app_->document().title(), "old.sculpt");
  const std::string titleBefore = app_->document().title();
  const auto saveAs = [&] {
    pointer_.shift = true;
    press(GLFW_KEY_S, true);  // Ctrl+Shift+S
    pointer_.shift = false;
    frames(1);
    ASSERT_TRUE(browserShowing("Save project as"));
    press(GLFW_KEY_A, true);  // Ctrl+A: the proposed name is replaced by what is typed
    type(old.string());
    enter();
    frames(1);
    ASSERT_TRUE(showing("Replace file?###replace")) << app_->model().fileBrowser.message;
    EXPECT_EQ(app_->model().fileBrowser.pendingOverwrite, old.string());
  };

  saveAs();
  frames(1, "file-browser-replace.png");
  press(GLFW_KEY_N, false);  // No
  frames(2);
  EXPECT_FALSE(showing("Replace file?###replace"));
  EXPECT_TRUE(browserShowing("Save project as")) << "No goes back to the browser";
  EXPECT_EQ(bytesOf(old), "the old bytes");
  EXPECT_EQ(app_->document().title(), titleBefore);
  press(GLFW_KEY_ESCAPE, false);  // and Escape leaves it
  frames(2);
  EXPECT_FALSE(browserShowing("Save project as"));
  EXPECT_EQ(bytesOf(old), "the old bytes");

  saveAs();
  press(GLFW_KEY_Y, false);  // Yes
  frames(2);
  EXPECT_FALSE(showing("Replace file?###replace"));
  EXPECT_FALSE(browserShowing("Save project as"));
  EXPECT_NE(bytesOf(old), "the old bytes");
  EXPECT_EQ(app_->document().path(), old);
  EXPECT_EQ(app_->document().title(), "old.sculpt");
  EXPECT_FALSE(app_->document().dirty());
}

TEST_F(FileBrowserWindow, ExportBrowseNamesASequenceAndAsksBeforeReplacingOne) {
  open((kAssets / "block3.json").string());
  frames(3);
  app_->model().requests.record.toggleRecord = true;
  frames(6);
  app_->model().requests.record.toggleRecord = true;
  frames(1);
  ASSERT_TRUE(app_->model().record.hasTake);
  std::ofstream(folder_ / "walk_0001.obj") << "an earlier export";
  ExportDialog& dialog = app_->model().exportDialog;
  dialog.show = true;
  dialog.format = exportFormatIndex(ExportFormat::ObjSequence);
  setExportPath(dialog, (folder_ / "take_####.obj").string());
  frames(2, "file-browser-export-dialog.png");

  // Browse... ends the File row, scaled(420) from the window's left padding.
  const ImGuiWindow* window = ImGui::FindWindowByName("Export recording");
  ASSERT_NE(window, nullptr);
  const ImGuiStyle& style = ImGui::GetStyle();
  const float browse = ImGui::CalcTextSize("Browse...").x + 2 * style.FramePadding.x;
  const ImVec2 button(
      window->Pos.x + style.WindowPadding.x + 420.0f * ImGui::GetFontSize() / 13.0f - 0.5f * browse,
      window->Pos.y + window->TitleBarHeight() + style.WindowPadding.y +
          ImGui::GetFrameHeightWithSpacing() + 0.5f * ImGui::GetFrameHeight());
  drag(button, 0, 0, 1);
  release();
  pointer_ = Pointer{};
  frames(2, "file-browser-export.png");
  ASSERT_TRUE(browserShowing("Export recording to"));
  const FileBrowser& browser = app_->model().fileBrowser;
  EXPECT_EQ(browser.folder, folder_) << "it opens where the export path points";
  EXPECT_EQ(field(), "take_####.obj");
  EXPECT_EQ(browser.listing.entries.size(), 1u) << "only walk_0001.obj: the .obj files";

  press(GLFW_KEY_A, true);
  type("walk.obj");
  enter();
  frames(1);
  ASSERT_TRUE(showing("Replace file?###replace"));
  EXPECT_EQ(browser.pendingOverwrite, (folder_ / "walk_####.obj").string());
  frames(1, "file-browser-export-replace.png");
  press(GLFW_KEY_Y, false);
  frames(1);
  EXPECT_FALSE(browserShowing("Export recording to"));
  EXPECT_EQ(std::string(dialog.path.data()), (folder_ / "walk_####.obj").string());
  EXPECT_TRUE(dialog.show) << "the export dialog stays for the export itself";
}

TEST_F(FileBrowserWindow, MissingPathsSayWhyInsideTheDialog) {
  open((kAssets / "block3.json").string());
  frames(3);
  press(GLFW_KEY_O, true);
  frames(1);
  const std::string missing = (folder_ / "nowhere" / "x.sculpt").string();
  type(missing);
  enter();
  EXPECT_TRUE(browserShowing("Open"));
  EXPECT_EQ(app_->model().fileBrowser.message, "No such file: " + missing);
  EXPECT_EQ(app_->model().sceneFile, (kAssets / "block3.json").string());
  press(GLFW_KEY_ESCAPE, false);
  frames(1);
  EXPECT_FALSE(browserShowing("Open"));
}

}  // namespace
}  // namespace sculpt::app
