#include "sculpt/scene_start.h"

#include <filesystem>

#include "project/project_file.h"
#include "scene/scene_file.h"

namespace sculpt::app {

void applyCommandLineSettings(const Options& options, SceneSettings& settings) {
  if (options.level) settings.level = *options.level;
  if (options.cage) settings.cageCellsAcross = *options.cage;
  if (options.timeStep) settings.timeStep = *options.timeStep;
}

std::unique_ptr<SceneController> startSceneBuild(const Options& options) {
  if (std::filesystem::path(options.scene).extension() == kProjectExtension) return nullptr;
  auto controller = std::make_unique<SceneController>(!options.headless);
  SceneSettings settings;
  applyCommandLineSettings(options, settings);
  controller->load(sceneSourceFor(options.scene), settings);
  return controller;
}

}  // namespace sculpt::app
