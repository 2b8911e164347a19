// The glTF morph-target animation writer and its key choice, read back with an independent
// reader (glb_reader.h) and checked against the take frame by frame, and by the Khronos
// validator.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "anim/fake_animated_surface.h"
#include "anim/glb_animation_writer.h"
#include "support/gltf_validator.h"
#include "anim/glb_reader.h"
#include "anim/morph_keys.h"
#include "io/atomic_file.h"
#include "io/file_error.h"
#include "support/scratch_directory.h"
#include "support/shell_quote.h"

namespace sculpt {
namespace {

using nlohmann::json;
using test::FakeAnimatedSurface;
using test::GlbFile;

// A wave slow enough at 30 fps that keys are a few frames apart.
constexpr double kAmplitude = 0.01;

// Counts evaluations, to check that key choice evaluates each frame once.
class CountingSurface : public FakeAnimatedSurface {
 public:
  using FakeAnimatedSurface::FakeAnimatedSurface;
  void evaluateSurface(uint32_t frame, SurfaceFrameData& out) const override {
    ++evaluations[frame];
    FakeAnimatedSurface::evaluateSurface(frame, out);
  }
  mutable std::vector<int> evaluations = std::vector<int>(frameCount(), 0);
};

double vertexDistance(const std::vector<float>& p, const std::vector<double>& q, size_t v) {
  double squared = 0.0;
  for (size_t c = 0; c < 3; ++c) {
    const double d = double(p[3 * v + c]) - q[3 * v + c];
    squared += d * d;
  }
  return std::sqrt(squared);
}

// The largest vertex distance of every frame of `segment` from the interpolation of its keys.
double keyInterpolationError(const AnimatedSurface& take, const std::vector<uint32_t>& keys) {
  double worst = 0.0;
  SurfaceFrameData a, b, f;
  for (size_t k = 0; k + 1 < keys.size(); ++k) {
    take.evaluateSurface(keys[k], a);
    take.evaluateSurface(keys[k + 1], b);
    for (uint32_t frame = keys[k] + 1; frame < keys[k + 1]; ++frame) {
      take.evaluateSurface(frame, f);
      const double s = double(frame - keys[k]) / double(keys[k + 1] - keys[k]);
      std::vector<double> lerp(a.positions.size());
      for (size_t i = 0; i < lerp.size(); ++i)
        lerp[i] = (1 - s) * a.positions[i] + s * b.positions[i];
      for (size_t v = 0; v < lerp.size() / 3; ++v)
        worst = std::max(worst, vertexDistance(f.positions, lerp, v));
    }
  }
  return worst;
}

TEST(MorphKeysTest, ToleranceIsRelativeToTheRestDiagonal) {
  const FakeAnimatedSurface take(10, 30.0, 1, kAmplitude);
  // The 4 x 3 grid spans the unit square: diagonal sqrt(2).
  EXPECT_NEAR(morphKeyTolerance(take.restSurface(0), 1e-3), 1e-3 * std::sqrt(2.0), 1e-15);
}

TEST(MorphKeysTest, EveryFrameIsWithinToleranceOfItsKeys) {
  const CountingSurface take(120, 30.0, 1, kAmplitude);
  MorphKeyOptions options;
  options.tolerance = morphKeyTolerance(take.restSurface(0), 1e-3);
  std::vector<uint32_t> seen;
  const MorphKeys keys =
      chooseMorphKeys(take, 0, options, {},
                      [&](uint32_t frame, const SurfaceFrameData&) { seen.push_back(frame); });
  ASSERT_GE(keys.frames.size(), 3u);
  EXPECT_LT(keys.frames.size(), 120u);  // the wave is smooth: most frames are interpolated
  EXPECT_EQ(keys.frames.front(), 0u);
  EXPECT_EQ(keys.frames.back(), 119u);
  EXPECT_EQ(seen, keys.frames);
  for (size_t k = 0; k + 1 < keys.frames.size(); ++k) {
    EXPECT_LT(keys.frames[k], keys.frames[k + 1]);
    EXPECT_LE(keys.frames[k + 1] - keys.frames[k], options.maxSpan);
  }
  for (const int count : take.evaluations) EXPECT_EQ(count, 1);
  const double error = keyInterpolationError(take, keys.frames);
  EXPECT_LE(error, options.tolerance);
  EXPECT_NEAR(keys.maxError, error, 1e-12);
  EXPECT_GT(keys.maxError, 0.0);
}

TEST(MorphKeysTest, KeysAreGreedy) {
  // Each key reaches as far as it can: one more frame would break the tolerance or the span.
  const FakeAnimatedSurface take(90, 30.0, 1, kAmplitude);
  MorphKeyOptions options;
  options.tolerance = morphKeyTolerance(take.restSurface(0), 1e-3);
  const MorphKeys keys = chooseMorphKeys(take, 0, options);
  for (size_t k = 0; k + 2 < keys.frames.size(); ++k) {
    const uint32_t a = keys.frames[k], next = keys.frames[k + 1] + 1;
    if (next - a > options.maxSpan) continue;
    EXPECT_GT(keyInterpolationError(take, {a, next}), options.tolerance) << "key " << a;
  }
}

TEST(MorphKeysTest, StillTakeHasKeysEveryMaxSpan) {
  const FakeAnimatedSurface take(70, 30.0, 1, 0.0);
  MorphKeyOptions options;
  options.tolerance = 1e-6;
  options.maxSpan = 32;
  EXPECT_EQ(chooseMorphKeys(take, 0, options).frames, (std::vector<uint32_t>{0, 32, 64, 69}));
  options.maxSpan = 1;
  EXPECT_EQ(chooseMorphKeys(take, 0, options).frames.size(), 70u);
}

TEST(MorphKeysTest, SecondSegmentStartsWithAKey) {
  const FakeAnimatedSurface take(60, 30.0, 2, kAmplitude);
  MorphKeyOptions options;
  options.tolerance = morphKeyTolerance(take.restSurface(1), 1e-3);
  const MorphKeys keys = chooseMorphKeys(take, 1, options);
  EXPECT_EQ(keys.frames.front(), 30u);
  EXPECT_EQ(keys.frames.back(), 59u);
  EXPECT_LE(keyInterpolationError(take, keys.frames), options.tolerance);
}

// ---------------------------------------------------------------------------------------------
// The written file
// ---------------------------------------------------------------------------------------------

class GlbAnimationTest : public ::testing::Test {
 protected:
  GlbAnimationTest() : dir_("sculpt_glb_animation_test") {}
  std::filesystem::path file(const std::string& name) const { return dir_.path() / name; }

