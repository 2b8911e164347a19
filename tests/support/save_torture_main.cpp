// save_torture PROJECT FIRST_GENERATION READY_FD: the work of a window that autosaves and saves
// without pause, until it is killed (tests/io/kill_during_save_test.cpp kills it at random
// moments). One byte on READY_FD says that the project is built and the saves begin, so that the
// kill times fall on saves rather than on the start.
// Each round stores the next generation number in the project's tool settings, autosaves it to
// the recovery file (the unsaved work), and every second round saves it to PROJECT and removes
// the recovery file, as Document::save does. Prints nothing; exit status 1 on an error.

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <exception>
#include <stdexcept>
#include <string>

#include "project/autosave.h"
#include "project/project.h"
#include "project/project_file.h"
#include "support/mesh_builders.h"
#include "support/save_torture.h"

namespace {

// A project large enough that a save takes milliseconds (a few thousand cells, a painted
// material array), so that kills land while its files are written.
sculpt::Project tortureProject() {
  sculpt::Project project;
  project.controlMesh = sculpt::test::hexGrid(14, 14, 14, 0.1);
  project.materials.level = 1;
  const size_t samples = 2 * project.controlMesh.numCells();
  project.materials.restPositions.reserve(samples);
  project.materials.materials.reserve(samples);
  for (size_t q = 0; q < samples; ++q) {
    const double t = static_cast<double>(q);
    project.materials.restPositions.emplace_back(0.001 * t, 0.5, -0.25);
    sculpt::Material material;
    material.youngs *= 1.0 + static_cast<double>(q % 7);
    project.materials.materials.push_back(material);
  }
  project.pins = {0, 1, 2, 3};
  project.tools["scene.source"] = std::string("control");
  return project;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 4) {
    std::fprintf(stderr, "usage: save_torture PROJECT FIRST_GENERATION READY_FD\n");
    return 2;
  }
  try {
    const std::filesystem::path path = argv[1];
    uint64_t generation = std::stoull(argv[2]);
    sculpt::Project project = tortureProject();
    // A clock one interval further at every reading: each tick autosaves.
    double now = 0.0;
    sculpt::Autosave autosave(sculpt::recoveryPathFor(path), 0.5, [&now] { return now += 1.0; });
    const int ready = std::stoi(argv[3]);
    if (::write(ready, "r", 1) != 1 || ::close(ready) != 0) throw std::runtime_error("not ready");
    for (;; ++generation) {
      sculpt::test::setGeneration(project, generation);
      autosave.tick(project, true);
      if (generation % 2 == 0) {
        sculpt::saveProject(project, path);
        autosave.savedCleanly();
      }
    }
  } catch (const std::exception& error) {
    std::fprintf(stderr, "save_torture: %s\n", error.what());
    return 1;
  }
}
