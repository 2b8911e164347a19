// The VTK sequence writer, read back by hand (legacy binary byte layout, VTK XML text, the .pvd
// and .vtk.series collections) and checked against the take's solid frame by frame.

#include "anim/vtk_sequence_writer.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <regex>
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

// A legacy file, walked keyword by keyword: text lines, then the binary block they announce.
class LegacyReader {
 public:
  explicit LegacyReader(std::string bytes) : bytes_(std::move(bytes)) {}
  std::string line() {
    const size_t end = bytes_.find('\n', at_);
    EXPECT_NE(end, std::string::npos);
    std::string text = bytes_.substr(at_, end - at_);
    at_ = end + 1;
    return text;
  }
  std::vector<double> doubles(size_t n) {
    std::vector<double> out;
    for (size_t i = 0; i < n; ++i, at_ += 8) out.push_back(test::bigEndianDouble(bytes_, at_));
    endOfBlock();
    return out;
  }
  std::vector<float> floats(size_t n) {
    std::vector<float> out;
    for (size_t i = 0; i < n; ++i, at_ += 4) out.push_back(test::bigEndianFloat(bytes_, at_));
    endOfBlock();
    return out;
  }
  std::vector<uint32_t> ints(size_t n) {
    std::vector<uint32_t> out;
    for (size_t i = 0; i < n; ++i, at_ += 4) out.push_back(test::bigEndian32(bytes_, at_));
    endOfBlock();
    return out;
  }
  bool atEnd() const { return at_ == bytes_.size(); }

 private:
  void endOfBlock() {
    ASSERT_LT(at_, bytes_.size());
    EXPECT_EQ(bytes_[at_], '\n');
    ++at_;
  }
  std::string bytes_;
  size_t at_ = 0;
};

std::vector<double> flatten(const Points& points) {
  std::vector<double> out;
  for (Eigen::Index i = 0; i < points.rows(); ++i)
    for (Eigen::Index k = 0; k < 3; ++k) out.push_back(points(i, k));
  return out;
}

std::string frameName(uint32_t n, const std::string& extension) {
  std::string digits = std::to_string(n);
  return "solid_" + std::string(3 - digits.size(), '0') + digits + extension;
}

// (file, timestep) of every DataSet of a .pvd.
std::vector<std::pair<std::string, double>> pvdDataSets(const std::filesystem::path& path) {
  const std::string text = test::fileBytes(path);
  EXPECT_NE(text.find("<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">"),
            std::string::npos);
  std::vector<std::pair<std::string, double>> out;
  const std::regex dataSet(
      "<DataSet timestep=\"([^\"]*)\" group=\"\" part=\"0\" file=\"([^\"]*)\"/>");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), dataSet);
       it != std::sregex_iterator(); ++it) {
    out.emplace_back((*it)[2].str(), std::strtod((*it)[1].str().c_str(), nullptr));
  }
  return out;
}

void expectCollections(const FakeAnimatedSurface& take, const std::filesystem::path& dir,
                       const std::string& extension) {
  const auto dataSets = pvdDataSets(dir / "solid.pvd");
  ASSERT_EQ(dataSets.size(), take.frameCount());
  for (uint32_t f = 0; f < take.frameCount(); ++f) {
    EXPECT_EQ(dataSets[f].first, frameName(f + 1, extension));
    EXPECT_EQ(dataSets[f].second, f / take.fps());
  }
}