  // Every entry of the directory, to see that no temporary file stays behind.
  std::vector<std::string> entries() const {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(dir_.path())) {
      names.push_back(entry.path().filename().string());
    }
    std::sort(names.begin(), names.end());
    return names;
  }

 private:
  test::ScratchDirectory dir_;
};

// A sampler of the animation, evaluated as glTF prescribes.
struct Sampler {
  std::vector<float> times, values;
  size_t width = 1;  // values per key
  bool step = false;

  std::vector<double> at(float t) const {
    size_t i = 0;
    while (i + 1 < times.size() && times[i + 1] <= t) ++i;
    std::vector<double> out(values.begin() + long(i * width),
                            values.begin() + long((i + 1) * width));
    if (step || i + 1 >= times.size() || t <= times[i]) return out;
    const double s = double(t - times[i]) / double(times[i + 1] - times[i]);
    for (size_t c = 0; c < width; ++c) out[c] = (1 - s) * out[c] + s * values[(i + 1) * width + c];
    return out;
  }
};

// The sampler of `node`'s channel on `path` ("weights", "scale"); width 0 when there is none.
Sampler channelSampler(const GlbFile& glb, size_t node, const std::string& path, size_t width) {
  Sampler sampler;
  const json& animation = glb.json.at("animations").at(0);
  for (const json& channel : animation.at("channels")) {
    if (channel.at("target").at("node") != node || channel.at("target").at("path") != path)
      continue;
    const json& s = animation.at("samplers").at(channel.at("sampler").get<size_t>());
    sampler.times = glb.values<float>(s.at("input").get<int>());
    sampler.values = glb.values<float>(s.at("output").get<int>());
    sampler.step = s.at("interpolation") == "STEP";
    sampler.width = width;
    EXPECT_EQ(sampler.values.size(), sampler.times.size() * width);
    return sampler;
  }
  sampler.width = 0;
  return sampler;
}

// Checks that every frame of each segment is reproduced by the cross-faded targets of its mesh.
void expectFramesReproduced(const GlbFile& glb, const AnimatedSurface& take, double relative) {
  ASSERT_EQ(glb.json.at("meshes").size(), take.segmentCount());
  for (uint32_t s = 0; s < take.segmentCount(); ++s) {
    SCOPED_TRACE("segment " + std::to_string(s));
    const json& node = glb.json.at("nodes").at(s);
    const json& mesh = glb.json.at("meshes").at(node.at("mesh").get<size_t>());
    const json& primitive = mesh.at("primitives").at(0);
    const std::vector<float> base =
        glb.values<float>(primitive.at("attributes").at("POSITION").get<int>());
    std::vector<std::vector<float>> deltas;
    for (const json& target : primitive.at("targets"))
      deltas.push_back(glb.values<float>(target.at("POSITION").get<int>()));
    EXPECT_EQ(mesh.at("extras").at("targetNames").size(), deltas.size());
    EXPECT_EQ(mesh.at("weights").size(), deltas.size());
    const Sampler weights = channelSampler(glb, s, "weights", deltas.size());
    ASSERT_EQ(weights.width, deltas.size());

    const double tolerance = morphKeyTolerance(take.restSurface(s), relative);
    SurfaceFrameData frame;
    const FrameRange range = take.segment(s);
    for (uint32_t f = range.first; f < range.first + range.count; ++f) {
      const float t = static_cast<float>(take.frameTime(f));
      const std::vector<double> w = weights.at(t);
      EXPECT_LE(std::count_if(w.begin(), w.end(), [](double x) { return x != 0.0; }), 2)
          << "frame " << f;
      std::vector<double> surface(base.begin(), base.end());
      for (size_t k = 0; k < deltas.size(); ++k) {
        if (w[k] == 0.0) continue;
        for (size_t i = 0; i < surface.size(); ++i) surface[i] += w[k] * deltas[k][i];
      }
      take.evaluateSurface(f, frame);
      ASSERT_EQ(frame.positions.size(), surface.size());
      double worst = 0.0;
      for (size_t v = 0; v < surface.size() / 3; ++v)
        worst = std::max(worst, vertexDistance(frame.positions, surface, v));
      EXPECT_LE(worst, tolerance * (1 + 1e-4) + 1e-6) << "frame " << f;  // float rounding
    }
    // Between frames too, at most two targets blend.
    for (size_t i = 0; i + 1 < weights.times.size(); ++i) {
      const std::vector<double> w = weights.at(0.5f * (weights.times[i] + weights.times[i + 1]));
      EXPECT_EQ(std::count_if(w.begin(), w.end(), [](double x) { return x != 0.0; }), 2);
    }
  }
}

// Every accessor's min and max equal the bounds of the values it holds.
void expectExactBounds(const GlbFile& glb) {
  const json& accessors = glb.json.at("accessors");
  for (size_t a = 0; a < accessors.size(); ++a) {
    const json& accessor = accessors[a];
    if (!accessor.contains("min")) continue;
    ASSERT_TRUE(accessor.contains("max"));
    const std::vector<float> values = glb.values<float>(static_cast<int>(a));
    const size_t width = GlbFile::components(accessor.at("type").get<std::string>());
    ASSERT_EQ(accessor.at("min").size(), width);
    for (size_t c = 0; c < width; ++c) {
      float low = values[c], high = values[c];
      for (size_t i = c; i < values.size(); i += width) {
        low = std::min(low, values[i]);
        high = std::max(high, values[i]);
      }
      EXPECT_EQ(accessor.at("min")[c].get<double>(), double(low)) << "accessor " << a;
      EXPECT_EQ(accessor.at("max")[c].get<double>(), double(high)) << "accessor " << a;
    }
  }
  // POSITION of bases and targets and every animation input must have bounds.
  for (const json& mesh : glb.json.at("meshes")) {
    const json& primitive = mesh.at("primitives").at(0);
    EXPECT_TRUE(
        accessors.at(primitive.at("attributes").at("POSITION").get<size_t>()).contains("min"));
    for (const json& target : primitive.at("targets")) {
      EXPECT_TRUE(accessors.at(target.at("POSITION").get<size_t>()).contains("min"));
    }
  }
  for (const json& sampler : glb.json.at("animations").at(0).at("samplers")) {
    EXPECT_TRUE(accessors.at(sampler.at("input").get<size_t>()).contains("min"));
  }
}

TEST_F(GlbAnimationTest, CrossFadedTargetsReproduceEveryFrame) {
  const FakeAnimatedSurface take(90, 30.0, 1, kAmplitude);
  std::vector<MorphKeys> keys;
  const ExportResult result = writeGlbAnimation(take, file("take.glb"), {}, nullptr, &keys);
  ASSERT_EQ(keys.size(), 1u);
  EXPECT_EQ(result.keys, keys[0].frames.size());
  EXPECT_EQ(result.frames, 90u);
  EXPECT_LT(result.keys, 45u);  // most frames are interpolated
  EXPECT_FALSE(result.cancelled);
  ASSERT_EQ(result.files, std::vector<std::filesystem::path>{file("take.glb")});
  EXPECT_EQ(result.bytes, std::filesystem::file_size(file("take.glb")));
  EXPECT_EQ(entries(), std::vector<std::string>{"take.glb"});

  const GlbFile glb = GlbFile::read(file("take.glb"));
  EXPECT_EQ(glb.version, 2u);
  EXPECT_EQ(glb.json.at("asset").at("generator"), "sculpt record");
  EXPECT_EQ(glb.json.at("asset").at("version"), "2.0");
  EXPECT_EQ(glb.json.at("scenes").at(0).at("nodes"), json::array({0}));
  const json& mesh = glb.json.at("meshes").at(0);
  const json& primitive = mesh.at("primitives").at(0);
  EXPECT_EQ(primitive.at("targets").size(), result.keys);
  EXPECT_EQ(mesh.at("extras").at("targetNames").front(), "take_key_0001");
  char last[32];
  std::snprintf(last, sizeof last, "take_key_%04u", result.keys);
  EXPECT_EQ(mesh.at("extras").at("targetNames").back(), last);
  EXPECT_EQ(glb.values<uint32_t>(primitive.at("indices").get<int>()), take.triangles(0));
  EXPECT_EQ(glb.values<float>(primitive.at("attributes").at("NORMAL").get<int>()),
            take.restVertexNormals(0));
  // One weights channel, no scale channel.
  EXPECT_EQ(glb.json.at("animations").at(0).at("channels").size(), 1u);
  EXPECT_EQ(channelSampler(glb, 0, "scale", 3).width, 0u);
  // Each key's sampler output is its own one-hot vector.
  const Sampler weights = channelSampler(glb, 0, "weights", result.keys);
  for (size_t k = 0; k < weights.times.size(); ++k) {
    EXPECT_EQ(weights.times[k], static_cast<float>(take.frameTime(keys[0].frames[k])));
    for (size_t j = 0; j < result.keys; ++j)
      EXPECT_EQ(weights.values[k * result.keys + j], j == k ? 1.0f : 0.0f);
  }
  expectFramesReproduced(glb, take, 1e-3);
  expectExactBounds(glb);
}

TEST_F(GlbAnimationTest, TargetNormalsAndTexcoords) {
  const FakeAnimatedSurface take(30, 30.0, 1, kAmplitude);
  const ExportResult result = writeGlbAnimation(take, file("take.glb"), {}, nullptr);
  const GlbFile glb = GlbFile::read(file("take.glb"));
  const json& primitive = glb.json.at("meshes").at(0).at("primitives").at(0);
  // Texture coordinates share the positions' indices in the fake: written, v flipped for glTF.
  const std::vector<float> uv =
      glb.values<float>(primitive.at("attributes").at("TEXCOORD_0").get<int>());
  const TexCoords& rest = take.restSurface(0).texcoords;
  ASSERT_EQ(uv.size(), 2 * size_t(rest.rows()));
  for (Eigen::Index v = 0; v < rest.rows(); ++v) {
    EXPECT_EQ(uv[2 * size_t(v)], float(rest(v, 0)));
    EXPECT_EQ(uv[2 * size_t(v) + 1], float(1.0 - rest(v, 1)));
  }
  // The last key's normal delta gives that frame's normals.
  const json& target = primitive.at("targets").at(result.keys - 1);
  const std::vector<float> delta = glb.values<float>(target.at("NORMAL").get<int>());
  SurfaceFrameData frame;
  take.evaluateSurface(29, frame);
  for (size_t i = 0; i < delta.size(); ++i) {
    EXPECT_EQ(delta[i], frame.normals[i] - take.restVertexNormals(0)[i]);
  }
}

TEST_F(GlbAnimationTest, SecondWriteIsByteIdentical) {
  const FakeAnimatedSurface take(60, 30.0, 2, kAmplitude);
  writeGlbAnimation(take, file("a.glb"), {}, nullptr);
  writeGlbAnimation(take, file("b.glb"), {}, nullptr);
  EXPECT_EQ(readFile(file("a.glb")), readFile(file("b.glb")));
}

TEST_F(GlbAnimationTest, SegmentsAreMeshesShownInTurn) {
  const FakeAnimatedSurface take(60, 30.0, 2, kAmplitude);
  const ExportResult result = writeGlbAnimation(take, file("take.glb"), {}, nullptr);
  const GlbFile glb = GlbFile::read(file("take.glb"));
  ASSERT_EQ(glb.json.at("meshes").size(), 2u);
  ASSERT_EQ(glb.json.at("nodes").size(), 2u);
  EXPECT_EQ(glb.json.at("scenes").at(0).at("nodes"), json::array({0, 1}));
  EXPECT_EQ(glb.json.at("nodes").at(0).at("name"), "take_segment_1");
  // A viewer without animation shows the first segment only.
  EXPECT_FALSE(glb.json.at("nodes").at(0).contains("scale"));
  EXPECT_EQ(glb.json.at("nodes").at(1).at("scale"), json::array({0.0, 0.0, 0.0}));
  size_t targets = 0;
  for (size_t s = 0; s < 2; ++s) {
    const json& mesh = glb.json.at("meshes").at(s);
    targets += mesh.at("primitives").at(0).at("targets").size();
    EXPECT_EQ(
        glb.values<float>(mesh.at("primitives").at(0).at("attributes").at("POSITION").get<int>())
            .size(),
        3 * size_t(take.restSurface(uint32_t(s)).numVertices()));
  }
  EXPECT_EQ(targets, result.keys);
  const float end = static_cast<float>(take.frameTime(59));
  for (size_t s = 0; s < 2; ++s) {
    const Sampler scale = channelSampler(glb, s, "scale", 3);
    ASSERT_EQ(scale.width, 3u);
    EXPECT_TRUE(scale.step);
    EXPECT_EQ(scale.times.front(), 0.0f);
    EXPECT_EQ(scale.times.back(), end);
    for (uint32_t f = 0; f < 60; ++f) {
      const double shown = take.segmentOf(f) == s ? 1.0 : 0.0;
      EXPECT_EQ(scale.at(static_cast<float>(take.frameTime(f))), std::vector<double>(3, shown))
          << f;
    }
  }
  expectFramesReproduced(glb, take, 1e-3);
  expectExactBounds(glb);
}

TEST_F(GlbAnimationTest, SingleFrameSegmentsHaveOneKey) {
  const FakeAnimatedSurface take(3, 30.0, 3, kAmplitude);
  const ExportResult result = writeGlbAnimation(take, file("take.glb"), {}, nullptr);
  EXPECT_EQ(result.keys, 3u);
  const GlbFile glb = GlbFile::read(file("take.glb"));
  for (const json& mesh : glb.json.at("meshes"))
    EXPECT_EQ(mesh.at("primitives").at(0).at("targets").size(), 1u);
  expectFramesReproduced(glb, take, 1e-3);
  expectExactBounds(glb);
}

TEST_F(GlbAnimationTest, FinerToleranceGivesMoreKeys) {
  const FakeAnimatedSurface take(90, 30.0, 1, kAmplitude);
  GlbAnimationOptions fine;
  fine.keyTolerance = 1e-5;
  fine.name = "fine";
  const ExportResult coarse = writeGlbAnimation(take, file("coarse.glb"), {}, nullptr);
  const ExportResult finer = writeGlbAnimation(take, file("fine.glb"), fine, nullptr);
  EXPECT_GT(finer.keys, coarse.keys);
  const GlbFile glb = GlbFile::read(file("fine.glb"));
  EXPECT_EQ(glb.json.at("meshes").at(0).at("extras").at("targetNames").at(0), "fine_key_0001");
  EXPECT_EQ(glb.json.at("animations").at(0).at("name"), "fine");
  expectFramesReproduced(glb, take, 1e-5);
}

TEST_F(GlbAnimationTest, CancelLeavesNoFileAndKeepsTheOldOne) {
  const FakeAnimatedSurface take(60, 30.0, 2, kAmplitude);
  writeFileAtomically(file("take.glb"), "old");
  for (const double stopAt : {0.2, 0.7}) {  // choosing keys, writing them
    SCOPED_TRACE(stopAt);
    ProgressReporter progress([&](double fraction, std::string_view) { return fraction < stopAt; });
    const ExportResult result = writeGlbAnimation(take, file("take.glb"), {}, &progress);
    EXPECT_TRUE(result.cancelled);
    EXPECT_TRUE(result.files.empty());
    EXPECT_EQ(readFile(file("take.glb")), "old");
    EXPECT_EQ(entries(), std::vector<std::string>{"take.glb"});
  }
  // Uncancelled, the progress reaches 1.
  double lastFraction = 0.0;
  ProgressReporter progress([&](double fraction, std::string_view) {
    EXPECT_GE(fraction, lastFraction);
    lastFraction = fraction;
    return true;
  });
  writeGlbAnimation(take, file("take.glb"), {}, &progress);
  EXPECT_DOUBLE_EQ(lastFraction, 1.0);
}

TEST_F(GlbAnimationTest, RefusesFilesOverFourGiB) {
  // Every frame a key: the one-hot weights alone take keys^2 x 4 bytes, over 4 GiB.
  const FakeAnimatedSurface take(33000, 30.0);
  GlbAnimationOptions options;
  options.maxKeySpan = 1;
  writeFileAtomically(file("take.glb"), "old");
  try {
    writeGlbAnimation(take, file("take.glb"), options, nullptr);
    FAIL() << "no FileError";
  } catch (const FileError& error) {
    EXPECT_EQ(std::string(error.what()),
              file("take.glb").string() +
                  ": 33000 keys of 12 vertices need 4.1 GiB, over glTF binary's 4 GiB limit; raise "
                  "--key-tolerance or record fewer frames");
  }
  EXPECT_EQ(readFile(file("take.glb")), "old");
  EXPECT_EQ(entries(), std::vector<std::string>{"take.glb"});

  GlbSegmentLayout big;
  big.vertices = 1'000'000;
  big.normals = true;
  big.keys = 180;  // 180 x 24 MB
  EXPECT_GT(glbBinaryBytes({big}), kGlbMaxBytes);
  EXPECT_THROW(checkGlbSize("big.glb", glbBinaryBytes({big}), {big}), FileError);
  big.keys = 170;
  EXPECT_NO_THROW(checkGlbSize("big.glb", glbBinaryBytes({big}), {big}));
}

TEST_F(GlbAnimationTest, UnwritablePathThrowsFileError) {
  const FakeAnimatedSurface take(10, 30.0, 1, kAmplitude);
  const auto path = file("missing") / "take.glb";
  try {
    writeGlbAnimation(take, path, {}, nullptr);
    FAIL() << "no FileError";
  } catch (const FileError& error) {
    EXPECT_EQ(std::string(error.what()).rfind(path.string() + ": cannot create", 0), 0u)
        << error.what();
  }
  EXPECT_THROW(writeGlbAnimation(FakeAnimatedSurface(0, 30.0), file("empty.glb"), {}, nullptr),
               FileError);
}


TEST_F(GlbAnimationTest, PassesTheKhronosValidator) {
  const auto script = test::gltfValidatorScript();
  ASSERT_FALSE(script.empty())
      << "the glTF validator is not installed: run scripts/install-gltf-validator.sh";
  ASSERT_EQ(std::system("node --version > /dev/null 2>&1"), 0)
      << "node is not installed (needed by the glTF validator; see "
         "scripts/install-gltf-validator.sh)";
  writeGlbAnimation(FakeAnimatedSurface(90, 30.0, 1, kAmplitude), file("one.glb"), {}, nullptr);
  writeGlbAnimation(FakeAnimatedSurface(90, 30.0, 2, kAmplitude), file("two.glb"), {}, nullptr);
  writeGlbAnimation(FakeAnimatedSurface(3, 30.0, 3, kAmplitude), file("single_frames.glb"), {},
                    nullptr);
  for (const char* name : {"one.glb", "two.glb", "single_frames.glb"}) {
    const auto report = file(std::string(name) + ".report");
    const std::string command = "node " + test::shellQuote(script.string()) + " " +
                                test::shellQuote(file(name).string()) + " > " +
                                test::shellQuote(report.string()) + " 2>&1";
    const int status = std::system(command.c_str());
    const std::string text = readFile(report);
    EXPECT_EQ(status, 0) << name << ":\n" << text;
    EXPECT_NE(text.find("errors=0 warnings=0"), std::string::npos) << name << ":\n" << text;
    std::printf("%s: %s", name, text.c_str());
  }
}

}  // namespace
}  // namespace sculpt
