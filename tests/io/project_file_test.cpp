// The .sculpt project file: deterministic bytes, atomic saves that survive a killed writer, and
// a clear error (never a crash) for every kind of damaged file.

#include "project/project_file.h"

#include <gtest/gtest.h>

#include "support/scratch_directory.h"
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <random>
#include <string>

#include "io/atomic_file.h"
#include "support/fem_builders.h"
#include "util/crc32.h"

namespace sculpt::test {

inline constexpr double kStiffPa = 5.0e7;
inline const Eigen::Vector3d kPaintCentre(1.5, 1.5, 0.5);
inline constexpr double kPaintRadius = 0.6;

// A project built from assets/block3.json with painted level-1 samples, pins, tags, a camera,
// tool settings and an embedded surface. Also used by project_undo_test.cpp (same binary).
Project block3Project() {
  static const Project cached = [] {
    Project project;
    project.controlMesh = block3();
    project.controlMesh.creases = {{0, 1}, {1, 2}, {2, 3}};
    project.controlMesh.corners = {0, 3};
    auto model = buildModel(project.controlMesh, /*level=*/1, /*trilinear=*/false);
    if (!model) return project;
    Material stiff;
    stiff.youngs = kStiffPa;
    stiff.density = 2500.0;
    model->paintMaterial(kPaintCentre, kPaintRadius, stiff);
    project.materials = captureMaterials(model->mesh(), 1);
    project.pins = {0, 1, 2, 3, 17};
    project.surface = {"bunny.obj", contentHash("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"), true,
                       "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"};
    project.camera = {Eigen::Vector3d(1.5, 1.5, 1.5), 0.7853981633974483, -0.3, 7.25, true};
    project.tools = {{"brush.radius", 0.35},
                     {"brush.falloff", std::string("smooth")},
                     {"brush.mirrorX", true},
                     {"paint.youngsPa", 1.0e6}};
    project.simulation = {"implicit-euler", 1.0 / 120.0, Eigen::Vector3d(0, 0, -9.81), 1};
    return project;
  }();
  return cached;
}

}  // namespace sculpt::test

