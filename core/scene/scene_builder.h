#pragma once
// The window's scenes and phase 1 of their build ("display"): the detailed surface to draw, the
// solid it is embedded in at simulation level K, and everything the renderer needs to draw the
// rest shape. Phase 2 (scene_physics.h) makes the solid simulate; scene_controller.h runs both.
//
// Scene sources:
//  - DefaultBunny: assets/bunny.obj Loop-refined three times onto its limit surface (about 235k
//    triangles) in a hexahedral cage (surface_cage.h) of about cageCellsAcross cells along its
//    longest side.
//  - ImportedSurface: an OBJ or glTF surface displayed as is (polygons fanned into triangles) in
//    such a cage.
//  - ControlMesh: a control-mesh JSON file; the surface is its own boundary surface,
//    Catmull–Clark refined to renderLevel onto the limit (with its crease and corner tags); the
//    solid is the control mesh itself.
// The control points of the top layer (within half a cell of the highest one, along y) are
// pinned, and gravity pulls along -y: the bunny hangs by its ears and moves at once. A source
// with a project takes its control mesh, pins and materials from the project instead.

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "embed/deformation_gradients.h"
#include "embed/gradient_scheme.h"
#include "embed/embedding.h"
#include "embed/solid_cell_mesh.h"
#include "fem/material.h"
#include "mesh/cell_complex.h"
#include "mesh/surface_mesh.h"
#include "mesh/volume_mesh.h"
#include "project/project.h"
#include "sim/simulator.h"
#include "util/progress.h"

namespace sculpt {

enum class SceneKind { DefaultBunny, ImportedSurface, ControlMesh };

struct SceneSource {
  SceneSource() = default;
  SceneSource(SceneKind kind_, std::string path_, std::shared_ptr<const Project> project_ = nullptr)
      : kind(kind_), path(std::move(path_)), project(std::move(project_)) {}

  SceneKind kind = SceneKind::DefaultBunny;
  std::string path;  ///< the surface or control-mesh file; DefaultBunny: empty for assets/bunny.obj
  /// The user's work (an edited or opened project): when set, its control mesh, pins and painted
  /// materials replace the cage or file's and the top-layer pins. The drawn surface still comes
  /// from `kind` and `path` (ControlMesh: the boundary of the project's control mesh).
  std::shared_ptr<const Project> project;
};

/// Timings of a build, in order: stage name and milliseconds (steady clock).
using StageTimes = std::vector<std::pair<std::string, double>>;

/// The default material: soft enough that the bunny (about 10 m tall) visibly sags and sways
/// for a second or two when hung by its ears, damped enough that it then settles.
Material defaultSceneMaterial();

/// What the window's right panel edits. Level, cage and render level changes rebuild the
/// scene; the rest applies to the running simulation.
struct SceneSettings {
  int level = 1;                ///< simulation level K (1..3)
  double cageCellsAcross = 6.0; ///< cage cells along the longest side (1..64), sources (a), (b)
  int renderLevel = 3;          ///< Catmull–Clark levels of a control mesh's surface (0..5), (c)
  Material material = defaultSceneMaterial();  ///< E, nu, density, damping (uniform)
  Integrator integrator = Integrator::Implicit;
  ElasticModel elasticModel = kDefaultElasticModel;  ///< with or without the inversion barrier
  double timeStep = 1.0 / 60.0;                ///< seconds per step
  Eigen::Vector3d gravity{0.0, -9.81, 0.0};    ///< m/s^2

  /// True when going from `other` to this needs a rebuild (level, cage or render level).
  bool needsRebuild(const SceneSettings& other) const;
};

/// Empty when the settings are usable; otherwise a sentence naming the bad one.
std::string sceneSettingsProblem(const SceneSettings& settings);

/// The FEM element kinds of SceneGeometry::cellKind (the values of ElementType).
inline constexpr uint8_t kCellTricubic = 0, kCellTrilinear = 1, kCellPyramid = 2;

/// Everything drawn for a scene at rest; immutable once built (shared with the renderer).
struct SceneGeometry {
  uint64_t sceneId = 0;  ///< matches SceneFrame::sceneId of the frames of this scene

  /// Display surface: #V by 3 rest positions and unit normals, 3 vertex indices per triangle.
  Points restPositions, restNormals;
  std::vector<uint32_t> triangles;
  /// The surface is closed and faces out (mesh/closed_surface.h): seen from outside, its
  /// triangles that face away from the eye are hidden and need not be drawn.
  bool closedOutward = false;
  /// The same surface as its file has it (positions in file order, faces with their texture and
  /// normal indices, texture coordinates, normals), for the writers that keep it.
  std::shared_ptr<const SurfaceMesh> surface;

