// The OBJ sequence writer, read back with a small OBJ reader here and checked against the take
// (positions bit for bit) and against the rest surface (texture coordinates, face syntax).

#include "anim/obj_sequence_writer.h"

#include <gtest/gtest.h>

#include <bit>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "anim/export_test_files.h"
#include "anim/fake_animated_surface.h"
#include "io/file_error.h"
#include "support/scratch_directory.h"

namespace sculpt {
namespace {

using test::FakeAnimatedSurface;

// The fake take with corners of every OBJ syntax (v, v/vt, v//vn, v/vt/vn) in its first
// segment, and no normals at all in its second.
class MixedCornerSurface : public FakeAnimatedSurface {
 public:
  MixedCornerSurface(uint32_t frames, double fps) : FakeAnimatedSurface(frames, fps, 2) {
    for (uint32_t s = 0; s < 2; ++s) {
      SurfaceMesh mesh = FakeAnimatedSurface::restSurface(s);
      for (size_t k = 0; k < mesh.faces.values.size(); ++k) {
        SurfaceCorner& corner = mesh.faces.values[k];
        if (s == 1 || k % 4 == 0 || k % 4 == 1) corner.normal = SurfaceCorner::kNoIndex;
        if (k % 4 == 0 || k % 4 == 2) corner.texcoord = SurfaceCorner::kNoIndex;
      }
      if (s == 1) mesh.normals.resize(0, 3);
      rest_.push_back(std::move(mesh));
    }
  }
  const SurfaceMesh& restSurface(uint32_t s) const override { return rest_[s]; }