namespace sculpt {
namespace {

using nlohmann::json;

class ProjectFileTest : public ::testing::Test {
 protected:
  test::ScratchDirectory scratch_{"sculpt_project_file_test"};
  const std::filesystem::path& dir_ = scratch_.path();
};

// The FileError message of parsing `bytes`, or "" (with a failure) when it parsed.
std::string parseError(std::string_view bytes) {
  try {
    parseProject(bytes, "p.sculpt");
  } catch (const FileError& error) {
    return error.what();
  } catch (const std::exception& error) {
    ADD_FAILURE() << "not a FileError: " << error.what();
    return error.what();
  }
  ADD_FAILURE() << "parsed without an error";
  return "";
}

// One line that names the file and says something.
void expectSentence(const std::string& message) {
  EXPECT_EQ(message.rfind("p.sculpt: ", 0), 0u) << message;
  EXPECT_GT(message.size(), 20u) << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

// The header fields and the manifest/blob split of a file, to craft damaged files whose
// checksums are still right.
struct Parts {
  std::string manifest, blobs;
};
Parts split(const std::string& bytes) {
  uint32_t length = 0;
  for (int i = 0; i < 4; ++i)
    length |= uint32_t{static_cast<unsigned char>(bytes[11 + i])} << (8 * i);
  return {bytes.substr(19, length), bytes.substr(19 + length)};
}
std::string join(const std::string& manifest, const std::string& blobs, uint32_t version = 1) {
  std::string out("SCULPT\0", 7);
  for (const uint32_t value : {version, static_cast<uint32_t>(manifest.size()), crc32(manifest)}) {
    for (int i = 0; i < 4; ++i) out.push_back(static_cast<char>((value >> (8 * i)) & 0xffu));
  }
  return out + manifest + blobs;
}

TEST(ProjectFileFormat, Crc32HasTheStandardCheckValue) {
  // The CRC-32/ISO-HDLC check value (zlib's crc32 of "123456789").
  EXPECT_EQ(crc32("123456789"), 0xcbf43926u);
  EXPECT_EQ(crc32(""), 0u);
}

TEST_F(ProjectFileTest, SaveLoadSaveGivesIdenticalBytes) {
  const Project project = test::block3Project();
  const auto a = dir_ / "a.sculpt", b = dir_ / "b.sculpt";
  saveProject(project, a);
  const Project loaded = loadProject(a);
  saveProject(loaded, b);
  const std::string bytesA = readFile(a), bytesB = readFile(b);
  EXPECT_EQ(bytesA, bytesB);
  EXPECT_EQ(bytesA.substr(0, 11), std::string("SCULPT\0\x01\0\0\0", 11));

  // Everything came back, bit for bit.
  EXPECT_TRUE(sameControlMesh(loaded.controlMesh, project.controlMesh));
  EXPECT_TRUE(sameMaterialSamples(loaded.materials, project.materials));
  EXPECT_EQ(loaded.pins, project.pins);
  EXPECT_EQ(loaded.surface, project.surface);
  EXPECT_EQ(loaded.camera, project.camera);
  EXPECT_EQ(loaded.tools, project.tools);
  EXPECT_EQ(loaded.simulation, project.simulation);
  // The painted region is the one painted (independent count by distance).
  long stiff = 0, expected = 0;
  for (size_t i = 0; i < loaded.materials.size(); ++i) {
    stiff += loaded.materials.materials[i].youngs == test::kStiffPa;
    expected +=
        (loaded.materials.restPositions[i] - test::kPaintCentre).norm() <= test::kPaintRadius;
  }
  EXPECT_GT(expected, 0);
  EXPECT_EQ(stiff, expected);
}

TEST_F(ProjectFileTest, BytesDoNotDependOnInsertionOrderOrTime) {
  Project one = test::block3Project();
  Project two = test::block3Project();
  one.tools.clear();
  two.tools.clear();
  one.tools["a.radius"] = 0.25;
  one.tools["z.mirror"] = true;
  two.tools["z.mirror"] = true;
  two.tools["a.radius"] = 0.25;
  EXPECT_EQ(serializeProject(one), serializeProject(two));
  // A different value gives different bytes (the comparison can fail).
  two.tools["a.radius"] = 0.5;
  EXPECT_NE(serializeProject(one), serializeProject(two));
}

TEST_F(ProjectFileTest, ReferencedSurfaceRoundTrips) {
  Project project = test::block3Project();
  project.surface = {"meshes/bunny.obj", contentHash("v 0 0 0\n"), false, ""};
  const std::string bytes = serializeProject(project);
  const Project loaded = parseProject(bytes, "p.sculpt");
  EXPECT_EQ(loaded.surface, project.surface);
  EXPECT_EQ(serializeProject(loaded), bytes);
  EXPECT_EQ(contentHash(""), "fnv1a64:cbf29ce484222325");  // FNV-1a offset basis
  EXPECT_NE(contentHash("a"), contentHash("b"));
}

TEST_F(ProjectFileTest, SaveRefusesAProjectItCouldNotReadBack) {
  Project project = test::block3Project();
  project.controlMesh.positions(3, 1) = std::nan("");
  EXPECT_THROW(serializeProject(project), std::invalid_argument);
  project = test::block3Project();
  project.pins = {5, 2};
  EXPECT_THROW(serializeProject(project), std::invalid_argument);
  project.pins = {project.controlMesh.numVertices()};
  EXPECT_THROW(serializeProject(project), std::invalid_argument);
  project = test::block3Project();
  project.tools["radius"] = INFINITY;
  EXPECT_THROW(serializeProject(project), std::invalid_argument);
  // Nothing was written: the directory is still empty.
  EXPECT_THROW(saveProject(project, dir_ / "x.sculpt"), std::invalid_argument);
  EXPECT_TRUE(std::filesystem::is_empty(dir_));
}

// Runs `save` in a child process whose file-size limit is `limitBytes`; returns its wait status.
template <typename Save>
int runLimited(rlim_t limitBytes, bool ignoreSignal, Save save) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::signal(SIGXFSZ, ignoreSignal ? SIG_IGN : SIG_DFL);
    const struct rlimit limit { limitBytes, limitBytes };
    ::setrlimit(RLIMIT_FSIZE, &limit);
    ::_exit(save());
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  return status;
}

TEST_F(ProjectFileTest, SaveKilledMidWriteLeavesThePreviousFile) {
  const auto path = dir_ / "work.sculpt";
  Project project = test::block3Project();
  saveProject(project, path);
  const std::string old = readFile(path);

  // The new version is larger; the kernel kills the writer (SIGXFSZ) when the temporary file
  // reaches half of it: a crash in the middle of write().
  project.surface.objText += std::string(4 * old.size(), '#');
  const std::string next = serializeProject(project);
  const rlim_t limit = next.size() / 2;
  const int status = runLimited(limit, false, [&] {
    saveProject(project, path);
    return 0;
  });
  ASSERT_TRUE(WIFSIGNALED(status)) << "the writer was not killed";
  EXPECT_EQ(WTERMSIG(status), SIGXFSZ);

  // The old file is untouched; the partial temporary file is what the kill left.
  EXPECT_EQ(readFile(path), old);
  EXPECT_NO_THROW(loadProject(path));
  size_t partial = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir_)) {
    if (entry.path() != path) partial = entry.file_size();
  }
  EXPECT_EQ(partial, limit);
}

