// sculpt-cli record end to end: the files it writes read back, frame by frame, to the surface the
// recorder's take evaluates to (recorded again in this process from the same scene and script);
// two runs give the same bytes; the .glb files pass the Khronos validator; bad requests are one
// sentence and leave nothing behind.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "anim/frame_pattern.h"
#include "anim/take_surface.h"
#include "anim/export_test_files.h"
#include "anim/glb_reader.h"
#include "anim/record_scene.h"
#include "io/atomic_file.h"
#include "support/cli_fixture.h"
#include "support/gltf_validator.h"

namespace sculpt {
namespace {

namespace fs = std::filesystem;

const std::string kBlock = SCULPT_SOURCE_DIR "/assets/block3.json";
constexpr double kFps = 30.0;
constexpr uint32_t kFrames = 31;  // 1 s

// Grab the block's free bottom corner region and drag it sideways for half a second.
constexpr const char* kScript = R"({"format": "sculpt-session", "version": 1, "events": [
  {"t": 0.0, "type": "grab", "point": [1.5, 0.25, 1.5],
   "path": [[0.0, 1.5, 0.25, 1.5], [0.5, 2.5, 0.25, 1.5]], "release": 0.7}]})";

class RecordCommand : public test::CliFixture {
 protected:
  RecordCommand() : CliFixture("sculpt_record_command_test_") {}

  std::string scriptPath() const {
    const std::string p = path("grab.json");
    if (!fs::exists(p)) writeFileAtomically(p, kScript);
    return p;
  }
  std::string recordBlock(const std::string& outs) const {
    return "record " + test::quote(kBlock) + " --script " + test::quote(scriptPath()) +
           " --seconds 1 --fps 30 " + outs;
  }
  // The frames as this process records and evaluates them.
  std::vector<std::vector<float>> expectedFrames() const {
    const SessionScript script = parseSessionScript(kScript, "grab.json");
    const auto take = test::recordScene({SceneKind::ControlMesh, kBlock}, SceneSettings{}, script,
                                        kFps, kFrames);
    TakeSurface surface(take);
    std::vector<std::vector<float>> frames(surface.frameCount());
    SurfaceFrameData data;
    data.withNormals = false;
    for (uint32_t f = 0; f < surface.frameCount(); ++f) {
      surface.evaluateSurface(f, data);
      frames[f] = data.positions;
    }
    return frames;
  }
};

float littleFloat(const std::string& bytes, size_t at) {
  float v;
  std::memcpy(&v, bytes.data() + at, 4);
  return v;
}

