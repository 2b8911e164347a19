#pragma once
// Phase 2 of a scene build ("physics") and the running simulation: the FEM model of the solid
// at level K, the simulator with the top layer pinned and gravity, and after every step the
// state the window draws (SceneFrame): level-K node positions and node gradients for the GPU
// Phong deformer, the control points, and per-cell fields.
//
// Frame node positions are the rest nodes plus the node displacements A (p - p_rest), so the rest
// state gives the rest nodes of SceneGeometry exactly.

#include <cstdint>
#include <future>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "scene/scene_builder.h"
#include "project/project.h"
#include "scene/material_picker.h"
#include "scene/scene_surface_map.h"
#include "tools/material_brush.h"
#include "tools/session_script.h"
#include "tools/tool.h"
#include "fem/fem_model.h"
#include "sim/simulator.h"

namespace sculpt {

/// A simulation state for the window, O(nodes + cells).
struct SceneFrame {
  uint64_t version = 0;  ///< increases with every frame the controller publishes
  uint64_t sceneId = 0;  ///< the SceneGeometry it belongs to
  Points nodes;          ///< #cellMesh nodes by 3
  /// Per cellMesh node (PhongGpuDeformer::setFrame), by kDefaultGradientScheme; a view showing
  /// another scheme applies SceneGeometry::gradientStencil(scheme) to `nodes` itself.
  std::vector<Eigen::Matrix3d> gradients;
  Points control;        ///< #control points by 3
  /// Per cellMesh cell, from its FEM element: mean Young's modulus (Pa), density (kg/m^3) and
  /// damping (kg/(m^3 s)), and strain energy density (J/m^3) in this state.
  std::vector<float> cellYoungs, cellDensity, cellStrainEnergy, cellDamping;
  double simulatedTime = 0.0;  ///< seconds since the last reset
  double stepMs = 0.0;         ///< wall time of the last step with this frame's update
  uint64_t steps = 0;          ///< steps since the physics was built, its first step included
  double stepMsTotal = 0.0;    ///< the wall times (as stepMs) of those steps, summed
  StepReport lastStep;
  bool physicsReady = false;   ///< false: the rest shape while phase 2 runs
  /// Springs of the strokes acting now (tools/tool.h; a curve's are not labelled: force NaN).
  std::vector<ToolSpring> springs;
  /// The solid's weight, total mass x 9.81 m/s^2 (N), while `springs` is not empty: pull
  /// forces are labelled in units of it.
  double weight = 0.0;
};

/// The rest frame of a geometry before its physics exists: rest nodes, identity gradients, rest
/// control points, the uniform `material`'s fields and no strain energy.
SceneFrame restFrame(const SceneGeometry& geometry, const Material& material);

class ScenePhysics : private ToolContext {
 public:
  /// Phase 2: the elements, the simulator (top layer pinned, gravity, settings) and one first
  /// step (which factorises the implicit solver's preconditioner). Stage times are appended to
  /// `stageMs`. Returns null when cancelled through `progress`; throws std::runtime_error with a
  /// sentence when the solid cannot be simulated (an inverted element, say). `stencilsReady`,
  /// when valid: the geometry's gradient stencils are still being made on another thread
  /// (scene_builder.h); the first step waits for them before it finds its state.
  static std::unique_ptr<ScenePhysics> build(std::shared_ptr<const SceneGeometry> geometry,
                                             std::shared_ptr<const SceneSolid> solid,
                                             const SceneSettings& settings,
                                             ProgressReporter* progress, StageTimes* stageMs,
                                             std::shared_future<void> stencilsReady = {});
  ~ScenePhysics();
  ScenePhysics(const ScenePhysics&) = delete;
  ScenePhysics& operator=(const ScenePhysics&) = delete;

  const SceneGeometry& geometry() const { return *geometry_; }
  const std::shared_ptr<const SceneGeometry>& sharedGeometry() const { return geometry_; }
  /// Control points to drawn nodes, shareable beyond this physics' life (scene_surface_map.h).
  const std::shared_ptr<const SceneSurfaceMap>& surfaceMap() const { return surfaceMap_; }
  FemModel& model() { return *model_; }
  Simulator& simulator() override { return *simulator_; }

