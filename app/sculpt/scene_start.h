#pragma once
// The scene the command line names: its settings, and a build started before the window exists.

#include <memory>

#include "scene/scene_builder.h"
#include "scene/scene_controller.h"
#include "sculpt/options.h"

namespace sculpt::app {

/// --level, --cage and --dt over `settings` (a scene's own, or the defaults).
void applyCommandLineSettings(const Options& options, SceneSettings& settings);

/// A scene controller already building the scene `options` names, with the default settings
/// under the command line's: made before the window, so that the build runs on the other core
/// while the window and its OpenGL context are made (about a tenth of a second on llvmpipe).
/// Null for a project, which the app opens itself (it carries a document and its own settings).
std::unique_ptr<SceneController> startSceneBuild(const Options& options);

}  // namespace sculpt::app
