#include "cli/scene_options.h"

#include <filesystem>
#include <iostream>

#include "cli/fem_options.h"
#include "project/project_file.h"
#include "tools/script_topology.h"

namespace sculpt::cli {

CliScene cliSceneFor(const CliArgs& args, const std::string& file, const char* command) {
  for (const char* option :
       {"trilinear", "E", "nu", "density", "damping", "fix", "force", "gravity"})
    if (args.has(option))
      throw UsageError(std::string("--") + option +
                       " is for control meshes; a scene brings its own (save them in its project)");
  CliScene scene;
  scene.source = file == kDefaultSceneName ? SceneSource{} : sceneSourceFor(file);
  if (isProjectPath(file)) {
    ProjectScene project = projectScene(
        loadProject(file), file, std::filesystem::path(file).filename().string(), scene.settings);
    for (const std::string& warning : project.warnings)
      std::cerr << command << ": " << warning << '\n';
    scene.source = std::move(project.source);
    scene.settings = project.settings;
  }
  SceneSettings& settings = scene.settings;
  if (args.has("levels") || args.has("level"))  // record spells it --level, as the window does
    settings.level = args.intValue(args.has("levels") ? "levels" : "level", 1, 1, 3);
  if (args.has("cage")) settings.cageCellsAcross = args.intValue("cage", 6, 1, 64);
  if (args.has("integrator") || args.has("dt") || args.has("model")) {
    const SimulationSettings given = parseIntegratorAndStep(args, false);
    if (args.has("integrator")) settings.integrator = given.integrator;
    if (args.has("model")) settings.elasticModel = given.elasticModel;
    if (args.has("dt")) settings.timeStep = given.timeStep;
  }
  if (args.has("script")) scene.script = loadSessionScript(args.requiredValue("script"));
  if (scene.script && hasTopologyEvents(*scene.script))
    throw UsageError(args.requiredValue("script") +
                     ": topology events edit a control mesh; run them on the .json file");
  return scene;
}

}  // namespace sculpt::cli
