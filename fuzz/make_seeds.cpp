// fuzz_make_seeds SOURCE_DIR OUT_DIR: writes seed inputs for the readers whose formats no file
// in assets/ or tests/data/ is in, with the project's own writers, so that every fuzzer starts
// from inputs the reader accepts (a .sculpt file with a wrong checksum would stop it at the
// header). The inputs are small on purpose: a fuzzer mutates small inputs much faster.
//   OUT_DIR/vtk_volume_mesh/  ASCII and BINARY VTK of a hexahedral and a tetrahedral lattice
//   OUT_DIR/gltf_surface/     a cube surface as .gltf (data URI) and .glb
//   OUT_DIR/obj_surface/      the same cube as OBJ (with texture coordinates and normals)
//   OUT_DIR/project_file/     projects around the control meshes of assets/
//   OUT_DIR/preferences/      a preferences file with every field set

#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>

#include "io/atomic_file.h"
#include "io/control_mesh_json.h"
#include "io/gltf_surface.h"
#include "io/obj_surface.h"
#include "io/vtk_volume_mesh.h"
#include "mesh/lattice_mesh.h"
#include "project/preferences.h"
#include "project/project_file.h"

namespace {

namespace fs = std::filesystem;
using namespace sculpt;

// A unit cube with texture coordinates and normals, so the glTF seeds carry every attribute.
constexpr char kCubeObj[] = R"(v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
v 0 0 1
v 1 0 1
v 1 1 1
v 0 1 1
vt 0 0
vt 1 0
vt 1 1
vt 0 1
vn 0 0 -1
vn 0 0 1
vn 0 -1 0
vn 1 0 0
vn 0 1 0
vn -1 0 0
f 1/1/1 4/4/1 3/3/1 2/2/1
f 5/1/2 6/2/2 7/3/2 8/4/2
f 1/1/3 2/2/3 6/3/3 5/4/3
f 2/1/4 3/2/4 7/3/4 6/4/4
f 3/1/5 4/2/5 8/3/5 7/4/5
f 4/1/6 1/2/6 5/3/6 8/4/6
)";

fs::path directory(const fs::path& out, const char* name) {
  fs::create_directories(out / name);
  return out / name;
}

void writeVtkSeeds(const fs::path& dir) {
  const VolumeMesh hexes = hexLattice({{2, 1, 1}, 0.5, Eigen::Vector3d::Zero()});
  const VolumeMesh tets = tetLattice({{1, 1, 1}, 1.0, Eigen::Vector3d::Zero()});
  writeFileAtomically(dir / "hex_ascii.vtk", volumeMeshToVtk(hexes, false));
  writeFileAtomically(dir / "hex_binary.vtk", volumeMeshToVtk(hexes, true));
  writeFileAtomically(dir / "tet_ascii.vtk", volumeMeshToVtk(tets, false));
  writeFileAtomically(dir / "tet_binary.vtk", volumeMeshToVtk(tets, true));
}

void writeGltfSeeds(const fs::path& dir) {
  const SurfaceMesh cube = parseObjSurface(kCubeObj, "cube.obj");
  writeSurfaceGltf(dir / "cube.gltf", cube);
  writeSurfaceGltf(dir / "cube.glb", cube);
}

void writeObjSeeds(const fs::path& dir) { writeFileAtomically(dir / "cube.obj", kCubeObj); }

void writeProjectSeeds(const fs::path& source, const fs::path& dir) {
  for (const char* name : {"tet", "cube", "house", "mixed"}) {
    Project project;
    project.controlMesh = loadControlMeshJson(source / "assets" / (std::string(name) + ".json"));
    project.pins = {0};
    project.tools = {{"brush.radius", 0.25}, {"brush.symmetric", true}, {"mirror", "x"}};
    if (std::string(name) == "cube") {
      project.surface.embedded = true;
      project.surface.path = "cube.obj";
      project.surface.objText = kCubeObj;
    } else {
      project.surface.path = "surface.obj";
    }
    writeFileAtomically(dir / (std::string(name) + ".sculpt"), serializeProject(project));
  }
}

void writePreferencesSeeds(const fs::path& dir) {
  Preferences preferences;
  preferences.keyMap = "Numpad1 = view_front\nCtrl+Numpad1 = view_back\n";
  preferences.uiScale = 1.5;
  preferences.window = {10, 20, 800, 600, true};
  preferences.addRecentFile("/home/user/b.sculpt");
  preferences.addRecentFile("/home/user/a.sculpt");
  preferences.brushRadii.byTool = {{"inflate", 150.0}, {"paint", 35.0}, {"pin", 80.0}};
  preferences.brushRadii.unified = true;
  preferences.brushRadii.unifiedPixels = 60.0;
  savePreferences(preferences, dir / "preferences.json");
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: fuzz_make_seeds SOURCE_DIR OUT_DIR\n");
    return 2;
  }
  const fs::path source = argv[1], out = argv[2];
  try {
    writeVtkSeeds(directory(out, "vtk_volume_mesh"));
    writeGltfSeeds(directory(out, "gltf_surface"));
    writeObjSeeds(directory(out, "obj_surface"));
    writeProjectSeeds(source, directory(out, "project_file"));
    writePreferencesSeeds(directory(out, "preferences"));
  } catch (const std::exception& error) {
    std::fprintf(stderr, "fuzz_make_seeds: %s\n", error.what());
    return 1;
  }
  return 0;
}
