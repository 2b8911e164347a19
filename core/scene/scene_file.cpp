#include "scene/scene_file.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <memory>
#include <stdexcept>

#include "io/file_error.h"
#include "io/input_file.h"
#include "mesh/validation.h"
#include "project/project_file.h"
#include "util/file_extension.h"

namespace sculpt {
namespace {

Integrator integratorFromName(const std::string& name) {
  return name == "paper" ? Integrator::Paper : Integrator::Implicit;
}

}  // namespace

const char* sceneKindName(SceneKind kind) {
  switch (kind) {
    case SceneKind::DefaultBunny: return "bunny";
    case SceneKind::ImportedSurface: return "surface";
    case SceneKind::ControlMesh: return "control";
  }
  return "control";
}

SceneKind sceneKindFromName(const std::string& name) {
  return name == "bunny"     ? SceneKind::DefaultBunny
         : name == "surface" ? SceneKind::ImportedSurface
                             : SceneKind::ControlMesh;
}

bool isProjectPath(const std::filesystem::path& path) {
  const std::string extension = lowerExtension(path);
  return extension == kProjectExtension || extension == ".recovery";
}

SceneSource sceneSourceFor(const std::string& path) {
  if (path.empty()) return {};
  return {lowerExtension(path) == ".json" ? SceneKind::ControlMesh : SceneKind::ImportedSurface,
          path, nullptr};
}

std::string fileContentHash(const std::filesystem::path& path) {
  try {
    return contentHash(readInputFile(path, kSurfaceInput));
  } catch (const FileError&) {
    return {};
  }
}

ProjectScene projectScene(Project project, const std::filesystem::path& from,
                          const std::string& name, const SceneSettings& defaults) {
  ProjectScene scene;
  // The scene builder validates the mesh again, but without the project's name to give.
  if (const std::string problem = firstErrorMessage(validate(project.controlMesh));
      !problem.empty())
    throw FileError(name + ": its control mesh is not valid: " + problem);
  const auto source = project.tools.find(kSceneSourceKey);
  scene.source.kind = sceneKindFromName(
      source != project.tools.end() && std::holds_alternative<std::string>(source->second)
          ? std::get<std::string>(source->second)
          : std::string("control"));
  if (scene.source.kind == SceneKind::ImportedSurface) {
    std::filesystem::path surface = project.surface.path;
    if (surface.is_relative()) surface = from.parent_path() / surface;
    scene.source.path = surface.string();
    try {
      checkInputFile(surface, kSurfaceInput);
    } catch (const FileError& error) {  // "<surface>: <why>"
      throw FileError(name + ": its surface " + error.what());
    }
    if (!project.surface.contentHash.empty() &&
        fileContentHash(surface) != project.surface.contentHash)
      scene.warnings.push_back("the surface " + surface.filename().string() +
                               " changed since the project was saved");
  }
  SceneSettings& s = scene.settings;
  s = defaults;
  s.level = std::clamp(project.simulation.level, 1, 3);
  s.integrator = integratorFromName(project.simulation.integrator);
  if (project.simulation.timeStepS > 0 && std::isfinite(project.simulation.timeStepS))
    s.timeStep = project.simulation.timeStepS;
  if (project.simulation.gravity.allFinite()) s.gravity = project.simulation.gravity;
  if (const auto it = project.tools.find("scene.cageCellsAcross");
      it != project.tools.end() && std::holds_alternative<double>(it->second))
    s.cageCellsAcross = std::clamp(std::get<double>(it->second), 1.0, 64.0);
  if (const auto it = project.tools.find("scene.elasticModel");
      it != project.tools.end() && std::holds_alternative<std::string>(it->second)) {
    if (const auto model = parseElasticModel(std::get<std::string>(it->second)))
      s.elasticModel = *model;
    else
      scene.warnings.push_back("unknown elastic model \"" + std::get<std::string>(it->second) +
                               "\"; using " + elasticModelName(s.elasticModel));
  }
  if (const auto it = project.tools.find("scene.renderLevel");
      it != project.tools.end() && std::holds_alternative<double>(it->second))
    s.renderLevel = std::clamp(static_cast<int>(std::get<double>(it->second)), 0, 5);
  scene.source.project = std::make_shared<const Project>(std::move(project));
  return scene;
}

void storeSceneSettings(const SceneSettings& settings, Project& project) {
  project.tools["scene.cageCellsAcross"] = settings.cageCellsAcross;
  project.tools["scene.renderLevel"] = static_cast<double>(settings.renderLevel);
  project.tools["scene.elasticModel"] = std::string(elasticModelName(settings.elasticModel));
  project.simulation.integrator =
      settings.integrator == Integrator::Paper ? "paper" : "implicit-euler";
  project.simulation.timeStepS = settings.timeStep;
  project.simulation.gravity = settings.gravity;
  project.simulation.level = settings.level;
}

}  // namespace sculpt
