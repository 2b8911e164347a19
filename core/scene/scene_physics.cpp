#include "scene/scene_physics.h"

#include "sim/material_point.h"

#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "scene/build_progress.h"
#include "sim/standard_forms.h"
#include "tools/pin_tool.h"

namespace sculpt {
namespace {

// Per cellMesh cell, the value of its element.
void toCells(const SceneGeometry& geometry, const std::vector<double>& perElement,
             std::vector<float>& perCell) {
  perCell.resize(geometry.cellElement.size());
  for (size_t c = 0; c < perCell.size(); ++c)
    perCell[c] = static_cast<float>(perElement[geometry.cellElement[c]]);
}

}  // namespace

SceneFrame restFrame(const SceneGeometry& geometry, const Material& material) {
  SceneFrame frame;
  frame.sceneId = geometry.sceneId;
  frame.nodes = geometry.cellMesh.positions;
  frame.gradients.assign(geometry.cellMesh.numNodes(), Eigen::Matrix3d::Identity());
  frame.control = geometry.restControl;
  const size_t cells = geometry.cellMesh.numCells();
  frame.cellYoungs.assign(cells, static_cast<float>(material.youngs));
  frame.cellDensity.assign(cells, static_cast<float>(material.density));
  frame.cellDamping.assign(cells, static_cast<float>(material.damping));
  frame.cellStrainEnergy.assign(cells, 0.0f);
  return frame;
}

ScenePhysics::~ScenePhysics() = default;

std::unique_ptr<ScenePhysics> ScenePhysics::build(std::shared_ptr<const SceneGeometry> geometry,
                                                  std::shared_ptr<const SceneSolid> solid,
                                                  const SceneSettings& settings,
                                                  ProgressReporter* progress, StageTimes* stageMs,
                                                  std::shared_future<void> stencilsReady) {
  StageTimes times;
  StageClock clock(times);
  std::unique_ptr<ScenePhysics> physics(new ScenePhysics);
  physics->geometry_ = std::move(geometry);
  physics->solid_ = std::move(solid);
  const SceneGeometry& g = *physics->geometry_;

  // Elements
  BuildStage elements(progress, 0.09, 0.2, "building the elements");
  if (!elements.start()) return nullptr;
  FemSetup setup;
  setup.level = settings.level;
  setup.material = settings.material;
  std::string error;
  std::optional<FemModel> model =
      FemModel::create(physics->solid_->control, setup, &error, elements.reporter());
  if (!model) {
    if (error.empty()) return nullptr;  // cancelled
    throw std::runtime_error("cannot simulate " + g.description + ": " + error);
  }
  physics->model_ = std::make_unique<FemModel>(std::move(*model));
  physics->surfaceMap_ = std::make_shared<const SceneSurfaceMap>(
      physics->geometry_, physics->solid_, physics->model_->subdivision().chain);
  const FemMesh& mesh = physics->model_->mesh();
  // The element plan of phase 1 must be the FEM's.
  const ElementCounts counts = mesh.counts();
  bool planMatches = counts.tricubic == g.elementCounts[0] &&
                     counts.trilinear == g.elementCounts[1] && counts.pyramid == g.elementCounts[2];
  for (size_t c = 0; planMatches && c < g.cellElement.size(); ++c)
    planMatches = g.cellElement[c] < mesh.numElements() &&
                  static_cast<uint8_t>(mesh.elementType[g.cellElement[c]]) == g.cellKind[c];
  if (!planMatches)
    throw std::logic_error("the element kinds drawn do not match the FEM elements of " +
                           g.description);
  physics->elementVolume_.assign(mesh.numElements(), 0.0);
  for (uint32_t e = 0; e < mesh.numElements(); ++e)
    for (uint32_t q = mesh.gaussBegin(e); q < mesh.gaussBegin(e) + mesh.gaussCount(e); ++q)
      physics->elementVolume_[e] += mesh.gaussVolume[q];
  clock.lap("elements");

  // Simulator: pins, gravity, settings
  BuildStage simulator(progress, 0.2, 0.21, "preparing the simulator");
  if (!simulator.start()) return nullptr;
  SimulationSettings simulation;
  simulation.integrator = settings.integrator;
  simulation.elasticModel = settings.elasticModel;
  simulation.timeStep = settings.timeStep;
  physics->simulator_ = std::make_unique<Simulator>(*physics->model_, simulation);
  for (uint32_t v = 0; v < g.pinned.size(); ++v)
    if (g.pinned[v]) physics->simulator_->setFixed(v, true);
  physics->setGravity(settings.gravity);
  physics->applied_ = settings;
  if (const Project* project = physics->solid_->project.get();
      project && project->materials.size()) {
    // The painted materials of the project, by position (exact when the level is the same).
    const std::string problem =
        physics->restoreEdits(project->materials, project->pins, settings.material);
    if (!problem.empty())
      throw std::runtime_error("cannot restore the painted materials: " + problem);
  }
  physics->updateMaterialFields();
  clock.lap("simulator");

  // The first step (the implicit integrator factorises its preconditioner here)
  BuildStage first(progress, 0.21, 1.0, "first step");
  if (!first.start()) return nullptr;
  physics->stepAfter(stencilsReady);
  clock.lap("first step");
  if (stageMs) stageMs->insert(stageMs->end(), times.begin(), times.end());
  return physics;
}

void ScenePhysics::setGravity(const Eigen::Vector3d& gravity) {
  if (gravityLoad_) simulator_->removeLoad(gravityLoad_);
  gravityLoad_ = nullptr;
  if (gravity.squaredNorm() > 0.0)
    gravityLoad_ = simulator_->addLoad(std::make_unique<GravityForm>(*model_, gravity));
}

double ScenePhysics::simulatedTime() const { return simulator_->time() - timeOrigin_; }

StepReport ScenePhysics::step() { return stepAfter({}); }

StepReport ScenePhysics::stepAfter(const std::shared_future<void>& stateInputs) {
  const auto start = std::chrono::steady_clock::now();
  lastStep_ = player_ ? player_->step() : simulator_->step();
  if (stateInputs.valid()) stateInputs.get();
  updateState();
  lastStepMs_ =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  ++stepCount_;
  stepMsTotal_ += lastStepMs_;
  return lastStep_;
}

// ---------------------------------------------------------------------------------------------
// Strokes

void ScenePhysics::beginStroke(uint64_t id, std::unique_ptr<Tool> tool, const ToolInput& input) {
  tool->begin(*this, input);
  strokes_.emplace_back(id, std::move(tool));
}

void ScenePhysics::updateStroke(uint64_t id, const ToolInput& input) {
  for (auto& [strokeId, tool] : strokes_)
    if (strokeId == id) tool->update(*this, input);
}

void ScenePhysics::endStroke(uint64_t id, const ToolInput& input) {
  for (auto it = strokes_.begin(); it != strokes_.end(); ++it) {
    if (it->first != id) continue;
    std::unique_ptr<Tool> tool = std::move(it->second);
    strokes_.erase(it);
    tool->end(*this, input);
    if (tool->holdsLoads()) retained_.emplace_back(id, std::move(tool));
    return;
  }
}

void ScenePhysics::strokeSprings(std::vector<std::pair<uint64_t, ToolSpring>>& out) const {
  std::vector<ToolSpring> springs;
  for (const auto& [id, tool] : strokes_) {
    springs.clear();
    tool->springs(*simulator_, springs);
    for (const ToolSpring& spring : springs) out.emplace_back(id, spring);
  }
  if (player_) {
    springs.clear();
    player_->springs(springs);
    for (const ToolSpring& spring : springs) out.emplace_back(0, spring);
  }
}

const MaterialPointLocator& ScenePhysics::locator() {
  if (!locator_) locator_.emplace(model_->mesh());
  return *locator_;
}

std::optional<Eigen::Vector3d> ScenePhysics::restPointAt(const Eigen::Vector3d& world) {
  if (!picker_) picker_ = std::make_unique<MaterialPicker>(geometry_->cellMesh, nodes_);
  return picker_->restPoint(world, 0.5 * solid_->cellSize);
}

void ScenePhysics::materialsChanged() {
  updateMaterialFields();
  updateState();
}

MaterialSamples ScenePhysics::captureMaterialSamples() const {
  return captureMaterials(model_->mesh(), applied_.level);
}

std::vector<uint32_t> ScenePhysics::pinnedPoints() const {
  std::vector<uint32_t> pins;
  const std::vector<uint8_t>& fixed = simulator_->fixedMask();
  for (uint32_t v = 0; v < fixed.size(); ++v)
    if (fixed[v]) pins.push_back(v);
  return pins;
}

std::string ScenePhysics::restoreEdits(const MaterialSamples& samples,
                                       const std::vector<uint32_t>& pins, const Material& uniform) {
  const uint32_t points = model_->numControlPoints();
  for (const uint32_t v : pins)
    if (v >= points) return "pin " + std::to_string(v) + " is not a control point";
  const MaterialSamples here = captureMaterials(model_->mesh(), applied_.level);
  const std::vector<Material> materials =
      resampleMaterials(samples, here.restPositions, uniform);
  std::string problem;
  if (!model_->setMaterials(materials, &problem)) return problem;
  std::vector<uint8_t> wanted(points, 0);
  for (const uint32_t v : pins) wanted[v] = 1;
  for (uint32_t v = 0; v < points; ++v)
    if ((simulator_->fixedMask()[v] != 0) != (wanted[v] != 0)) simulator_->setFixed(v, wanted[v]);
  if (!elementVolume_.empty()) {
    updateMaterialFields();
    updateState();
  }
  return {};
}

void ScenePhysics::playScript(const SessionScript& script) {
  player_.reset();  // the loads of a script in progress go first
  player_ = std::make_unique<ScriptPlayer>(*simulator_, script, static_cast<ToolContext*>(this));
}

void ScenePhysics::reset() {
  player_.reset();  // its loads go with it
  for (auto* strokes : {&strokes_, &retained_}) {
    for (auto& stroke : *strokes) stroke.second->clear();
    strokes->clear();
  }
  const Points zero = Points::Zero(model_->numControlPoints(), 3);
  simulator_->setState(model_->restControl(), zero);
  timeOrigin_ = simulator_->time();
  lastStep_ = StepReport{};
  updateState();
}

std::string ScenePhysics::applyLive(const SceneSettings& settings) {
  if (std::string problem = sceneSettingsProblem(settings); !problem.empty()) return problem;
  bool changed = false;
  if (settings.integrator != applied_.integrator || settings.timeStep != applied_.timeStep ||
      settings.elasticModel != applied_.elasticModel) {
    SimulationSettings simulation = simulator_->settings();
    simulation.integrator = settings.integrator;
    simulation.elasticModel = settings.elasticModel;
    simulation.timeStep = settings.timeStep;
    if (std::string problem = simulator_->setSettings(simulation); !problem.empty()) return problem;
    changed = true;
  }
  if (settings.material != applied_.material) {
    std::string problem;
    if (model_->paintMaterial(Eigen::Vector3d::Zero(), std::numeric_limits<double>::infinity(),
                              settings.material, &problem) < 0)
      return problem;
    updateMaterialFields();
    changed = true;
  }
  if (settings.gravity != applied_.gravity) {
    setGravity(settings.gravity);
    changed = true;
  }
  applied_ = settings;
  if (changed) updateState();
  return {};
}

void ScenePhysics::cellMaterialFields(std::vector<float>& youngs, std::vector<float>& density,
                                      std::vector<float>& damping) const {
  toCells(*geometry_, elementYoungs_, youngs);
  toCells(*geometry_, elementDensity_, density);
  toCells(*geometry_, elementDamping_, damping);
}

void ScenePhysics::updateMaterialFields() {
  ++materialVersion_;
  // Volume-weighted means over each element's Gauss points.
  const FemMesh& mesh = model_->mesh();
  elementYoungs_.assign(mesh.numElements(), 0.0);
  elementDensity_.assign(mesh.numElements(), 0.0);
  elementDamping_.assign(mesh.numElements(), 0.0);
  for (uint32_t e = 0; e < mesh.numElements(); ++e) {
    double youngs = 0.0, density = 0.0, damping = 0.0;
    for (uint32_t q = mesh.gaussBegin(e); q < mesh.gaussBegin(e) + mesh.gaussCount(e); ++q) {
      youngs += mesh.gaussVolume[q] * mesh.gaussMaterial[q].youngs;
      density += mesh.gaussVolume[q] * mesh.gaussMaterial[q].density;
      damping += mesh.gaussVolume[q] * mesh.gaussMaterial[q].damping;
    }
    elementYoungs_[e] = youngs / elementVolume_[e];
    elementDensity_[e] = density / elementVolume_[e];
    elementDamping_[e] = damping / elementVolume_[e];
  }
}

void ScenePhysics::updateState() {
  // Node displacements A (p - p_rest): the rest state gives the rest nodes exactly.
  Points displacement;
  model_->nodesFromControl(simulator_->positions() - model_->restControl(), displacement);
  femNodes_ = model_->mesh().restNodes + displacement;
  surfaceMap_->cellNodesFromDisplacement(displacement, nodes_);
  applyNodeGradientStencil(geometry_->gradientStencil(kDefaultGradientScheme), nodes_, gradients_);
  picker_.reset();
  strainEnergyStale_ = true;
  if (strainEnergyWanted_) findStrainEnergy();
}

void ScenePhysics::findStrainEnergy() const {
  // In this state's frames, found for the query alone, so that the motion does not depend on
  // whether the field is shown. (The step finds its own rotations at its predicted state; a
  // pass over every element after each step cost 3-5% of one.)
  ElasticKernel& kernel = model_->elastic();
  const ElasticKernel::WarmStartKept kept(kernel);
  kernel.updateRotations(femNodes_);
  kernel.elementEnergies(femNodes_, elementEnergy_);
  elementEnergyDensity_.resize(elementEnergy_.size());
  for (size_t e = 0; e < elementEnergy_.size(); ++e)
    elementEnergyDensity_[e] = elementEnergy_[e] / elementVolume_[e];
  strainEnergyStale_ = false;
}

const std::vector<double>& ScenePhysics::elementStrainEnergyDensity() const {
  if (strainEnergyStale_) findStrainEnergy();
  return elementEnergyDensity_;
}

void ScenePhysics::fillFrame(SceneFrame& frame) const {
  const SceneGeometry& g = *geometry_;
  frame.sceneId = g.sceneId;
  frame.nodes = nodes_;
  frame.gradients = gradients_;
  frame.control = simulator_->positions();
  cellMaterialFields(frame.cellYoungs, frame.cellDensity, frame.cellDamping);
  if (strainEnergyWanted_) toCells(g, elementStrainEnergyDensity(), frame.cellStrainEnergy);
  else frame.cellStrainEnergy.assign(g.cellElement.size(), 0.0f);
  frame.simulatedTime = simulatedTime();
  frame.stepMs = lastStepMs_;
  frame.steps = stepCount_;
  frame.stepMsTotal = stepMsTotal_;
  frame.lastStep = lastStep_;
  frame.physicsReady = true;
  frame.springs.clear();
  std::vector<std::pair<uint64_t, ToolSpring>> springs;
  strokeSprings(springs);
  for (const auto& spring : springs) frame.springs.push_back(spring.second);
  frame.weight = frame.springs.empty() ? 0.0 : 9.81 * model_->totalMass();
}

}  // namespace sculpt