TEST(VtkSequenceWriter, LegacyBinaryFramesHoldTheDeformedSolid) {
  test::ScratchDirectory dir("sculpt_vtk_legacy");
  const FakeAnimatedSurface take(4, 25.0, 2);
  const ExportResult result = writeVtkSequence(take, dir.path() / "solid_###.vtk");
  EXPECT_EQ(result.frames, 4u);
  ASSERT_EQ(result.files.size(), 6u);  // 4 frames, .vtk.series, .pvd
  EXPECT_EQ(result.files[4], dir.path() / "solid.vtk.series");
  EXPECT_EQ(result.files[5], dir.path() / "solid.pvd");
  uint64_t bytes = 0;
  for (const auto& file : result.files) bytes += std::filesystem::file_size(file);
  EXPECT_EQ(result.bytes, bytes);

  SolidFrameData solid;
  for (uint32_t f = 0; f < 4; ++f) {
    const VolumeMesh& rest = take.restSolid(take.segmentOf(f));
    take.evaluateSolid(f, solid);
    const uint32_t nodes = rest.numNodes(), cells = rest.numCells();
    LegacyReader in(test::fileBytes(dir.path() / frameName(f + 1, ".vtk")));
    EXPECT_EQ(in.line(), "# vtk DataFile Version 4.2");
    EXPECT_EQ(in.line().rfind("frame " + std::to_string(f + 1) + " of 4", 0), 0u);
    EXPECT_EQ(in.line(), "BINARY");
    EXPECT_EQ(in.line(), "DATASET UNSTRUCTURED_GRID");
    EXPECT_EQ(in.line(), "POINTS " + std::to_string(nodes) + " double");
    EXPECT_EQ(in.doubles(3 * nodes), flatten(solid.nodes));  // exact
    EXPECT_EQ(in.line(), "CELLS " + std::to_string(cells) + " " +
                             std::to_string(rest.cells.values.size() + cells));
    std::vector<uint32_t> expectedCells;
    for (uint32_t c = 0; c < cells; ++c) {
      expectedCells.push_back(rest.cells.rowSize(c));
      for (const uint32_t node : rest.cells.row(c)) expectedCells.push_back(node);
    }
    EXPECT_EQ(in.ints(expectedCells.size()), expectedCells);
    EXPECT_EQ(in.line(), "CELL_TYPES " + std::to_string(cells));
    EXPECT_EQ(in.ints(cells), (std::vector<uint32_t>{12, 10}));  // the hexahedron, the tetrahedron
    EXPECT_EQ(in.line(), "POINT_DATA " + std::to_string(nodes));
    EXPECT_EQ(in.line(), "VECTORS displacement double");
    EXPECT_EQ(in.doubles(3 * nodes), flatten(solid.displacement));
    EXPECT_EQ(in.line(), "CELL_DATA " + std::to_string(cells));
    for (const auto& [name, values] : {std::pair{"youngs_modulus", &solid.fields.youngs},
                                       std::pair{"density", &solid.fields.density},
                                       std::pair{"damping", &solid.fields.damping}}) {
      EXPECT_EQ(in.line(), std::string("SCALARS ") + name + " float 1");
      EXPECT_EQ(in.line(), "LOOKUP_TABLE default");
      EXPECT_EQ(in.floats(cells), *values) << name;
    }
    EXPECT_TRUE(in.atEnd());
  }
  EXPECT_EQ(solid.fields.youngs[0], 4.0e5f);  // the last frame's painted value

  const nlohmann::json series =
      nlohmann::json::parse(test::fileBytes(dir.path() / "solid.vtk.series"));
  EXPECT_EQ(series["file-series-version"], "1.0");
  ASSERT_EQ(series["files"].size(), 4u);
  for (uint32_t f = 0; f < 4; ++f) {
    EXPECT_EQ(series["files"][f]["name"], frameName(f + 1, ".vtk"));
    EXPECT_EQ(series["files"][f]["time"].get<double>(), f / 25.0);
  }
  expectCollections(take, dir.path(), ".vtk");
  EXPECT_EQ(test::fileNames(dir.path()).size(), 6u);
}

// The numbers of the DataArray whose opening tag contains `tag`.
std::vector<double> xmlArray(const std::string& text, const std::string& tag) {
  const size_t open = text.find(tag);
  EXPECT_NE(open, std::string::npos) << tag;
  if (open == std::string::npos) return {};
  const size_t begin = text.find('>', open) + 1;
  const size_t end = text.find("</DataArray>", begin);
  std::istringstream in(text.substr(begin, end - begin));
  std::vector<double> out;
  std::string word;
  while (in >> word) out.push_back(std::strtod(word.c_str(), nullptr));
  return out;
}

