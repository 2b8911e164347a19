// One scene pipeline: `sculpt-cli simulate SCENE --script S --steps N --out A.vtk` and
// `sculpt --headless --scene SCENE --script S --frames N --out B.vtk` build the same scene, apply
// the same script through the same tools and write the same control points: for a surface caged
// as the window cages it (the bunny) and for a saved project with painted material and pins.
// They agree bit for bit: the same scene, settings and script give the same steps (and a progress
// line, which asks for the elastic energy, no longer disturbs the next step's rotations).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

#include "fem/fem_model.h"
#include "io/control_mesh_json.h"
#include "project/project_file.h"
#include "scene/scene_file.h"
#include "tools/material_brush.h"

namespace sculpt {
namespace {

namespace fs = std::filesystem;

const std::string kSculpt = SCULPT_BINARY_DIR "/bin/sculpt";
const std::string kCli = SCULPT_BINARY_DIR "/bin/sculpt-cli";
const std::string kAssets = SCULPT_SOURCE_DIR "/assets/";

std::vector<double> vtkPoints(const fs::path& path) {
  std::ifstream in(path);
  std::string word;
  while (in >> word && word != "POINTS") {}
  size_t n = 0;
  in >> n >> word;
  std::vector<double> values(3 * n);
  for (double& v : values) in >> v;
  return in ? values : std::vector<double>{};
}

class SameScene : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_NE(std::getenv("DISPLAY"), nullptr) << "run the GUI tests under xvfb-run";
    dir_ = fs::temp_directory_path() / ("sculpt_same_scene_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  int run(const std::string& command) const {
    return std::system(("XDG_CONFIG_HOME=" + dir_.string() + " " + command + " > " +
                        (dir_ / "out.txt").string() + " 2>&1").c_str());
  }
  // Runs both programs on `scene` and returns the largest coordinate difference and the largest
  // displacement from rest of the CLI's result.
  void compare(const std::string& scene, const std::string& script, int steps, double size) {
    const fs::path a = dir_ / "cli.vtk", b = dir_ / "window.vtk";
    ASSERT_EQ(run(kCli + " simulate " + scene + " --dt 0.0166667 --steps " + std::to_string(steps) +
                  " --script " + script + " --out " + a.string()), 0);
    ASSERT_EQ(
        run(kSculpt + " --headless --size 320x200 --scene " + scene + " --dt 0.0166667 --script " +
            script + " --frames " + std::to_string(steps) + " --out " + b.string()),
        0);
    const std::vector<double> cli = vtkPoints(a), window = vtkPoints(b);
    ASSERT_FALSE(cli.empty());
    ASSERT_EQ(cli.size(), window.size());
    double difference = 0.0;
    for (size_t i = 0; i < cli.size(); ++i)
      difference = std::max(difference, std::abs(cli[i] - window[i]));
    std::printf(
        "[ measured ] %s: %zu control points, max |cli - window| = %.3g m (model size %.3g m)\n",
        scene.c_str(), cli.size() / 3, difference, size);
    (void)size;
    EXPECT_EQ(difference, 0.0);
    EXPECT_EQ(cli, window) << "bit for bit";
  }
  fs::path dir_;
};

TEST_F(SameScene, ACagedSurfaceGivesTheSameControlPointsInTheCliAndTheWindow) {
  const fs::path script = dir_ / "s.json";
  std::ofstream(script) << R"({"format": "sculpt-session", "version": 1, "events": [
    {"t": 0, "type": "paint", "centre": [0, 3, 0], "radius": 2.0, "youngs": 3e7, "mirror": "x"},
    {"t": 0, "type": "grab", "point": [0, 4, 0], "path": [[0, 0, 4, 0], [0.3, 2, 4, 1]], "release": 0.4},
    {"t": 0.1, "type": "inflate", "centre": [0, 6, 0], "radius": 2.0, "pressure": 3e4, "duration": 0.2},
    {"t": 0.2, "type": "curve", "points": [[-2, 2, 0], [2, 2, 0]], "path": [[0, 0, 0, 0], [0.2, 0, 0, 1]],
     "profile": "smooth", "release": 0.3},
    {"t": 0.3, "type": "pin", "centre": [0, 1, 0], "radius": 1.5}]})";
  compare(kAssets + "bunny.obj", script.string(), 30, 20.0);
}

TEST_F(SameScene, AProjectWithPaintAndPinsGivesTheSameControlPointsInTheCliAndTheWindow) {
  // A project as the window saves it: block3 with a stiff painted corner and the bottom pinned.
  Project project;
  project.controlMesh = loadControlMeshJson(kAssets + "block3.json");
  project.tools[kSceneSourceKey] = std::string("control");
  FemSetup setup;
  setup.level = 1;
  std::string error;
  std::optional<FemModel> model = FemModel::create(project.controlMesh, setup, &error);
  ASSERT_TRUE(model) << error;
  MaterialBrushSettings brush;
  brush.radius = 1.2;
  brush.target.youngs = 5e7;
  brush.mirror.x = false;
  paintDab(*model, Eigen::Vector3d(3, 3, 3), brush);
  project.materials = captureMaterials(model->mesh(), 1);
  for (uint32_t v = 0; v < project.controlMesh.numVertices(); ++v)
    if (project.controlMesh.positions(v, 1) < 0.01) project.pins.push_back(v);
  project.simulation.level = 1;
  const fs::path file = dir_ / "block.sculpt";
  saveProject(project, file);
  const fs::path script = dir_ / "s.json";
  std::ofstream(script) << R"({"format": "sculpt-session", "version": 1, "events": [
    {"t": 0, "type": "grab", "point": [1.5, 3, 1.5], "path": [[0, 1.5, 3, 1.5], [0.5, 2.5, 4, 1.5]]},
    {"t": 0.2, "type": "paint", "centre": [0, 3, 0], "radius": 1.0, "density": 5000, "mirror": "none"}]})";
  compare(file.string(), script.string(), 60, 3.0);
}

}  // namespace
}  // namespace sculpt
