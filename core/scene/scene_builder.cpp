#include "scene/scene_builder.h"

#include <cmath>
#include <filesystem>
#include <stdexcept>

#include "embed/gradient_fit.h"
#include "embed/recomputed_normals.h"
#include "embed/surface_cage.h"
#include "io/control_mesh_json.h"
#include "io/surface_file.h"
#include "mesh/boundary_surface.h"
#include "mesh/closed_surface.h"
#include "mesh/hexahedron.h"
#include "mesh/surface_triangles.h"
#include "mesh/validation.h"
#include "scene/build_progress.h"
#include "subdiv/catmull_clark_surface.h"
#include "subdiv/loop_surface.h"
#include "subdiv/mj_refiner.h"
#include "subdiv/refinement_cost.h"
#include "subdiv/regularity.h"

namespace sculpt {

// What the drawn surface is made from.
struct SceneSurfaceInput {
  SceneKind kind = SceneKind::DefaultBunny;
  SurfaceMesh source;    // the surface as read (the bunny, an imported surface)
  int renderLevel = 0;   // a control mesh: Catmull–Clark levels of its boundary
  Topology controlTopology;
};

namespace {

std::string fileName(const std::string& path) {
  return std::filesystem::path(path).filename().string();
}


SurfaceMesh readSurface(const std::string& path) {
  if (!std::filesystem::exists(path))
    throw std::runtime_error("cannot open " + path + ": the file does not exist");
  return readSurfaceFile(path).surface();  // FileError names the file
}

Cage cageAround(const SurfaceMesh& surface, const SceneSettings& settings,
                const std::string& path) {
  const Eigen::Vector3d extent =
      (surface.positions.colwise().maxCoeff() - surface.positions.colwise().minCoeff()).transpose();
  CageSettings cageSettings;
  cageSettings.cellSize = extent.maxCoeff() / settings.cageCellsAcross;
  try {
    return buildSurfaceCage(surface, cageSettings);
  } catch (const std::exception& e) {
    throw std::runtime_error("cannot build a cage around " + fileName(path) + ": " + e.what());
  }
}

// The boundary of a control mesh, Catmull–Clark refined with its sharp tags.
SurfaceMesh controlMeshSurface(const CellComplex& control, const Topology& topology, int levels) {
  const BoundarySurface boundary = boundarySurface(control, topology);
  SurfaceTags tags;
  tags.creases = boundary.creases;
  tags.corners = boundary.corners;
  return catmullClarkRefine(boundary.surface, levels, true, tags);
}

void throwIfInvalid(const CellComplex& control, const std::string& name) {
  for (const ValidationIssue& issue : validate(control))
    if (issue.severity == ValidationIssue::Severity::Error)
      throw std::runtime_error(name + " is not a valid control mesh: " + issue.message);
}

double meanEdgeLength(const CellComplex& complex, const Topology& topology) {
  double sum = 0.0;
  for (const auto& [a, b] : topology.edgeVertices)
    sum += (complex.positions.row(a) - complex.positions.row(b)).norm();
  return topology.numEdges() ? sum / topology.numEdges() : 1.0;
}

// The FEM's element per level-K cell, known before the elements are built so that the first
// frame can colour the cells (fem_mesh.h decides the same way: regular hexahedra with a 4x4x4
// block are tricubic, other hexahedra trilinear, other cells one pyramid per face; tricubic
// elements are numbered first). Phase 2 checks it against the FemMesh.
struct ElementPlan {
  std::vector<uint8_t> kind;          // per level-K cell
  std::vector<uint32_t> firstElement;  // per level-K cell
  std::array<uint32_t, 3> counts{};
};

ElementPlan planElements(const Topology& topology) {
  const std::vector<CellRegularity> regularity = classifyCells(topology);
  ElementPlan plan;
  plan.kind.resize(topology.numCells());
  for (uint32_t c = 0; c < topology.numCells(); ++c) {
    if (regularity[c] == CellRegularity::Regular && regularControlBlock(topology, c))
      plan.kind[c] = kCellTricubic;
    else if (vtkHexahedronOrder(topology, c))
      plan.kind[c] = kCellTrilinear;
    else
      plan.kind[c] = kCellPyramid;
  }
  plan.firstElement.resize(topology.numCells());
  uint32_t tricubic = 0, linear = 0;
  for (uint32_t c = 0; c < topology.numCells(); ++c)
    if (plan.kind[c] == kCellTricubic) plan.firstElement[c] = tricubic++;
  for (uint32_t c = 0; c < topology.numCells(); ++c) {
    if (plan.kind[c] == kCellTricubic) continue;
    plan.firstElement[c] = tricubic + linear;
    const uint32_t elements = plan.kind[c] == kCellTrilinear ? 1 : topology.cellFaces.rowSize(c);
    linear += elements;
    plan.counts[plan.kind[c]] += elements;
  }
  plan.counts[kCellTricubic] = tricubic;
  return plan;
}

}  // namespace

Material defaultSceneMaterial() {
  Material material;
  material.youngs = 3.0e6;
  material.poisson = 0.3;
  material.density = 1000.0;
  material.damping = 2000.0;
  return material;
}

bool SceneSettings::needsRebuild(const SceneSettings& other) const {
  return level != other.level || cageCellsAcross != other.cageCellsAcross ||
         renderLevel != other.renderLevel;
}

std::string sceneSettingsProblem(const SceneSettings& s) {
  if (s.level < 1 || s.level > 3)
    return "the simulation level must be 1, 2 or 3 (got " + std::to_string(s.level) + ")";
  if (!(s.cageCellsAcross >= 1.0 && s.cageCellsAcross <= 64.0))
    return "the cage must have 1 to 64 cells across (got " + std::to_string(s.cageCellsAcross) +
           ")";
  if (s.renderLevel < 0 || s.renderLevel > 5)
    return "the render level must be in 0..5 (got " + std::to_string(s.renderLevel) + ")";
  if (const std::string problem = materialProblem(s.material); !problem.empty())
    return "invalid material: " + problem;
  if (!s.gravity.allFinite()) return "gravity must be finite";
  SimulationSettings simulation;
  simulation.integrator = s.integrator;
  simulation.timeStep = s.timeStep;
  return settingsProblem(simulation);
}

namespace {

std::string bunnyPath(const SceneSource& source) {
  if (source.kind != SceneKind::DefaultBunny || !source.path.empty()) return source.path;
  // A path, not string concatenation: GCC 12 misreads the latter under -O2 -fsanitize=thread.
  return (std::filesystem::path(SCULPT_SOURCE_DIR) / "assets" / "bunny.obj").string();
}

std::optional<SceneSolidPart> buildSolidPart(const SceneSource& source,
                                             const SceneSettings& settings, uint64_t sceneId,
                                             ProgressReporter* progress) {
  auto geometry = std::make_shared<SceneGeometry>();
  auto solid = std::make_shared<SceneSolid>();
  auto surface = std::make_shared<SceneSurfaceInput>();
  geometry->sceneId = sceneId;
  StageClock clock(geometry->stageMs);
  // Fractions of the whole build (both phases) as measured on the default scene: phase 1 is
  // under a tenth of it, the first implicit step (matrices and factorisation) most of the rest.
  BuildStage read(progress, 0.0, 0.01, "reading");
  if (!read.start()) return std::nullopt;

  // The control mesh (and the surface the drawn one is made from)
  const std::string sourceName = source.path.empty() ? "the project" : fileName(source.path);
  surface->kind = source.kind;
  surface->renderLevel = settings.renderLevel;
  CellComplex control;
  double cellSize = 0.0;  // a cage's own, or else the mean control edge (below)
  bool caged = false;
  std::string description;
  if (source.kind == SceneKind::ControlMesh) {
    try {
      control = source.project ? source.project->controlMesh : loadControlMeshJson(source.path);
    } catch (const std::exception& e) {
      throw std::runtime_error(std::string("cannot load the control mesh ") + e.what());
    }
    throwIfInvalid(control, sourceName);
    description = sourceName + ", surface at Catmull-Clark level " +
                  std::to_string(settings.renderLevel);
    clock.lap("read");
  } else {
    const std::string path = bunnyPath(source);
    surface->source = readSurface(path);
    clock.lap("read");
    if (source.project) {  // the user's (possibly edited) cage
      control = source.project->controlMesh;
      throwIfInvalid(control, sourceName);
      description = fileName(path) + " in a cage of " + std::to_string(control.numCells()) +
                    " cells";
    } else {
      BuildStage cage(progress, 0.01, 0.02, "building the cage");
      if (!cage.start()) return std::nullopt;
      // Around the surface as read: the margin covers the refined surface's difference.
      Cage built = cageAround(surface->source, settings, path);
      cellSize = built.cellSize;
      caged = true;
      control = std::move(built.control);
      description = fileName(path) + " in a " + std::to_string(built.gridSize[0]) + "x" +
                    std::to_string(built.gridSize[1]) + "x" + std::to_string(built.gridSize[2]) +
                    " cage of " + std::to_string(control.numCells()) + " cells";
    }
    clock.lap("cage");
  }
  // The control mesh's topology, once: the cell size, the refusal below and a control mesh's
  // drawn surface need it.
  surface->controlTopology = buildTopology(control);
  const Topology& topology = surface->controlTopology;
  if (!caged) cellSize = meanEdgeLength(control, topology);

  // The solid at level K and its cells
  BuildStage refineSolid(progress, 0.02, 0.03, "subdividing the solid");
  if (!refineSolid.start()) return std::nullopt;
  // Phase 2 builds the elements and the solver on these cells: refuse before either phase
  // allocates when the whole would not fit.
  if (const std::string refusal =
          refinementRefusal(topology, settings.level, sourceName, kSimulation);
      !refusal.empty())
    throw std::runtime_error(refusal);
  std::optional<Subdivision> subdivision =
      subdivide(control, settings.level, refineSolid.reporter());
  if (!subdivision) return std::nullopt;
  clock.lap("subdivide");
  BuildStage cells(progress, 0.03, 0.04, "cells");
  if (!cells.start()) return std::nullopt;
  solid->centres = solidCellMesh(subdivision->finest(), subdivision->finestTopology());
  geometry->cellMesh = std::move(solid->centres.mesh);
  solid->centres.mesh = VolumeMesh{};
  const ElementPlan plan = planElements(subdivision->finestTopology());
  geometry->elementCounts = plan.counts;
  for (uint32_t c = 0; c < subdivision->finest().numCells(); ++c) {
    if (plan.kind[c] != kCellPyramid) {  // one hexahedron
      geometry->cellKind.push_back(plan.kind[c]);
      geometry->cellElement.push_back(plan.firstElement[c]);
      continue;
    }
    // solidCellMesh: per face j, a fan of (corners - 2) tetrahedra on pyramid element first + j.
    for (uint32_t j = 0; j < subdivision->finest().numFacesOfCell(c); ++j)
      for (size_t t = 2; t < subdivision->finest().cellFace(c, j).size(); ++t) {
        geometry->cellKind.push_back(kCellPyramid);
        geometry->cellElement.push_back(plan.firstElement[c] + j);
      }
  }
  if (geometry->cellKind.size() != geometry->cellMesh.numCells())
    throw std::logic_error("the element plan does not match the level-K cells");
  clock.lap("cells");

  // The control mesh for display, with the top layer pinned
  const Topology& controlTopology = subdivision->topologies.front();
  geometry->restControl = control.positions;
  geometry->controlEdges = controlTopology.edgeVertices;
  geometry->pinned.assign(control.numVertices(), 0);
  if (source.project) {
    for (const uint32_t v : source.project->pins)
      if (v < geometry->pinned.size()) geometry->pinned[v] = 1;
  } else {
    const double top = control.positions.col(1).maxCoeff();
    for (uint32_t v = 0; v < control.numVertices(); ++v)
      geometry->pinned[v] = control.positions(v, 1) >= top - 0.5 * cellSize;
  }
  solid->project = source.project;
  geometry->controlMesh = std::make_shared<const CellComplex>(control);
  solid->control = std::move(control);
  solid->cellSize = cellSize;
  geometry->description = description + ", level " + std::to_string(settings.level);
  return SceneSolidPart{std::move(geometry), std::move(solid), std::move(surface)};
}

bool buildStencilPart(const SceneSolidPart& part, ProgressReporter* progress) {
  SceneGeometry& geometry = *part.geometry;
  StageClock clock(geometry.stageMs);
  BuildStage stencil(progress, 0.04, 0.05, "gradient stencil");
  if (!stencil.start()) return false;
  // The fit keeps the average's rows where it cannot fit: made from it, not anew.
  const NodeGradientStencil& average =
      geometry.gradientStencils[static_cast<size_t>(GradientScheme::Average)] =
          nodeGradientStencil(geometry.cellMesh, GradientScheme::Average);
  geometry.gradientStencils[static_cast<size_t>(GradientScheme::Fit)] =
      quadraticFitStencil(geometry.cellMesh, average);
  clock.lap("stencil");
  return true;
}

bool buildSurfacePart(const SceneSolidPart& part, ProgressReporter* progress) {
  SceneGeometry& geometry = *part.geometry;
  const SceneSurfaceInput& input = *part.surface;
  StageClock clock(geometry.stageMs);
  BuildStage refine(progress, 0.05, 0.08, "refining the surface");
  if (!refine.start()) return false;
  SurfaceMesh display;
  if (input.kind == SceneKind::ControlMesh) {
    display = controlMeshSurface(part.solid->control, input.controlTopology, input.renderLevel);
  } else {
    // The bunny is drawn Loop-refined three times onto its limit surface (235k triangles, the
    // issue's "about 200k").
    display = input.kind == SceneKind::DefaultBunny ? loopRefine(input.source, 3, true)
                                                    : input.source;
  }
  clock.lap("refine");
  geometry.restPositions = display.positions;
  geometry.restNormals = vertexNormals(display);
  geometry.triangles = triangulate(display);
  if (geometry.triangles.empty()) throw std::runtime_error("the surface has no faces to draw");
  geometry.closedOutward = isClosedOutwardSurface(geometry.restPositions, geometry.triangles);
  geometry.surface = std::make_shared<const SurfaceMesh>(std::move(display));
  clock.lap("normals");

  BuildStage embed(progress, 0.08, 0.09, "embedding the surface");
  if (!embed.start()) return false;
  geometry.embedding = embedPoints(geometry.cellMesh, geometry.restPositions, embed.reporter());
  if (embed.cancelled()) return false;
  clock.lap("embed");
  return true;
}

// Runs `build`, naming the source's file in every failure.
template <class Build>
auto namingTheFile(const SceneSource& source, const Build& build) {
  try {
    return build();
  } catch (const std::exception& e) {
    const std::string path = bunnyPath(source);
    const std::string name = path.empty() ? std::string("the project") : fileName(path);
    if (std::string(e.what()).find(name) != std::string::npos) throw;
    throw std::runtime_error(name + ": " + e.what());
  }
}

}  // namespace

std::optional<SceneSolidPart> buildSceneSolid(const SceneSource& source,
                                              const SceneSettings& settings, uint64_t sceneId,
                                              ProgressReporter* progress) {
  if (const std::string problem = sceneSettingsProblem(settings); !problem.empty())
    throw std::invalid_argument(problem);
  return namingTheFile(source, [&] { return buildSolidPart(source, settings, sceneId, progress); });
}

bool buildSceneStencils(const SceneSource& source, const SceneSolidPart& part,
                        ProgressReporter* progress) {
  return namingTheFile(source, [&] { return buildStencilPart(part, progress); });
}

bool buildSceneSurface(const SceneSource& source, const SceneSolidPart& part,
                       ProgressReporter* progress) {
  return namingTheFile(source, [&] { return buildSurfacePart(part, progress); });
}

std::optional<SceneBuildPhase1> buildSceneGeometry(const SceneSource& source,
                                                   const SceneSettings& settings, uint64_t sceneId,
                                                   ProgressReporter* progress) {
  std::optional<SceneSolidPart> part = buildSceneSolid(source, settings, sceneId, progress);
  if (!part || !buildSceneStencils(source, *part, progress) ||
      !buildSceneSurface(source, *part, progress))
    return std::nullopt;
  return SceneBuildPhase1{std::move(part->geometry), std::move(part->solid)};
}

}  // namespace sculpt