 private:
  std::vector<SurfaceMesh> rest_;
};

struct ObjFile {
  std::string header;
  std::vector<float> positions;                 // 3 per v
  std::vector<double> texcoords;                // 2 per vt
  std::vector<float> normals;                   // 3 per vn
  std::vector<std::vector<std::string>> faces;  // corner tokens as written
};

ObjFile readObj(const std::filesystem::path& path) {
  ObjFile obj;
  std::istringstream in(test::fileBytes(path));
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string keyword, word;
    words >> keyword;
    if (keyword == "#") {
      if (obj.header.empty()) obj.header = line;
    } else if (keyword == "v" || keyword == "vn") {
      std::vector<float>& out = keyword == "v" ? obj.positions : obj.normals;
      for (int k = 0; k < 3 && words >> word; ++k)
        out.push_back(std::strtof(word.c_str(), nullptr));
    } else if (keyword == "vt") {
      for (int k = 0; k < 2 && words >> word; ++k)
        obj.texcoords.push_back(std::strtod(word.c_str(), nullptr));
    } else if (keyword == "f") {
      obj.faces.emplace_back();
      while (words >> word) obj.faces.back().push_back(word);
    } else if (!keyword.empty()) {
      ADD_FAILURE() << path << ": unexpected line " << line;
    }
  }
  return obj;
}

std::string cornerText(const SurfaceCorner& corner) {
  std::string text = std::to_string(corner.position + 1);
  const bool t = corner.texcoord != SurfaceCorner::kNoIndex;
  const bool n = corner.normal != SurfaceCorner::kNoIndex;
  if (t && n)
    return text + "/" + std::to_string(corner.texcoord + 1) + "/" +
           std::to_string(corner.normal + 1);
  if (t) return text + "/" + std::to_string(corner.texcoord + 1);
  if (n) return text + "//" + std::to_string(corner.normal + 1);
  return text;
}

void expectBitsEqual(const std::vector<float>& read, const std::vector<float>& expected,
                     const std::string& what) {
  ASSERT_EQ(read.size(), expected.size()) << what;
  for (size_t i = 0; i < read.size(); ++i) {
    ASSERT_EQ(std::bit_cast<uint32_t>(read[i]), std::bit_cast<uint32_t>(expected[i]))
        << what << " value " << i << ": " << read[i] << " vs " << expected[i];
  }
}

std::string frameName(uint32_t n) {
  std::string digits = std::to_string(n);
  return "wave_" + std::string(4 - digits.size(), '0') + digits + ".obj";
}

TEST(ObjSequenceWriter, EveryFrameKeepsTheRestSurfaceAndTheTakesPositions) {
  test::ScratchDirectory dir("sculpt_obj_sequence");
  const MixedCornerSurface take(6, 30.0);
  const ExportResult result = writeObjSequence(take, dir.path() / "wave_####.obj", nullptr);
  ASSERT_EQ(result.files.size(), 6u);
  EXPECT_EQ(result.frames, 6u);
  uint64_t bytes = 0;
  SurfaceFrameData frame;
  for (uint32_t f = 0; f < 6; ++f) {
    const auto path = dir.path() / frameName(f + 1);
    EXPECT_EQ(result.files[f], path);
    bytes += std::filesystem::file_size(path);
    const ObjFile obj = readObj(path);
    const SurfaceMesh& rest = take.restSurface(take.segmentOf(f));
    take.evaluateSurface(f, frame);
    EXPECT_EQ(obj.header.rfind("# frame " + std::to_string(f + 1) + " of 6, t = ", 0), 0u)
        << obj.header;
    const std::string what = frameName(f + 1);
    expectBitsEqual(obj.positions, frame.positions, what + " positions");
    if (rest.normals.rows() > 0) {
      expectBitsEqual(obj.normals, frame.sourceNormals, what + " normals");
    } else {
      EXPECT_TRUE(obj.normals.empty()) << what;
    }
    ASSERT_EQ(obj.texcoords.size(), 2u * rest.texcoords.rows()) << what;
    for (Eigen::Index t = 0; t < rest.texcoords.rows(); ++t) {
      EXPECT_EQ(obj.texcoords[2 * t], rest.texcoords(t, 0));
      EXPECT_EQ(obj.texcoords[2 * t + 1], rest.texcoords(t, 1));
    }
    ASSERT_EQ(obj.faces.size(), rest.numFaces()) << what;
    for (uint32_t face = 0; face < rest.numFaces(); ++face) {
      std::vector<std::string> expected;
      for (const SurfaceCorner& corner : rest.faces.row(face))
        expected.push_back(cornerText(corner));
      EXPECT_EQ(obj.faces[face], expected) << what << " face " << face;
    }
  }
  EXPECT_EQ(result.bytes, bytes);
  // The first segment's file has every corner syntax.
  const ObjFile first = readObj(dir.path() / frameName(1));
  EXPECT_EQ(first.faces[0], (std::vector<std::string>{"1", "2/2", "6//6", "5/5/5"}));
  EXPECT_EQ(test::fileNames(dir.path()).size(), 6u);
}

TEST(ObjSequenceWriter, CancelRemovesTheFramesItWrote) {
  test::ScratchDirectory dir("sculpt_obj_cancel");
  { std::ofstream(dir.path() / "notes.txt") << "kept"; }
  const FakeAnimatedSurface take(6, 30.0);
  ProgressReporter progress = test::cancelAfter(2);
  const ExportResult result = writeObjSequence(take, dir.path() / "wave_####.obj", &progress);
  EXPECT_TRUE(result.cancelled);
  EXPECT_TRUE(result.files.empty());
  EXPECT_EQ(test::fileNames(dir.path()), std::set<std::string>{"notes.txt"});
  EXPECT_EQ(test::fileBytes(dir.path() / "notes.txt"), "kept");
}

TEST(ObjSequenceWriter, AFailedFrameRemovesTheFramesBeforeIt) {
  test::ScratchDirectory dir("sculpt_obj_failure");
  std::filesystem::create_directory(dir.path() / frameName(3));  // frame 3 cannot replace it
  const FakeAnimatedSurface take(5, 30.0);
  try {
    writeObjSequence(take, dir.path() / "wave_####.obj");
    FAIL() << "wrote over a directory";
  } catch (const FileError& error) {
    EXPECT_EQ(std::string(error.what()).rfind((dir.path() / frameName(3)).string(), 0), 0u)
        << error.what();
  }
  EXPECT_EQ(test::fileNames(dir.path()), std::set<std::string>{frameName(3)});
}

TEST(ObjSequenceWriter, PatternWithoutHashIsRefused) {
  const FakeAnimatedSurface take(2, 30.0);
  try {
    writeObjSequence(take, "name.obj");
    FAIL() << "accepted a name without #";
  } catch (const std::invalid_argument& error) {
    EXPECT_STREQ(error.what(),
                 "'name.obj' is not a sequence pattern: put #### where the frame number goes, "
                 "e.g. name_####.obj");
  }
  EXPECT_FALSE(std::filesystem::exists("name.obj"));
}

TEST(ObjSequenceWriter, MissingDirectoryThrowsAndLeavesNothing) {
  test::ScratchDirectory dir("sculpt_obj_missing");
  const FakeAnimatedSurface take(3, 30.0);
  EXPECT_THROW(writeObjSequence(take, dir.path() / "missing" / "wave_##.obj"), FileError);
  EXPECT_TRUE(test::fileNames(dir.path()).empty());
}

TEST(ObjSequenceWriter, TwoRunsWriteIdenticalBytes) {
  test::ScratchDirectory dir("sculpt_obj_repeat");
  const FakeAnimatedSurface take(3, 24.0, 2);
  writeObjSequence(take, dir.path() / "a_##.obj");
  writeObjSequence(take, dir.path() / "b_##.obj");
  for (const char* n : {"01", "02", "03"}) {
    EXPECT_EQ(test::fileBytes(dir.path() / ("a_" + std::string(n) + ".obj")),
              test::fileBytes(dir.path() / ("b_" + std::string(n) + ".obj")));
  }
}

}  // namespace
}  // namespace sculpt