TEST_F(RecordCommand, CachesAndObjFramesAreTheRecordedPositionsAndTheGlbIsWithinItsTolerance) {
  const test::CliResult result = run(recordBlock("--out " + test::quote(path("t.pc2")) + " --out " +
                                                 test::quote(path("t.mdd")) + " --out " +
                                                 test::quote(path("t_####.obj")) + " --out " +
                                                 test::quote(path("t.glb"))));
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const std::vector<std::vector<float>> expected = expectedFrames();
  ASSERT_EQ(expected.size(), kFrames);
  const size_t values = expected[0].size();
  EXPECT_NE(result.lastLine().find("frames=31 seconds=1 vertices=" + std::to_string(values / 3)),
            std::string::npos) << result.lastLine();

  // PC2: 32-byte header, then little-endian float32 x y z per vertex per frame.
  const std::string pc2 = readFile(path("t.pc2"));
  ASSERT_EQ(pc2.compare(0, 12, std::string("POINTCACHE2\0", 12)), 0);
  ASSERT_EQ(pc2.size(), 32 + 4 * values * kFrames);
  // MDD: frame count, vertex count, the times, then big-endian float32 positions.
  const std::string mdd = readFile(path("t.mdd"));
  ASSERT_EQ(test::bigEndian32(mdd, 0), kFrames);
  ASSERT_EQ(test::bigEndian32(mdd, 4), values / 3);
  const size_t mddData = 8 + 4 * kFrames;
  ASSERT_EQ(mdd.size(), mddData + 4 * values * kFrames);
  size_t cacheMismatches = 0, objMismatches = 0;
  for (uint32_t f = 0; f < kFrames; ++f) {
    EXPECT_EQ(test::bigEndianFloat(mdd, 8 + 4 * f), static_cast<float>(f / kFps));
    for (size_t i = 0; i < values; ++i) {
      cacheMismatches += littleFloat(pc2, 32 + 4 * (f * values + i)) != expected[f][i];
      cacheMismatches +=
          test::bigEndianFloat(mdd, mddData + 4 * (f * values + i)) != expected[f][i];
    }
    // OBJ: the v lines read back to the same floats.
    std::ifstream obj(framePath(framePatternOrThrow(path("t_####.obj")), f + 1));
    ASSERT_TRUE(obj) << "frame " << f + 1;
    std::vector<float> read;
    for (std::string keyword; obj >> keyword;) {
      if (keyword == "v") {
        std::string x, y, z;
        obj >> x >> y >> z;
        for (const std::string* w : {&x, &y, &z}) read.push_back(std::strtof(w->c_str(), nullptr));
      } else {
        obj.ignore(1 << 20, '\n');
      }
    }
    ASSERT_EQ(read.size(), values);
    for (size_t i = 0; i < values; ++i) objMismatches += read[i] != expected[f][i];
  }
  EXPECT_EQ(cacheMismatches, 0u) << "float32 exact";
  EXPECT_EQ(objMismatches, 0u);

  // GLB: base + the linearly cross-faded targets, at every frame's time.
  const test::GlbFile glb = test::GlbFile::read(path("t.glb"));
  const auto& primitive = glb.json["meshes"][0]["primitives"][0];
  const std::vector<float> base = glb.values<float>(primitive["attributes"]["POSITION"]);
  std::vector<std::vector<float>> deltas;
  for (const auto& target : primitive["targets"])
    deltas.push_back(glb.values<float>(target["POSITION"]));
  const auto& sampler = glb.json["animations"][0]["samplers"][0];
  const std::vector<float> times = glb.values<float>(sampler["input"]);
  const std::vector<float> weights = glb.values<float>(sampler["output"]);
  const size_t targets = deltas.size();
  ASSERT_GE(targets, 2u);
  ASSERT_EQ(weights.size(), times.size() * targets);
  double diagonal = 0.0;
  {
    Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e30), hi = -lo;
    for (size_t v = 0; v < values / 3; ++v)
      for (int d = 0; d < 3; ++d)
        lo[d] = std::min<double>(lo[d], base[3 * v + d]),
        hi[d] = std::max<double>(hi[d], base[3 * v + d]);
    diagonal = (hi - lo).norm();
  }
  double worst = 0.0;
  for (uint32_t f = 0; f < kFrames; ++f) {
    const float t = static_cast<float>(f / kFps);
    size_t k = 0;
    while (k + 2 < times.size() && times[k + 1] <= t) ++k;
    const double s =
        times.size() < 2 ? 0.0 : std::clamp((t - times[k]) / (times[k + 1] - times[k]), 0.0f, 1.0f);
    int active = 0;
    std::vector<double> w(targets);
    for (size_t j = 0; j < targets; ++j) {
      w[j] = (1 - s) * weights[k * targets + j] +
             (times.size() < 2 ? 0.0 : s * weights[(k + 1) * targets + j]);
      active += w[j] != 0.0;
    }
    EXPECT_LE(active, 2) << "frame " << f;
    for (size_t v = 0; v < values / 3; ++v) {
      double error = 0.0;
      for (int d = 0; d < 3; ++d) {
        double p = base[3 * v + d];
        for (size_t j = 0; j < targets; ++j) p += w[j] * deltas[j][3 * v + d];
        error += (p - expected[f][3 * v + d]) * (p - expected[f][3 * v + d]);
      }
      worst = std::max(worst, std::sqrt(error));
    }
  }
  EXPECT_LE(worst, 1e-3 * diagonal * 1.001) << "the key tolerance";
  std::cout << "glb: " << targets << " keys for " << kFrames << " frames, worst error " << worst
            << " m (tolerance " << 1e-3 * diagonal << " m)\n";
}