  /// Advances by one time step and updates the state.
  StepReport step();
  /// Back to rest: rest positions, zero velocity, simulated time 0.
  void reset();
  /// Replays a session script (core/tools/session_script.h) from now on, in place of one in
  /// progress; reset() ends it. Throws std::invalid_argument when a grab point cannot be located.
  void playScript(const SessionScript& script);
  /// The script's log lines since the last call ("events[0] (grab) started ..."); none without one.
  std::vector<std::string> takeScriptLog() {
    return player_ ? player_->takeLog() : std::vector<std::string>{};
  }
  /// Strokes of any tool (tools/tool.h), named by the caller's id: begin throws
  /// std::invalid_argument with a sentence when the stroke cannot start (nothing changes then);
  /// update and end of an unknown id (ended, or dropped by reset()) do nothing. A tool that
  /// still holds loads after its end (a kept pull spring) stays until reset().
  void beginStroke(uint64_t id, std::unique_ptr<Tool> tool, const ToolInput& input);
  void updateStroke(uint64_t id, const ToolInput& input);
  void endStroke(uint64_t id, const ToolInput& input);
  /// The springs of the strokes acting now (a script's included, id 0), with their stroke ids.
  void strokeSprings(std::vector<std::pair<uint64_t, ToolSpring>>& out) const;
  /// The edited state as a project keeps it: painted materials (captureMaterials at level K) and
  /// the pinned control points (ascending).
  MaterialSamples captureMaterialSamples() const;
  std::vector<uint32_t> pinnedPoints() const;
  /// Undo/redo: sets the materials (resampled by position; empty samples: `uniform` everywhere)
  /// and the pins. Returns a sentence when they cannot be applied (nothing changes then).
  std::string restoreEdits(const MaterialSamples& samples, const std::vector<uint32_t>& pins,
                           const Material& uniform);
  /// Applies what can change live (material, integrator, time step, gravity). Returns a sentence
  /// when a setting is invalid (nothing is changed then).
  std::string applyLive(const SceneSettings& settings);
  /// Fills `frame` with the current state (all but version); its strain energy only while it
  /// is wanted (zeros otherwise).
  void fillFrame(SceneFrame& frame) const;
  /// Whether each step also finds the strain energy density for the frames: an element pass,
  /// about a tenth of a step, spent only while the field is on show. Off at first.
  void setStrainEnergyWanted(bool wanted) { strainEnergyWanted_ = wanted; }

  /// Per FEM element: strain energy density (J/m^3) in the current state (found now if the steps
  /// did not) and rest volume (m^3).
  const std::vector<double>& elementStrainEnergyDensity() const;
  const std::vector<double>& elementVolume() const { return elementVolume_; }
  /// Per cell-mesh cell, the painted material's mean Young's modulus, density and damping (as
  /// SceneFrame's cell fields); materialVersion() changes whenever they do.
  void cellMaterialFields(std::vector<float>& youngs, std::vector<float>& density,
                          std::vector<float>& damping) const;
  uint64_t materialVersion() const { return materialVersion_; }
  double simulatedTime() const;

 private:
  // A step; before its state is found, waits for `stateInputs` when valid.
  StepReport stepAfter(const std::shared_future<void>& stateInputs);
  ScenePhysics() = default;
  void setGravity(const Eigen::Vector3d& gravity);
  // ToolContext
  const MaterialPointLocator& locator() override;
  std::optional<Eigen::Vector3d> restPointAt(const Eigen::Vector3d& world) override;
  void materialsChanged() override;

  void updateState();          // nodes, gradients, strain energy from the simulator's state
  void findStrainEnergy() const;  // elementEnergy_ and its density at the current rotations
  void updateMaterialFields();  // per-element mean E and density

  std::shared_ptr<const SceneGeometry> geometry_;
  std::shared_ptr<const SceneSolid> solid_;
  std::shared_ptr<const SceneSurfaceMap> surfaceMap_;
  uint64_t materialVersion_ = 0;
  std::unique_ptr<FemModel> model_;
  std::unique_ptr<Simulator> simulator_;
  Form* gravityLoad_ = nullptr;
  SceneSettings applied_;  // the live settings in force
  double timeOrigin_ = 0.0;
  StepReport lastStep_;
  double lastStepMs_ = 0.0;
  uint64_t stepCount_ = 0;
  double stepMsTotal_ = 0.0;

  std::optional<MaterialPointLocator> locator_;
  std::unique_ptr<MaterialPicker> picker_;  // over nodes_, made on the first pick after a change
  // Strokes and the script (after the simulator: their loads go first)
  std::unique_ptr<ScriptPlayer> player_;
  std::vector<std::pair<uint64_t, std::unique_ptr<Tool>>> strokes_, retained_;

  Points femNodes_, nodes_;
  std::vector<Eigen::Matrix3d> gradients_;
  std::vector<double> elementVolume_;
  bool strainEnergyWanted_ = false;
  mutable bool strainEnergyStale_ = true;
  mutable std::vector<double> elementEnergy_, elementEnergyDensity_;
  std::vector<double> elementYoungs_, elementDensity_, elementDamping_;
};

}  // namespace sculpt