TEST(VtkSequenceWriter, XmlFramesHoldTheDeformedSolid) {
  test::ScratchDirectory dir("sculpt_vtk_xml");
  const FakeAnimatedSurface take(3, 24.0, 2);
  const ExportResult result = writeVtkSequence(take, dir.path() / "solid_###.vtu");
  ASSERT_EQ(result.files.size(), 4u);  // 3 frames and the .pvd
  SolidFrameData solid;
  for (uint32_t f = 0; f < 3; ++f) {
    const VolumeMesh& rest = take.restSolid(take.segmentOf(f));
    take.evaluateSolid(f, solid);
    const std::string text = test::fileBytes(dir.path() / frameName(f + 1, ".vtu"));
    EXPECT_NE(text.find("<VTKFile type=\"UnstructuredGrid\""), std::string::npos);
    EXPECT_NE(text.find("<Piece NumberOfPoints=\"9\" NumberOfCells=\"2\">"), std::string::npos);
    const size_t points = text.find("<Points>");
    ASSERT_NE(points, std::string::npos);
    EXPECT_EQ(xmlArray(text.substr(points), "<DataArray type=\"Float64\""), flatten(solid.nodes));
    EXPECT_EQ(xmlArray(text, "Name=\"displacement\""), flatten(solid.displacement));
    std::vector<double> connectivity(rest.cells.values.begin(), rest.cells.values.end());
    EXPECT_EQ(xmlArray(text, "Name=\"connectivity\""), connectivity);
    EXPECT_EQ(xmlArray(text, "Name=\"offsets\""), (std::vector<double>{8, 12}));
    EXPECT_EQ(xmlArray(text, "Name=\"types\""), (std::vector<double>{12, 10}));
    for (const auto& [name, values] : {std::pair{"youngs_modulus", &solid.fields.youngs},
                                       std::pair{"density", &solid.fields.density},
                                       std::pair{"damping", &solid.fields.damping}}) {
      const std::vector<double> read = xmlArray(text, std::string("Name=\"") + name + "\"");
      ASSERT_EQ(read.size(), values->size()) << name;
      for (size_t c = 0; c < read.size(); ++c) EXPECT_EQ(static_cast<float>(read[c]), (*values)[c]);
    }
  }
  expectCollections(take, dir.path(), ".vtu");
  EXPECT_EQ(test::fileNames(dir.path()).size(), 4u);
}

TEST(VtkSequenceWriter, CancelRemovesEverythingItWrote) {
  test::ScratchDirectory dir("sculpt_vtk_cancel");
  const FakeAnimatedSurface take(5, 24.0);
  for (const char* pattern : {"solid_###.vtk", "solid_###.vtu"}) {
    ProgressReporter progress = test::cancelAfter(2);
    const ExportResult result = writeVtkSequence(take, dir.path() / pattern, &progress);
    EXPECT_TRUE(result.cancelled);
    EXPECT_TRUE(result.files.empty());
    EXPECT_TRUE(test::fileNames(dir.path()).empty()) << pattern;
  }
}

TEST(VtkSequenceWriter, RefusesPatternsItCannotWrite) {
  const FakeAnimatedSurface take(2, 24.0);
  try {
    writeVtkSequence(take, "name.vtk");
    FAIL() << "accepted a name without #";
  } catch (const std::invalid_argument& error) {
    EXPECT_STREQ(error.what(),
                 "'name.vtk' is not a sequence pattern: put #### where the frame number goes, "
                 "e.g. name_####.vtk");
  }
  EXPECT_THROW(writeVtkSequence(take, "name_##.vtp"), std::invalid_argument);
  test::ScratchDirectory dir("sculpt_vtk_missing");
  EXPECT_THROW(writeVtkSequence(take, dir.path() / "missing" / "s_##.vtk"), FileError);
  EXPECT_TRUE(test::fileNames(dir.path()).empty());
}

TEST(VtkSequenceWriter, TwoRunsWriteIdenticalBytes) {
  test::ScratchDirectory dir("sculpt_vtk_repeat");
  const FakeAnimatedSurface take(3, 24.0);
  for (const char* run : {"a", "b"}) {
    std::filesystem::create_directory(dir.path() / run);
    writeVtkSequence(take, dir.path() / run / "legacy_#.vtk");
    writeVtkSequence(take, dir.path() / run / "xml_#.vtu");
  }
  const auto names = test::fileNames(dir.path() / "a");
  EXPECT_EQ(names.size(), 3u + 2u + 3u + 1u);
  EXPECT_EQ(test::fileNames(dir.path() / "b"), names);
  for (const std::string& name : names) {
    EXPECT_EQ(test::fileBytes(dir.path() / "a" / name), test::fileBytes(dir.path() / "b" / name))
        << name;
  }
}

}  // namespace
}  // namespace sculpt
