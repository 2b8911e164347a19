// sculpt-cli refuses what its readers refuse with exit code 2 and one line naming the file:
// a device, a FIFO (without blocking), a file over its format's size limit, a glTF buffer that
// is not a file, a TetGen node that is not finite (in the .node file), and a project whose
// control mesh is invalid or whose surface is a device.

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "io/input_file.h"
#include "project/project_file.h"
#include "scene/scene_file.h"
#include "support/cli_fixture.h"
#include "support/fifo_release.h"
#include "support/mesh_builders.h"

namespace sculpt {
namespace {

namespace fs = std::filesystem;

using test::quote;
using test::writeText;

class InputCliTest : public test::CliFixture {
 protected:
  InputCliTest() : CliFixture("sculpt_input_cli_test_") {}
};

TEST_F(InputCliTest, DevicesFifosAndOversizedFilesAreRefused) {
  expectBadInput("info /dev/zero", "/dev/zero: is a character device, not a regular file");

  const std::string fifo = path("pipe.json");
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_TRUE(test::runReleasingFifo(fifo, [&] {
    expectBadInput("info " + quote(fifo), fifo + ": is a FIFO (named pipe), not a regular file");
  })) << "info blocked on the FIFO";

  const std::string big = path("big.json");
  { std::ofstream create(big); }
  fs::resize_file(big, kControlMeshInput.maxBytes + 1);  // sparse: nothing is written
  expectBadInput("info " + quote(big),
                 big +
                     ": 1 GiB (1073741825 bytes) is more than the 1 GiB (1073741824 bytes) "
                     "that a control-mesh file may have");
}

TEST_F(InputCliTest, GltfBufferThatIsADirectoryIsNamed) {
  const std::string gltf = path("bad.gltf");
  writeText(gltf, R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
    "nodes": [{"mesh": 0}], "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
    "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                   "min": [0, 0, 0], "max": [1, 1, 0]}],
    "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36}],
    "buffers": [{"uri": ".", "byteLength": 36}]})");
  expectBadInput("simulate " + quote(gltf) + " --steps 1 --dt 0.01 --out " + quote(path("o.vtk")),
                 gltf + ": buffer 0: " + dir_.string() + "/.: is a directory, not a regular file");
}

TEST_F(InputCliTest, TetGenNodeIsBlamedOnTheNodeFile) {
  writeText(path("m.node"), "4 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 inf 0\n3 0 0 1\n");
  writeText(path("m.ele"), "1 4 0\n0 0 1 2 3\n");
  writeText(path("s.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  const std::string ele = quote(path("m.ele"));
  expectBadInput("deform --rest " + ele + " --deformed " + ele + " --surface " +
                     quote(path("s.obj")) + " --out " + quote(path("o.obj")),
                 path("m.node") + ": line 4: coordinate 1 of point 2 is not finite");
}

TEST_F(InputCliTest, ProjectErrorsNameTheProject) {
  Project dented;
  dented.controlMesh = test::unitCube();
  dented.controlMesh.positions.row(test::gridVertex(1, 1, 1, 1, 1)) << 0.1, 0.1, 0.1;
  saveProject(dented, path("dented.sculpt"));
  expectBadInput("simulate " + quote(path("dented.sculpt")) + " --steps 1 --dt 0.01 --out " +
                     quote(path("o.vtk")),
                 "error: dented.sculpt: its control mesh is not valid: cell 0 is inverted at "
                 "vertex 7: ");

  Project zero;
  zero.controlMesh = test::unitCube();
  zero.tools[kSceneSourceKey] = std::string("surface");
  zero.surface.path = "/dev/zero";
  zero.surface.contentHash = "0123456789abcdef";  // so that opening it would hash the surface
  saveProject(zero, path("zero.sculpt"));
  expectBadInput("simulate " + quote(path("zero.sculpt")) + " --steps 1 --dt 0.01 --out " +
                     quote(path("o.vtk")),
                 "error: zero.sculpt: its surface /dev/zero: is a character device, not a "
                 "regular file");
}

}  // namespace
}  // namespace sculpt
