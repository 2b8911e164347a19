#pragma once
// The scene a subcommand runs (simulate, haptics): a surface caged as the window cages it or a
// .sculpt project, with its saved settings, overridden by --levels, --cage, --integrator and
// --dt; and the session script it replays.

#include <optional>
#include <string>

#include "cli/cli_args.h"
#include "scene/scene_builder.h"
#include "scene/scene_file.h"
#include "tools/session_script.h"

namespace sculpt::cli {

/// The SCENE that names the window's default scene (the refined bunny in its cage).
inline constexpr const char* kDefaultSceneName = "default";

struct CliScene {
  SceneSource source;
  SceneSettings settings;
  std::optional<SessionScript> script;  ///< --script
};

/// Reads `file` and the options. Throws UsageError for control-mesh options or a script with
/// topology events, and what loading the project or the script throws.
CliScene cliSceneFor(const CliArgs& args, const std::string& file, const char* command);

}  // namespace sculpt::cli
