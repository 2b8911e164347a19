// The window driven like a person would (gui/sculpt_session.h). It pulls the bunny, paints a stiff
// ear, extrudes a face of the cage and undoes it, checking the effect of each step on the scene and
// on the project. With SCULPT_SESSION_IMAGES set to a folder, each step's screenshot is written
// there (the README's images come from this test).

#include "render/gl.h"
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <string>

#include "edit/topology_edit.h"
#include "io/control_mesh_json.h"
#include "mesh/validation.h"
#include "project/autosave.h"
#include "project/project_file.h"
#include "gui/sculpt_session.h"
#include "sculpt/sculpt_app.h"
#include "tools/session_script.h"

namespace sculpt::app {
namespace {

namespace fs = std::filesystem;

// The centroid of the boundary face of `mesh` with the highest score(centroid, unit outward
// normal); faces scoring NaN are skipped.
Eigen::Vector3d bestFaceCentre(
    const CellComplex& mesh,
    const std::function<double(const Eigen::Vector3d&, const Eigen::Vector3d&)>& score) {
  double best = -std::numeric_limits<double>::infinity();
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (const FaceRef& f : boundaryFaces(mesh)) {
    const auto loop = mesh.cellFace(f.cell, f.face);
    Eigen::Vector3d c = Eigen::Vector3d::Zero(), n = Eigen::Vector3d::Zero();
    for (size_t k = 0; k < loop.size(); ++k) {
      c += mesh.positions.row(loop[k]).transpose() / static_cast<double>(loop.size());
      n += mesh.positions.row(loop[k]).transpose().cross(
          mesh.positions.row(loop[(k + 1) % loop.size()]).transpose());
    }
    const double value = score(c, n.normalized());
    if (value > best) best = value, centre = c;
  }
  return centre;
}

TEST_F(SculptSession, PullPaintAStiffEarExtrudeAndUndo) {
  open();
  frames(40);  // the bunny is built, hangs and swings
  ASSERT_TRUE(app_->sceneView().hasGeometry());
  ASSERT_TRUE(app_->sceneView().frame().physicsReady);
  const Points& rest = geometry().restPositions;
  EXPECT_FALSE(app_->document().canUndo());

  // 1. Pull the bunny's lowest point (far from the pinned top layer) 120 px to the right.
  Eigen::Index low = 0, top = 0;
  rest.col(1).minCoeff(&low);
  rest.col(1).maxCoeff(&top);
  app_->model().tools.tool = ToolKind::Pull;
  const ImVec2 grabAt = screen(rest.row(low).transpose() + Eigen::Vector3d(0, 0.3, 0));
  drag(grabAt, 220.0f, 40.0f, 16);
  frames(30, "sculpt-pull.png");
  ASSERT_EQ(app_->sceneView().frame().springs.size(), 1u);
  const Eigen::Vector3d point = app_->sceneView().frame().springs.front().point;
  const Eigen::Vector3d target = app_->sceneView().frame().springs.front().target;
  const ImVec2 pointOnScreen = screen(point);
  EXPECT_GT(pointOnScreen.x - grabAt.x, 20.0f) << "the grabbed point follows the cursor";
  EXPECT_LT((point - target).norm(), (screen(target).x - grabAt.x) * 1.0)
      << "the spring pulls the point toward its target";
  release();
  frames(5);
  EXPECT_TRUE(app_->sceneView().frame().springs.empty()) << "release lets go";
  EXPECT_FALSE(app_->document().canUndo()) << "pulling is not an edit of the project";

  // 2. Paint a stiff ear: Young's modulus 100x the body's, under the highest surface point.
  ToolState& tools = app_->model().tools;
  usePaintBrush(3.0e8, 45.0f);
  tools.mirrorX = false;
  app_->model().display.field = FieldKind::YoungsModulus;
  const ImVec2 ear = screen(rest.row(top).transpose() - Eigen::Vector3d(0, 0.6, 0));
  drag(ear, 0.0f, 30.0f, 8);
  release();
  frames(3, "sculpt-paint-ear.png");
  ASSERT_TRUE(app_->document().canUndo());
  EXPECT_EQ(app_->document().undoLabel(), "Paint Young's modulus");
  const MaterialSamples& painted = app_->document().project().materials;
  ASSERT_GT(painted.size(), 0u);
  size_t stiff = 0;
  double highest = 0.0;
  for (size_t q = 0; q < painted.size(); ++q) {
    highest = std::max(highest, painted.materials[q].youngs);
    if (painted.materials[q].youngs > 3.0e6 * 1.5) {
      ++stiff;
      // Only samples near the ear: within the brush (a few cells) of the highest point.
      EXPECT_LT((painted.restPositions[q] - rest.row(top).transpose()).norm(), 4.0) << q;
    }
  }
  EXPECT_GT(highest, 1.0e8);
  EXPECT_GT(stiff, 0u);
  EXPECT_LT(stiff, painted.size() / 10) << "a brush, not a fill";
  EXPECT_GT(app_->model().fieldRange.high, 1.0e8) << "the field shows the painted value";

  // 3. Extrude a cage face on the right-hand side that the camera sees (obliquely, so that the
  //    new cell shows in profile).
  tools.tool = ToolKind::Topology;
  tools.operation = TopologyTool::Extrude;
  app_->model().display.field = FieldKind::None;
  app_->model().display.showControlMesh = true;
  const CellComplex before = app_->document().project().controlMesh;
  const size_t samplesBefore = app_->document().project().materials.size();
  const std::string bytesBefore = serializeProject(app_->document().project());
  const glm::vec3 eye = app_->camera().eye(), right = app_->camera().right();
  const Eigen::Vector3d faceCentre =
      bestFaceCentre(before, [&](const Eigen::Vector3d& c, const Eigen::Vector3d& n) {
        const Eigen::Vector3d toEye = Eigen::Vector3d(eye.x, eye.y, eye.z) - c;
        if (n.dot(toEye.normalized()) < 0.25) return std::numeric_limits<double>::quiet_NaN();
        return n.dot(Eigen::Vector3d(right.x, right.y, right.z)) + 0.02 * c.y();  // right, high
      });
  const ImVec2 faceAt = screen(faceCentre);
  pointer_ = Pointer{faceAt.x, faceAt.y};
  frames(2);  // hover highlights the face
  pointer_.left = true;
  frames(1);
  release();
  frames(6, "sculpt-extrude.png");
  ASSERT_EQ(app_->document().undoLabel(), "Extrude face");
  EXPECT_EQ(app_->document().project().controlMesh.numCells(), before.numCells() + 1);
  EXPECT_EQ(app_->document().project().controlMesh.numVertices(), before.numVertices() + 4);
  EXPECT_EQ(geometry().controlMesh->numCells(), before.numCells() + 1) << "the scene was rebuilt";
  EXPECT_GT(app_->document().project().materials.size(), samplesBefore)
      << "the new cell's Gauss points got materials";

  // 4. Ctrl+Z: the project is byte for byte what it was before the extrusion.
  pointer_ = Pointer{};
  press(GLFW_KEY_Z, true);
  frames(6, "sculpt-extrude-undone.png");
  EXPECT_EQ(serializeProject(app_->document().project()), bytesBefore);
  EXPECT_EQ(geometry().controlMesh->numCells(), before.numCells());
  EXPECT_EQ(app_->document().undoLabel(), "Paint Young's modulus");
  EXPECT_EQ(app_->document().redoLabel(), "Extrude face");
  EXPECT_TRUE(app_->document().dirty());

  // 5. Ctrl+Z again undoes the paint: uniform material everywhere again.
  press(GLFW_KEY_Z, true);
  frames(3);
  EXPECT_EQ(app_->document().project().materials.size(), 0u);
  EXPECT_FALSE(app_->document().dirty()) << "back at the state the scene was loaded in";
  EXPECT_LT(app_->model().fieldRange.high, 1.0e8);
}

// Volume of the control mesh with the control points where the simulation has them.
double deformedVolume(const CellComplex& mesh, const Points& control) {
  CellComplex deformed = mesh;
  deformed.positions = control;
  double volume = 0.0;
  for (uint32_t c = 0; c < deformed.numCells(); ++c) volume += cellVolume(deformed, c);
  return volume;
}

TEST_F(SculptSession, InflatePinCurveSaveAndOpenOnBlock3) {
  const std::string block3 = std::string(SCULPT_SOURCE_DIR) + "/assets/block3.json";
  open(block3);
  frames(30);
  ASSERT_TRUE(app_->sceneView().frame().physicsReady);
  const CellComplex mesh = *geometry().controlMesh;
  const ViewRect view = app_->viewRect();
  const ImVec2 middle(0.5f * (view.min.x + view.max.x), 0.5f * (view.min.y + view.max.y));
  ToolState& tools = app_->model().tools;

  // Inflate grows the solid while held; Ctrl deflates it below where it started.
  tools.tool = ToolKind::Inflate;
  tools.pressureFraction = kMaxPressureFraction;
  tools.brush().strength = 1.0f;
  tools.brush().radiusPixels = 150.0f;
  const double settled = deformedVolume(mesh, app_->sceneView().frame().control);
  drag(middle, 0.0f, 0.0f, 1);
  frames(25);
  const double inflated = deformedVolume(mesh, app_->sceneView().frame().control);
  release();
  frames(40);
  pointer_.ctrl = true;
  drag(middle, 0.0f, 0.0f, 1);
  frames(25);
  const double deflated = deformedVolume(mesh, app_->sceneView().frame().control);
  pointer_.ctrl = false;
  release();
  std::printf("block3 volume: settled %.5f, inflated %.5f, deflated %.5f m^3\n", settled, inflated,
              deflated);
  EXPECT_GT(inflated, settled * 1.002);
  EXPECT_LT(deflated, settled * 0.998);
  EXPECT_FALSE(app_->document().canUndo()) << "inflation is not an edit";

  // Pin paints pins onto control points under the brush (one undo entry); Ctrl unpins.
  tools.tool = ToolKind::Pin;
  tools.brush().radiusPixels = 120.0f;
  const size_t pinsBefore = app_->document().project().pins.size();
  drag(ImVec2(middle.x - 40, middle.y + 40), 80.0f, 0.0f, 6);
  release();
  frames(2);
  ASSERT_TRUE(app_->document().canUndo());
  EXPECT_EQ(app_->document().undoLabel(), "Pin");
  const size_t pinsPainted = app_->document().project().pins.size();
  EXPECT_GT(pinsPainted, pinsBefore);
  pointer_.ctrl = true;  // (starting 10 px away: a press where the last one was is a double-click)
  drag(ImVec2(middle.x - 30, middle.y + 40), 70.0f, 0.0f, 6);
  pointer_.ctrl = false;
  release();
  frames(2);
  EXPECT_EQ(app_->document().undoLabel(), "Unpin");
  EXPECT_LT(app_->document().project().pins.size(), pinsPainted);
  press(GLFW_KEY_Z, true);
  press(GLFW_KEY_Z, true);
  EXPECT_EQ(app_->document().project().pins.size(), pinsBefore);
  EXPECT_FALSE(app_->document().canUndo());
  EXPECT_TRUE(app_->document().canRedo());

  // Curve: draw across the solid, then Shift+drag it up: one spring per curve sample.
  tools.tool = ToolKind::Curve;
  drag(ImVec2(middle.x - 80, middle.y + 20), 160.0f, 0.0f, 16);
  release();
  pointer_.shift = true;
  drag(ImVec2(middle.x, middle.y + 20), 0.0f, -60.0f, 6);
  frames(10, "sculpt-curve.png");
  const size_t springs = app_->sceneView().frame().springs.size();
  EXPECT_GE(springs, 2u);
  pointer_.shift = false;
  release();
  frames(2);
  EXPECT_TRUE(app_->sceneView().frame().springs.empty());

  // Save As, then open the file in a new window: the same project, byte for byte.
  tools.tool = ToolKind::Paint;
  tools.brush().strength = 1.0f;  // paint's own brush, as strong and wide as inflate's and pin's
  tools.brush().radiusPixels = 120.0f;
  tools.mirrorX = true;
  drag(ImVec2(middle.x + 60, middle.y), 0.0f, 20.0f, 4);
  release();
  frames(2);
  ASSERT_TRUE(app_->document().dirty());
  // Damping paints too, and its field shows it.
  tools.field = PaintField::Damping;
  tools.paint.damping = 5.0e4;
  app_->model().display.field = FieldKind::Damping;
  drag(ImVec2(middle.x - 60, middle.y), 0.0f, 20.0f, 4);
  release();
  frames(2);
  EXPECT_EQ(app_->document().undoLabel(), "Paint damping");
  EXPECT_GT(app_->model().fieldRange.high, 2.0e4);
  EXPECT_LT(app_->model().fieldRange.low, 2.5e3) << "unpainted cells keep the body's 2000";
  const fs::path saved = folder_ / "block3-edit";  // the extension is added
  app_->model().requests.saveAs = saved.string();
  frames(1);
  const fs::path file = folder_ / "block3-edit.sculpt";
  ASSERT_TRUE(fs::exists(file));
  EXPECT_FALSE(app_->document().dirty());
  EXPECT_EQ(app_->document().title(), "block3-edit.sculpt");
  std::ifstream in(file, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), {});
  EXPECT_EQ(serializeProject(app_->document().project()), bytes);
  open(file.string());
  frames(3);
  EXPECT_EQ(serializeProject(app_->document().project()), bytes);
  EXPECT_FALSE(app_->document().dirty());
  EXPECT_GT(app_->document().project().materials.size(), 0u);
  EXPECT_EQ(geometry().controlMesh->numCells(), mesh.numCells());