  /// The level-K cells (solid_cell_mesh.h: hexahedra, and tetrahedra around a centre node for
  /// cells that are not hexahedra) and the embedding of restPositions in them.
  VolumeMesh cellMesh;
  Embedding embedding;
  /// Node positions -> node gradients of cellMesh (Phong deformation), one per GradientScheme.
  std::array<NodeGradientStencil, 2> gradientStencils;
  const NodeGradientStencil& gradientStencil(GradientScheme scheme) const {
    return gradientStencils[static_cast<size_t>(scheme)];
  }
  /// Per cellMesh cell: the kind of its FEM element (kCellTricubic, kCellTrilinear,
  /// kCellPyramid) and the element's index in the FemMesh. The tetrahedra of a cell split around
  /// its centre belong to the pyramid element of the cell face they stand on.
  std::vector<uint8_t> cellKind;
  std::vector<uint32_t> cellElement;
  std::array<uint32_t, 3> elementCounts{};  ///< tricubic, trilinear and pyramid elements

  /// The control mesh: #C by 3 rest control points, its edges, and which points are pinned.
  Points restControl;
  std::vector<std::array<uint32_t, 2>> controlEdges;
  std::vector<uint8_t> pinned;
  /// The control mesh itself: what the user's project starts from and topology tools edit.
  std::shared_ptr<const CellComplex> controlMesh;

  StageTimes stageMs;       ///< phase 1 stages
  std::string description;  ///< e.g. "bunny.obj in a 6-cell cage, level 1"
};

/// What phase 2 needs from phase 1 besides the geometry (not drawn).
struct SceneSolid {
  CellComplex control;       ///< the control mesh (cage or file), valid
  /// Centre nodes of the level-K cells (its `mesh` is empty: that is SceneGeometry::cellMesh).
  SolidCellMesh centres;
  double cellSize = 0.0;        ///< cage cell side, or the mean control edge length
  /// The project the scene was built from (SceneSource::project), for its painted materials.
  std::shared_ptr<const Project> project;
};

struct SceneBuildPhase1 {
  std::shared_ptr<const SceneGeometry> geometry;
  std::shared_ptr<const SceneSolid> solid;
};

/// Phase 1. Reports progress over [0, 1] with stage names through `progress`; returns nullopt
/// when cancelled there. Throws std::runtime_error with one sentence naming the file for a
/// missing or malformed file, an invalid control mesh or a surface that cannot be caged, and
/// std::invalid_argument for bad settings.
std::optional<SceneBuildPhase1> buildSceneGeometry(const SceneSource& source,
                                                   const SceneSettings& settings, uint64_t sceneId,
                                                   ProgressReporter* progress = nullptr);

/// Phase 1 in three parts, so that phase 2 can start on the solid while the rest is made
/// (buildSceneGeometry runs them one after the other; scene_controller.h side by side):
///  - buildSceneSolid: the source read, the cage, the cells and their element plan, the control
///    mesh, its pins and the description: what phase 2 builds its model from.
///  - buildSceneStencils: the node-gradient stencils, which phase 2 needs from the end of its
///    first step on (ScenePhysics::build waits for them there).
///  - buildSceneSurface: restPositions, restNormals, triangles, surface and embedding, which only
///    the renderer reads.
/// Each part writes only its own fields of the geometry.
struct SceneSurfaceInput;
struct SceneSolidPart {
  std::shared_ptr<SceneGeometry> geometry;  ///< the other parts' fields empty until they ran
  std::shared_ptr<const SceneSolid> solid;
  std::shared_ptr<const SceneSurfaceInput> surface;  ///< what the drawn surface is made from
};
std::optional<SceneSolidPart> buildSceneSolid(const SceneSource& source,
                                              const SceneSettings& settings, uint64_t sceneId,
                                              ProgressReporter* progress = nullptr);
/// These two return false when cancelled through `progress`, and throw like buildSceneGeometry.
bool buildSceneStencils(const SceneSource& source, const SceneSolidPart& part,
                        ProgressReporter* progress = nullptr);
bool buildSceneSurface(const SceneSource& source, const SceneSolidPart& part,
                       ProgressReporter* progress = nullptr);

}  // namespace sculpt