TEST_F(RecordCommand, RecordingTwiceGivesByteIdenticalFilesInEveryFormat) {
  const auto outs = [&](const std::string& run) {
    fs::create_directories(path(run));
    std::string args;
    for (const char* name : {"t.glb", "t.pc2", "t.mdd", "t_####.obj", "t_####.vtk", "u_####.vtu"})
      args += " --out " + test::quote(path(run + "/" + name));
    return args;
  };
  ASSERT_EQ(run(recordBlock(outs("a"))).exitCode, 0);
  ASSERT_EQ(run(recordBlock(outs("b"))).exitCode, 0);
  size_t files = 0;
  for (const auto& entry : fs::directory_iterator(path("a"))) {
    const fs::path other = fs::path(path("b")) / entry.path().filename();
    ASSERT_TRUE(fs::exists(other)) << other;
    EXPECT_EQ(readFile(entry.path()), readFile(other)) << entry.path().filename();
    ++files;
  }
  EXPECT_EQ(files, 3u + 3 * kFrames + 3)
      << "glb, pc2, mdd, the three sequences, two .pvd and a .vtk.series";
}


TEST_F(RecordCommand, GlbOfTheDefaultSceneAndOfAControlMeshScenePassTheKhronosValidator) {
  const fs::path script = test::gltfValidatorScript();
  ASSERT_FALSE(script.empty())
      << "the glTF validator is missing: run scripts/install-gltf-validator.sh";
  ASSERT_EQ(run(recordBlock("--out " + test::quote(path("block.glb")))).exitCode, 0);
  const test::CliResult bunny =
      run("record default --script " +
          test::quote(SCULPT_SOURCE_DIR "/assets/scripts/bunny_pull.json") +
          " --seconds 0.5 --out " + test::quote(path("bunny.glb")));
  ASSERT_EQ(bunny.exitCode, 0) << bunny.err;
  for (const char* name : {"block.glb", "bunny.glb"}) {
    const std::string report = path(std::string(name) + ".txt");
    const int status = std::system(("node " + test::quote(script.string()) + " " +
                                    test::quote(path(name)) + " > " + test::quote(report) + " 2>&1")
                                       .c_str());
    const std::string text = readFile(report);
    EXPECT_EQ(status, 0) << text;
    EXPECT_NE(text.find("errors=0 warnings=0"), std::string::npos) << name << ":\n" << text;
  }
}

TEST_F(RecordCommand, BadRequestsAreOneSentenceAndWriteNothing) {
  expectBadInput(recordBlock("--out " + test::quote(path("frame.obj"))), "####");
  expectBadInput(recordBlock("--out " + test::quote(path("take.abc"))),
                 "unknown kind of recording");
  expectBadInput(
      "record " + test::quote(kBlock) + " --seconds 1 --fps 0 --out " + test::quote(path("a.glb")),
      "frame rate");
  expectBadInput("record " + test::quote(kBlock) + " --seconds 1 --fps 2000 --out " +
                     test::quote(path("a.glb")),
                 "frame rate");
  expectBadInput("record " + test::quote(kBlock) + " --seconds 4000 --fps 30 --out " +
                     test::quote(path("a.glb")),
                 "100000");
  expectBadInput("record " + test::quote(kBlock) + " --out " + test::quote(path("a.glb")),
                 "--seconds");
  // A folder that does not exist: the error names the file, exit 2, nothing written.
  const test::CliResult missing = run(recordBlock(
      "--out " + test::quote(path("no/such/dir/t.glb")) + " --out " + test::quote(path("ok.pc2"))));
  EXPECT_EQ(missing.exitCode, 2);
  EXPECT_NE(missing.err.find("error: "), std::string::npos);
  EXPECT_NE(missing.err.find("t.glb"), std::string::npos) << missing.err;
  EXPECT_FALSE(fs::exists(path("no")));
  EXPECT_TRUE(fs::exists(path("ok.pc2"))) << "the other outputs are still written";
  for (const auto& entry : fs::directory_iterator(path("")))
    EXPECT_EQ(entry.path().filename().string().find(".tmp"), std::string::npos) << entry.path();
}

}  // namespace
}  // namespace sculpt
