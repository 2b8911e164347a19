// Every reader gets its bytes through io/input_file.h: a directory, a device or a FIFO given as
// any kind of file is refused by its type before it is opened (instead of a read that never
// ends, or blocks), a file larger than its format's limit by its size, and each message names
// the file. Also the files a .gltf names by uri, and the TetGen pair's blame for a bad node.

#include "io/input_file.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "io/control_mesh_json.h"
#include "io/file_error.h"
#include "io/surface_file.h"
#include "io/tetgen_mesh.h"
#include "io/volume_mesh_file.h"
#include "project/project_file.h"
#include "support/fifo_release.h"
#include "support/scratch_directory.h"

namespace sculpt {
namespace {

namespace fs = std::filesystem;

using Reader = std::function<void(const fs::path&)>;

struct NamedReader {
  const char* extension;
  const InputFormat* format;
  Reader read;
};

// Every public reader of a whole file, by the extension it reads.
std::vector<NamedReader> readers() {
  const Reader surface = [](const fs::path& p) { readSurfaceFile(p); };
  const Reader volume = [](const fs::path& p) { readVolumeMesh(p); };
  return {{".json", &kControlMeshInput, [](const fs::path& p) { loadControlMeshJson(p); }},
          {".obj", &kSurfaceInput, surface},
          {".gltf", &kSurfaceInput, surface},
          {".glb", &kSurfaceInput, surface},
          {".vtk", &kVolumeMeshInput, volume},
          {".msh", &kVolumeMeshInput, volume},
          {".node", &kVolumeMeshInput, volume},
          {".sculpt", &kProjectInput, [](const fs::path& p) { loadProject(p); }}};
}

void writeText(const fs::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

// The FileError message of read(path). A FIFO that the reader opens instead of refusing would
// block it: it is released after a few seconds, and the result says so.
std::string errorOf(const Reader& read, const fs::path& path, const fs::path& fifo = {}) {
  return test::fileErrorMessage<FileError>([&] { read(path); }, fifo);
}

TEST(InputFile, DevicesFifosAndDirectoriesAreRefusedByType) {
  test::ScratchDirectory dir("input_file_type");
  for (const NamedReader& reader : readers()) {
    SCOPED_TRACE(reader.extension);
    const fs::path folder = dir.path() / (std::string("folder") + reader.extension);
    fs::create_directory(folder);
    EXPECT_EQ(errorOf(reader.read, folder),
              folder.string() + ": is a directory, not a regular file");

    const fs::path fifo = dir.path() / (std::string("pipe") + reader.extension);
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    EXPECT_EQ(errorOf(reader.read, fifo, fifo),
              fifo.string() + ": is a FIFO (named pipe), not a regular file");

    // A link to /dev/zero, so that the reader is chosen by the extension.
    const fs::path zero = dir.path() / (std::string("zero") + reader.extension);
    fs::create_symlink("/dev/zero", zero);
    EXPECT_EQ(errorOf(reader.read, zero),
              zero.string() + ": is a character device, not a regular file");

    const fs::path missing = dir.path() / (std::string("missing") + reader.extension);
    EXPECT_EQ(errorOf(reader.read, missing).rfind(missing.string() + ": cannot open (", 0), 0u);
  }
}

TEST(InputFile, FilesLargerThanTheirFormatAllowsAreRefusedBySize) {
  test::ScratchDirectory dir("input_file_size");
  for (const NamedReader& reader : readers()) {
    SCOPED_TRACE(reader.extension);
    const std::string extension = reader.extension;
    const InputFormat& format = *reader.format;
    // Sparse: the size is what matters, and nothing may read the file to find it.
    const fs::path big = dir.path() / ("big" + extension);
    { std::ofstream create(big); }
    fs::resize_file(big, format.maxBytes + 1);
    const std::string error = errorOf(reader.read, big);
    EXPECT_EQ(error.rfind(big.string() + ": ", 0), 0u) << error;
    EXPECT_NE(error.find(" (" + std::to_string(format.maxBytes + 1) + " bytes) is more than the "),
              std::string::npos)
        << error;
    EXPECT_NE(error.find("(" + std::to_string(format.maxBytes) + " bytes) that " + format.noun +
                         " may have"),
              std::string::npos)
        << error;
    fs::remove(big);
  }
  EXPECT_EQ(checkInputFile(SCULPT_SOURCE_DIR "/tests/data/cube.json", kControlMeshInput),
            fs::file_size(SCULPT_SOURCE_DIR "/tests/data/cube.json"));
}

// A triangle whose positions live in an external buffer `uri`.
std::string triangleGltf(const std::string& firstBufferUri, const std::string& secondBufferUri) {
  return R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
  "nodes": [{"mesh": 0}], "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                 "min": [0, 0, 0], "max": [1, 1, 0]}],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36}],
  "buffers": [{"uri": ")" +
         firstBufferUri + R"(", "byteLength": 36}, {"uri": ")" + secondBufferUri +
         R"(", "byteLength": 36}]})";
}

TEST(InputFile, GltfBufferUrisMustNameRegularFiles) {
  test::ScratchDirectory dir("input_file_gltf");
  const float positions[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  std::ofstream(dir.path() / "tri.bin", std::ios::binary)
      .write(reinterpret_cast<const char*>(positions), sizeof positions);
  const fs::path ok = dir.path() / "ok.gltf";
  writeText(ok, triangleGltf("tri.bin", "tri.bin"));
  EXPECT_EQ(readSurfaceFile(ok).surface().numVertices(), 3u);

  fs::create_directory(dir.path() / "sub");
  ASSERT_EQ(::mkfifo((dir.path() / "pipe.bin").c_str(), 0600), 0);
  fs::create_symlink("/dev/zero", dir.path() / "zero.bin");
  const std::string base = dir.path().string() + "/";
  struct Case {
    std::string uri;
    std::string why;
  };
  const std::vector<Case> cases = {
      {".", base + ".: is a directory, not a regular file"},
      {"sub", base + "sub: is a directory, not a regular file"},
      {"pipe.bin", base + "pipe.bin: is a FIFO (named pipe), not a regular file"},
      {"zero.bin", base + "zero.bin: is a character device, not a regular file"},
      {"nothere.bin", base + "nothere.bin: cannot open (No such file or directory)"}};
  for (const Case& c : cases) {
    SCOPED_TRACE(c.uri);
    const fs::path gltf = dir.path() / "bad.gltf";
    writeText(gltf, triangleGltf("tri.bin", c.uri));  // buffer 1 is the bad one
    EXPECT_EQ(errorOf([](const fs::path& p) { readSurfaceFile(p); }, gltf, dir.path() / "pipe.bin"),
              gltf.string() + ": buffer 1: " + c.why);
  }
}

TEST(InputFile, TetGenBlamesANonFiniteNodeOnTheNodeFile) {
  test::ScratchDirectory dir("input_file_tetgen");
  for (const char* bad : {"inf", "nan", "-infinity"}) {
    SCOPED_TRACE(bad);
    writeText(dir.path() / "m.node",
              std::string("4 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 ") + bad + " 0\n3 0 0 1\n");
    writeText(dir.path() / "m.ele", "1 4 0\n0 0 1 2 3\n");
    const std::string error =
        errorOf([](const fs::path& p) { readVolumeMesh(p); }, dir.path() / "m.ele");
    EXPECT_EQ(error,
              (dir.path() / "m.node").string() + ": line 4: coordinate 1 of point 2 is not finite");
  }
}

}  // namespace
}  // namespace sculpt
