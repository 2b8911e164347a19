// A project that loads but cannot become a scene says which project: an invalid control mesh is
// reported with the project's name and the mesh's problem, and a surface path that names a
// device, a FIFO or a directory is refused (naming both files) without reading it.

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <string>

#include "io/file_error.h"
#include "project/project_file.h"
#include "scene/scene_file.h"
#include "support/fifo_release.h"
#include "support/mesh_builders.h"
#include "support/scratch_directory.h"

namespace sculpt {
namespace {

namespace fs = std::filesystem;

// The FileError of opening `project`, saved as `path`, as a scene. A reader stuck on `fifo` is
// released after a few seconds, and the result says so.
std::string sceneError(const Project& project, const fs::path& path, const fs::path& fifo = {}) {
  saveProject(project, path);
  return test::fileErrorMessage<FileError>(
      [&] { projectScene(loadProject(path), path, path.filename().string(), SceneSettings{}); },
      fifo);
}

TEST(ProjectSceneErrors, InvalidControlMeshNamesTheProject) {
  test::ScratchDirectory dir("project_scene_mesh");
  Project project;
  project.controlMesh = test::unitCube();
  const uint32_t corner = test::gridVertex(1, 1, 1, 1, 1);     // at (1, 1, 1)
  project.controlMesh.positions.row(corner) << 0.1, 0.1, 0.1;  // pushed through the cell
  std::string error = sceneError(project, dir.path() / "dented.sculpt");
  EXPECT_EQ(error.rfind("dented.sculpt: its control mesh is not valid: cell 0 is inverted at "
                        "vertex " +
                            std::to_string(corner) + ": ",
                        0),
            0u)
      << error;
  project.controlMesh = test::unitCube();
  project.controlMesh.positions.col(2) *= -1.0;  // the whole cell mirrored
  error = sceneError(project, dir.path() / "mirrored.sculpt");
  EXPECT_EQ(error.rfind("mirrored.sculpt: its control mesh is not valid: cell 0 has negative "
                        "volume",
                        0),
            0u)
      << error;
  project.controlMesh = test::unitCube();
  EXPECT_EQ(sceneError(project, dir.path() / "fine.sculpt"), "no error");
}

TEST(ProjectSceneErrors, SurfaceMustBeARegularFile) {
  test::ScratchDirectory dir("project_scene_surface");
  Project project;
  project.controlMesh = test::unitCube();
  project.tools[kSceneSourceKey] = std::string("surface");
  ASSERT_EQ(::mkfifo((dir.path() / "pipe.obj").c_str(), 0600), 0);
  fs::create_directory(dir.path() / "folder.obj");
  const fs::path base = dir.path();
  struct Case {
    std::string path;
    std::string error;
  };
  for (const Case& c :
       {Case{"/dev/zero",
             "p.sculpt: its surface /dev/zero: is a character device, not a regular "
             "file"},
        Case{"pipe.obj", "p.sculpt: its surface " + (base / "pipe.obj").string() +
                             ": is a FIFO (named pipe), not a regular file"},
        Case{"folder.obj", "p.sculpt: its surface " + (base / "folder.obj").string() +
                               ": is a directory, not a regular file"},
        Case{"gone.obj", "p.sculpt: its surface " + (base / "gone.obj").string() +
                             ": cannot open (No such file or directory)"}}) {
    SCOPED_TRACE(c.path);
    project.surface.path = c.path;
    project.surface.contentHash = "0123456789abcdef";  // so that the scene would hash the file
    EXPECT_EQ(sceneError(project, base / "p.sculpt", base / "pipe.obj"), c.error);
  }
}

}  // namespace
}  // namespace sculpt
