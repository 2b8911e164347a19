#pragma once
// What a file on the command line or in File > Open becomes as a scene: a control mesh (.json),
// a surface to cage (OBJ, glTF), or a .sculpt project, whose saved simulation settings and scene
// keys override the defaults. The window and `sculpt-cli simulate` open files through here, so
// the same file gives the same scene in both.

#include <filesystem>
#include <string>
#include <vector>

#include "project/project.h"
#include "scene/scene_builder.h"

namespace sculpt {

/// The tool-settings key under which a project keeps where its surface comes from.
inline constexpr char kSceneSourceKey[] = "scene.source";

/// "bunny", "surface", "control" (as kept under kSceneSourceKey) and back (unknown: control).
const char* sceneKindName(SceneKind kind);
SceneKind sceneKindFromName(const std::string& name);

/// True for a .sculpt project or its .recovery file.
bool isProjectPath(const std::filesystem::path& path);

/// The scene a non-project file opens as: .json a control mesh, any other a surface; an empty
/// path the default bunny.
SceneSource sceneSourceFor(const std::string& path);

/// contentHash of a file's bytes; empty when it cannot be read.
std::string fileContentHash(const std::filesystem::path& path);

struct ProjectScene {
  SceneSource source;       ///< with `project` set
  SceneSettings settings;   ///< the defaults given, overridden by what the project saved
  std::vector<std::string> warnings;  ///< e.g. the surface changed since the project was saved
};

/// The scene of `project`, read from the file `from` (relative surface paths are relative to
/// it). Throws FileError, a sentence naming `name`, when its control mesh does not
/// validate or its surface is not a readable file (missing, a directory, a device, too large).
ProjectScene projectScene(Project project, const std::filesystem::path& from,
                          const std::string& name, const SceneSettings& defaults);

/// Stores the simulation settings and the scene keys (cage, render level) in `project`, as
/// projectScene reads them back.
void storeSceneSettings(const SceneSettings& settings, Project& project);

}  // namespace sculpt