TEST_F(ProjectFileTest, FailedWriteReportsAndLeavesThePreviousFile) {
  const auto path = dir_ / "work.sculpt";
  Project project = test::block3Project();
  saveProject(project, path);
  const std::string old = readFile(path);
  project.surface.objText += std::string(4 * old.size(), '#');
  // Exit codes: 0 FileError naming the file, 1 no error, 2 another error.
  const int status = runLimited(old.size(), true, [&] {
    try {
      saveProject(project, path);
    } catch (const FileError& error) {
      return std::string(error.what()).find("work.sculpt") != std::string::npos ? 0 : 2;
    } catch (...) {
      return 2;
    }
    return 1;
  });
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0);
  EXPECT_EQ(readFile(path), old);
  // The failed writer removed its temporary file.
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir_), {}), 1);
}

TEST(ProjectFileMalformed, TruncatedAtEverySixteenthGivesASentence) {
  const std::string bytes = serializeProject(test::block3Project());
  for (size_t k = 0; k < 16; ++k) {
    const size_t length = bytes.size() * k / 16;
    const std::string message = parseError(bytes.substr(0, length));
    expectSentence(message);
    EXPECT_NE(message.find("truncated"), std::string::npos) << length << ": " << message;
  }
  // Also every length inside the header and a byte short of the end.
  for (size_t length = 1; length < 24; ++length)
    expectSentence(parseError(bytes.substr(0, length)));
  expectSentence(parseError(bytes.substr(0, bytes.size() - 1)));
  EXPECT_NE(parseError(bytes + "x").find("unexpected bytes"), std::string::npos);
}

TEST(ProjectFileMalformed, RandomByteFlipsAreAllDetected) {
  const std::string bytes = serializeProject(test::block3Project());
  std::mt19937 rng(20240611);
  std::uniform_int_distribution<size_t> where(0, bytes.size() - 1);
  std::uniform_int_distribution<int> mask(1, 255);
  for (int trial = 0; trial < 200; ++trial) {
    std::string damaged = bytes;
    const size_t at = where(rng);
    damaged[at] = static_cast<char>(damaged[at] ^ mask(rng));
    // Every single-byte change is caught: magic, version, lengths or a CRC-32.
    const std::string message = parseError(damaged);
    expectSentence(message);
  }
}

TEST(ProjectFileMalformed, BadMagicAndNewerVersion) {
  const std::string bytes = serializeProject(test::block3Project());
  std::string other = bytes;
  other[0] = 'X';
  EXPECT_NE(parseError(other).find("magic"), std::string::npos);
  EXPECT_NE(parseError("{\"format\": \"sculpt-control-mesh\"}").find("magic"), std::string::npos);

  const Parts parts = split(bytes);
  const std::string newer = parseError(join(parts.manifest, parts.blobs, 2));
  expectSentence(newer);
  EXPECT_NE(newer.find("newer"), std::string::npos) << newer;
  EXPECT_NE(newer.find("version 2"), std::string::npos) << newer;
  expectSentence(parseError(join(parts.manifest, parts.blobs, 0)));
  // The crafting helpers themselves reproduce a valid file.
  EXPECT_EQ(parseProject(join(parts.manifest, parts.blobs, 1), "p.sculpt").pins,
            test::block3Project().pins);
}

