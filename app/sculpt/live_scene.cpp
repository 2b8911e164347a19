#include "sculpt/live_scene.h"

#include <chrono>
#include <stdexcept>

#include <Eigen/Geometry>

#include "embed/gradient_weights.h"
#include "embed/recomputed_normals.h"
#include "embed/surface_cage.h"
#include "io/surface_file.h"
#include "sim/standard_forms.h"
#include "subdiv/loop_surface.h"

namespace sculpt::app {

std::unique_ptr<LiveScene> LiveScene::buildDefault(const std::string& sourceDir) {
  std::unique_ptr<LiveScene> scene(new LiveScene);
  const SurfaceMesh bunny = readSurfaceFile(sourceDir + "/assets/bunny.obj").surface();

  // Display surface: Loop-refined twice onto the limit surface, one normal per vertex.
  const SurfaceMesh display = loopRefine(bunny, 2, true);
  scene->restNormals_ = vertexNormals(display);
  scene->restPositions_ = display.positions;
  for (const SurfaceCorner& corner : display.faces.values)
    scene->triangles_.push_back(corner.position);

  // A coarse cage (about 6 cells along the longest side) simulated at level 1.
  const Eigen::Vector3d lo = bunny.positions.colwise().minCoeff().transpose();
  const Eigen::Vector3d hi = bunny.positions.colwise().maxCoeff().transpose();
  CageSettings cageSettings;
  cageSettings.cellSize = (hi - lo).maxCoeff() / 6.0;
  const Cage cage = buildSurfaceCage(bunny, cageSettings);
  FemSetup setup;
  setup.level = 1;
  setup.material.youngs = 3.0e6;
  setup.material.poisson = 0.3;
  setup.material.density = 1000.0;
  setup.material.damping = 20.0;
  std::string error;
  scene->model_ = FemModel::create(cage.control, setup, &error);
  if (!scene->model_) throw std::runtime_error("cannot build the bunny's solid: " + error);
  scene->simulator_ = std::make_unique<Simulator>(*scene->model_);
  // Pin the bottom layer of control points; gravity along -y (the bunny's up is +y).
  const double lowest = cage.control.positions.col(1).minCoeff();
  Eigen::AlignedBox3d bottom(Eigen::Vector3d(-1e9, lowest - 1e-6, -1e9),
                             Eigen::Vector3d(1e9, lowest + 0.5 * cage.cellSize, 1e9));
  scene->simulator_->fixInBox(bottom);
  scene->simulator_->addLoad(
      std::make_unique<GravityForm>(*scene->model_, Eigen::Vector3d(0.0, -9.81, 0.0)));

  // The level-1 cells as the embedding mesh, and the node-gradient stencil of Phong deformation.
  const Subdivision& subdivision = scene->model_->subdivision();
  scene->solid_ = solidCellMesh(subdivision.finest(), subdivision.finestTopology());
  scene->embedding_ = embedPoints(scene->solid_.mesh, scene->restPositions_);
  scene->stencil_ = nodeGradientStencil(scene->solid_.mesh, cellGradientOperator(scene->solid_.mesh),
                                        cellToNodeWeights(scene->solid_.mesh));
  scene->updateNodes();
  return scene;
}

uint32_t LiveScene::numElements() const { return model_->mesh().numElements(); }

void LiveScene::updateNodes() {
  model_->nodesFromControl(simulator_->positions(), femNodes_);
  const uint32_t vertices = model_->subdivision().finest().numVertices();
  nodes_ = solid_.nodePositions(femNodes_.topRows(vertices));
  applyNodeGradientStencil(stencil_, nodes_, gradients_);
}

StepReport LiveScene::step() {
  const auto start = std::chrono::steady_clock::now();
  const StepReport report = simulator_->step();
  updateNodes();
  lastStepMs_ =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return report;
}

}  // namespace sculpt::app