  // Symmetry applies to topology too: extruding a face on the right extrudes its mirror image
  // on the left, in one undo entry.
  app_->model().tools.tool = ToolKind::Topology;
  app_->model().tools.operation = TopologyTool::Extrude;
  app_->model().tools.mirrorX = true;
  const glm::vec3 right = app_->camera().right();
  const Eigen::Vector3d faceCentre =
      bestFaceCentre(app_->document().project().controlMesh,
                     [&](const Eigen::Vector3d& c, const Eigen::Vector3d& n) {
                       if (std::abs(n.x()) < 0.99)
                         return std::numeric_limits<double>::quiet_NaN();  // across x
                       return n.dot(Eigen::Vector3d(right.x, right.y, right.z)) - 0.01 * c.norm();
                     });
  const ImVec2 faceAt = screen(faceCentre);
  pointer_ = Pointer{faceAt.x, faceAt.y};
  frames(2);
  pointer_.left = true;
  frames(1);
  release();
  frames(3, "sculpt-extrude-mirror.png");
  EXPECT_EQ(app_->document().project().controlMesh.numCells(), mesh.numCells() + 2);
  EXPECT_EQ(app_->document().undoLabel().rfind("Extrude", 0), 0u);
  press(GLFW_KEY_Z, true);
  EXPECT_EQ(app_->document().project().controlMesh.numCells(), mesh.numCells());
}

TEST_F(SculptSession, WorkLeftByACrashIsOfferedAndRecovered) {
  // What an autosave leaves behind when the program dies: an untitled project's recovery file.
  Project lost;
  lost.controlMesh = loadControlMeshJson(std::string(SCULPT_SOURCE_DIR) + "/assets/block3.json");
  lost.pins = {0, 1, 2, 3};
  lost.tools["scene.source"] = std::string("control");
  const fs::path recovery = folder_ / "untitled.sculpt.recovery";
  saveProject(lost, recovery);
  open({}, false);  // the interactive window (worker threads), drawn offscreen here
  framesUntil([this] { return !app_->model().document.recoveryOffer.empty(); });
  ASSERT_EQ(app_->model().document.recoveryOffer, recovery.string())
      << app_->document().recoveryPath() << " geometry " << app_->sceneView().hasGeometry();
  frames(2, "sculpt-recovery-offer.png");
  app_->model().requests.recover = true;
  frames(1);
  EXPECT_TRUE(app_->model().document.recoveryOffer.empty());
  EXPECT_TRUE(app_->document().dirty()) << "recovered work is not saved yet";
  EXPECT_TRUE(app_->document().path().empty()) << "an untitled project stays untitled";
  EXPECT_EQ(app_->document().project().pins, lost.pins);
  EXPECT_TRUE(sameControlMesh(app_->document().project().controlMesh, lost.controlMesh));
  framesUntil([this] {
    return app_->sceneView().hasGeometry() &&
           app_->sceneView().geometry()->controlMesh->numCells() == 27;
  });
  EXPECT_EQ(app_->sceneView().geometry()->controlMesh->numCells(), 27u) << "block3 is shown";

  // Ctrl+Q (over the view) and File > Quit with unsaved changes ask too, and the window stays.
  const ViewRect view = app_->viewRect();
  pointer_.x = 0.5f * (view.min.x + view.max.x), pointer_.y = 0.5f * (view.min.y + view.max.y);
  frames(1);
  press(GLFW_KEY_Q, true);
  EXPECT_TRUE(app_->model().document.closePrompt) << "Ctrl+Q asks";
  EXPECT_FALSE(glfwWindowShouldClose(window_));
  app_->model().document.closePrompt = false;
  frames(1);
  app_->model().requests.quit = true;  // the menu's Quit
  frames(1);
  EXPECT_TRUE(app_->model().document.closePrompt) << "File > Quit asks";
  EXPECT_FALSE(glfwWindowShouldClose(window_));
  app_->model().document.closePrompt = false;
  frames(1);

  // Closing with unsaved changes asks first; "Don't save" closes and removes the recovery file.
  glfwSetWindowShouldClose(window_, 1);
  frames(2, "sculpt-close-prompt.png");
  EXPECT_TRUE(app_->model().document.closePrompt);
  EXPECT_FALSE(glfwWindowShouldClose(window_)) << "the window stays until answered";
  app_->model().requests.closeDiscard = true;
  app_->model().document.closePrompt = false;
  frames(1);
  EXPECT_TRUE(glfwWindowShouldClose(window_));
  EXPECT_FALSE(fs::exists(recovery)) << "closing without saving, on purpose, keeps no recovery";
}

TEST_F(SculptSession, StrokesOfATakeAreMarkedOnTheTimelineAndSavedAsAScriptThatReRecords) {
  const std::string block3 = std::string(SCULPT_SOURCE_DIR) + "/assets/block3.json";
  open(block3);
  frames(30);
  ASSERT_TRUE(app_->sceneView().frame().physicsReady);
  const ViewRect view = app_->viewRect();
  const ImVec2 middle(0.5f * (view.min.x + view.max.x), 0.5f * (view.min.y + view.max.y));
  ToolState& tools = app_->model().tools;
  tools.mirrorX = false;

  app_->model().requests.record.toggleRecord = true;
  frames(1);
  ASSERT_TRUE(app_->recording().recording());
  // Pull, paint, inflate held still, pin, and a curve drawn (not an event) then dragged.
  tools.tool = ToolKind::Pull;
  drag(ImVec2(middle.x, middle.y - 30), 60.0f, -20.0f, 8);
  release();
  tools.tool = ToolKind::Paint;
  tools.brush().radiusPixels = 40.0f;
  drag(ImVec2(middle.x - 60, middle.y), 120.0f, 0.0f, 10);
  release();
  tools.tool = ToolKind::Inflate;
  tools.brush().radiusPixels = 120.0f;
  tools.pressureFraction = 0.01;
  drag(ImVec2(middle.x + 10, middle.y + 10), 0.0f, 0.0f, 1);
  frames(8);
  release();
  tools.tool = ToolKind::Pin;
  drag(ImVec2(middle.x - 40, middle.y + 40), 80.0f, 0.0f, 6);
  release();
  tools.tool = ToolKind::Curve;
  drag(ImVec2(middle.x - 80, middle.y + 20), 160.0f, 0.0f, 12);
  release();
  pointer_.shift = true;
  drag(ImVec2(middle.x + 3, middle.y + 20), 0.0f, -50.0f, 6);
  pointer_.shift = false;
  release();
  frames(3);
  app_->model().requests.record.toggleRecord = true;
  frames(1);
  ASSERT_FALSE(app_->recording().recording());
  ASSERT_NE(app_->recording().take(), nullptr);
  const double duration = app_->recording().take()->duration();

  // One event per grab and curve drag, and what each brush acted as, in take time.
  const SessionScript& script = app_->recording().strokes().script();
  std::map<std::string, int> types;
  double previous = 0.0;
  for (const ScriptEvent& event : script.events) {
    ++types[event.typeName()];
    EXPECT_GE(event.time, previous) << event.typeName() << " in time order";
    EXPECT_LE(event.endTime(), duration + 1e-9) << event.typeName() << " ends within the take";
    previous = event.time;
  }
  std::printf("[ captured ] take %.2f s: %d grab, %d paint, %d inflate, %d pin, %d curve\n",
              duration, types["grab"], types["paint"], types["inflate"], types["pin"],
              types["curve"]);
  EXPECT_EQ(types["grab"], 1);
  EXPECT_GE(types["paint"], 2) << "dabs along the stroke";
  EXPECT_EQ(types["inflate"], 1) << "held still: one press";
  EXPECT_GE(types["pin"], 2);
  EXPECT_EQ(types["curve"], 1);
  const auto inflate = std::find_if(
      script.events.begin(), script.events.end(),
      [](const ScriptEvent& e) { return std::holds_alternative<InflateEvent>(e.action); });
  ASSERT_NE(inflate, script.events.end());
  EXPECT_GT(std::get<InflateEvent>(inflate->action).duration, 0.05) << "held for 8 frames";
  EXPECT_EQ(app_->model().record.marks.size(), script.events.size()) << "each is marked";

  // The timeline with its marks (hovered: the tooltip counts them), and the script saved.
  const fs::path glb = folder_ / "take.glb";
  std::snprintf(app_->model().exportDialog.path.data(), app_->model().exportDialog.path.size(),
                "%s", glb.c_str());
  app_->model().requests.record.saveScript = true;
  frames(1);
  const fs::path saved = folder_ / "take_script.json";
  ASSERT_TRUE(fs::exists(saved));
  const SessionScript loaded = loadSessionScript(saved);
  EXPECT_EQ(loaded.events.size(), script.events.size());
  pointer_.x = 0.5f * (view.min.x + view.max.x), pointer_.y = 778.0f;  // over the timeline row
  frames(3, "record-strokes-timeline.png");

  // Replayed and re-recorded from the command line.
  const fs::path cache = folder_ / "again.pc2", log = folder_ / "again.txt";
  char seconds[32];
  std::snprintf(seconds, sizeof seconds, "%.3f", duration);
  const std::string command = std::string(SCULPT_BINARY_DIR) + "/bin/sculpt-cli record " + block3 +
                              " --script " + saved.string() + " --seconds " + seconds + " --out " +
                              cache.string() + " > " + log.string() + " 2>&1";
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  std::ifstream in(log);
  std::string line, last;
  while (std::getline(in, line)) last = line;
  std::printf("[ re-recorded ] %s\n", last.c_str());
  EXPECT_EQ(last.rfind("frames=", 0), 0u) << last;
  EXPECT_TRUE(fs::exists(cache));
}

TEST_F(SculptSession, OpeningAProjectOffersItsNewerRecoveryFile) {
  Project saved;
  saved.controlMesh = loadControlMeshJson(std::string(SCULPT_SOURCE_DIR) + "/assets/block3.json");
  saved.tools["scene.source"] = std::string("control");
  const fs::path file = folder_ / "work.sculpt";
  saveProject(saved, file);
  Project autosaved = saved;
  autosaved.pins = {7, 8};
  saveProject(autosaved, recoveryPathFor(file));
  open(file.string(), false);
  EXPECT_EQ(app_->model().document.recoveryOffer, recoveryPathFor(file).string());
  EXPECT_FALSE(app_->document().dirty());
  app_->model().requests.recover = true;
  frames(1);
  EXPECT_EQ(app_->document().path(), file) << "recovered into its own file";
  EXPECT_TRUE(app_->document().dirty());
  EXPECT_EQ(app_->document().project().pins, autosaved.pins);
}

}  // namespace
}  // namespace sculpt::app