TEST(ProjectFileMalformed, ChecksumMismatchNamesTheBlob) {
  std::string bytes = serializeProject(test::block3Project());
  bytes[bytes.size() - 1] = static_cast<char>(bytes.back() ^ 0x20);  // inside surface.obj
  const std::string message = parseError(bytes);
  EXPECT_NE(message.find("checksum of blob \"surface.obj\""), std::string::npos) << message;
}

TEST(ProjectFileMalformed, ValidChecksumsButBadContent) {
  const Parts parts = split(serializeProject(test::block3Project()));
  const json manifest = json::parse(parts.manifest);

  // Bad JSON.
  std::string message = parseError(join("{\"format\": ", parts.blobs));
  EXPECT_NE(message.find("not valid JSON"), std::string::npos) << message;
  message = parseError(join(std::string(1000, '[') + std::string(1000, ']'), parts.blobs));
  EXPECT_NE(message.find("not valid JSON"), std::string::npos) << message;
  message = parseError(join("[]", parts.blobs));
  expectSentence(message);

  // Counts that disagree with the blobs.
  json wrong = manifest;
  wrong["controlMesh"]["vertices"] = manifest["controlMesh"]["vertices"].get<uint64_t>() - 1;
  message = parseError(join(wrong.dump(), parts.blobs));
  EXPECT_NE(message.find("inconsistent counts"), std::string::npos) << message;
  wrong = manifest;
  wrong["materials"]["samples"] = 7;
  message = parseError(join(wrong.dump(), parts.blobs));
  EXPECT_NE(message.find("inconsistent counts"), std::string::npos) << message;
  wrong = manifest;
  wrong["blobs"][0]["count"] = uint64_t{1} << 62;
  message = parseError(join(wrong.dump(), parts.blobs));
  expectSentence(message);
  wrong = manifest;
  wrong["camera"]["distance"] = "far";
  message = parseError(join(wrong.dump(), parts.blobs));
  EXPECT_NE(message.find("camera.distance"), std::string::npos) << message;
  wrong = manifest;
  wrong["camera"]["distance"] = 1e308 * 10;  // nlohmann writes infinity as null
  expectSentence(parseError(join(wrong.dump(), parts.blobs)));

  // A non-finite number in a blob, with its checksum updated.
  std::string blobs = parts.blobs;
  const double nan = std::nan("");
  std::memcpy(blobs.data() + 8, &nan, 8);  // control.positions[1]
  wrong = manifest;
  wrong["blobs"][0]["crc32"] =
      crc32(std::string_view(blobs).substr(0, 8 * manifest["blobs"][0]["count"].get<size_t>()));
  message = parseError(join(wrong.dump(), blobs));
  EXPECT_NE(message.find("not finite"), std::string::npos) << message;

  // A vertex id beyond the control points, with its checksum updated.
  wrong = manifest;
  size_t offset = 0;
  for (int i = 0; i < 3; ++i) {
    offset += manifest["blobs"][i]["count"].get<size_t>() * (i == 0 ? 8 : 4);
  }
  blobs = parts.blobs;
  const uint32_t bad = 1000000;
  std::memcpy(blobs.data() + offset, &bad, 4);  // control.loopVertices[0] (little-endian host)
  wrong["blobs"][3]["crc32"] = crc32(
      std::string_view(blobs).substr(offset, 4 * manifest["blobs"][3]["count"].get<size_t>()));
  message = parseError(join(wrong.dump(), blobs));
  EXPECT_NE(message.find("1000000"), std::string::npos) << message;
}

TEST_F(ProjectFileTest, MissingFileAndDirectoryAreFileErrors) {
  EXPECT_THROW(loadProject(dir_ / "none.sculpt"), FileError);
  EXPECT_THROW(loadProject(dir_), FileError);
}

}  // namespace
}  // namespace sculpt
