// sculpt-cli end to end: every bad input ends with exit code 2 and one line on stderr naming the
// file, never with a signal; subdivide writes files that load again.

#include <gtest/gtest.h>

#include <filesystem>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "io/control_mesh_json.h"
#include "mesh/validation.h"
#include "support/cli_fixture.h"
#include "support/mesh_builders.h"

namespace sculpt {
namespace {

namespace fs = std::filesystem;

const std::string kData = SCULPT_SOURCE_DIR "/tests/data/";

using test::CliResult;
using test::isMilliseconds;
using test::keyValues;
using test::quote;
using test::readText;
using test::writeText;

class CliTest : public test::CliFixture {
 protected:
  CliTest() : CliFixture("sculpt_cli_test_") {}
};

TEST_F(CliTest, UsageAndBadUsage) {
  const CliResult help = run("--help");
  EXPECT_EQ(help.exitCode, 0);
  EXPECT_NE(help.out.find("usage: sculpt-cli"), std::string::npos);
  EXPECT_NE(help.out.find("subdivide CONTROL.json --levels K"), std::string::npos);
  EXPECT_EQ(run("subdivide --help").exitCode, 0);
  EXPECT_EQ(run("").exitCode, 2);

  const std::string cube = quote(kData + "cube.json");
  expectBadInput("frobnicate", "unknown command 'frobnicate'");
  expectBadInput("info " + cube + " --bogus", "unknown option '--bogus'");
  expectBadInput("info " + cube + " --levels", "'--levels' needs a value");
  expectBadInput("info", "exactly one FILE");
  expectBadInput("subdivide " + cube + " --levels 9 --out " + quote(path("x.json")), "0 to 6");
  expectBadInput("subdivide " + cube + " --levels=two --out " + quote(path("x.json")), "'two'");
  expectBadInput("subdivide " + cube + " --out " + quote(path("x.json")), "--levels is required");
  expectBadInput("subdivide " + cube + " --levels 1", "--out is required");
  expectBadInput("subdivide " + cube + " --levels 1 --out " + quote(path("x.stl")),
                 "unknown extension");
  expectBadInput("subdivide " + cube + " --levels 1 --out " + quote(path("x.vtk")) +
                     " --boundary " + quote(path("b.ply")),
                 "unknown extension");
  expectBadInput("bench subdivide " + cube, "--levels is required");
  expectBadInput("bench frobnicate " + cube + " --levels 1", "unknown benchmark");
  EXPECT_FALSE(fs::exists(path("x.json")));
}

TEST_F(CliTest, MissingFileIsExit2NamingTheFile) {
  expectBadInput("info " + quote(path("nowhere.json")), "nowhere.json: cannot open");
  expectBadInput(
      "subdivide " + quote(path("nowhere.json")) + " --levels 1 --out " + quote(path("x.json")),
      "nowhere.json: cannot open");
  expectBadInput("info " + quote(dir_.string()), "is a directory");
}

TEST_F(CliTest, TruncatedJsonIsExit2WithOneLineNamingTheFile) {
  const std::string cube = readText(kData + "cube.json");
  ASSERT_GT(cube.size(), 100u);
  for (size_t length : {size_t{1}, size_t{17}, cube.size() / 2, cube.size() - 3}) {
    const std::string file = path("truncated_" + std::to_string(length) + ".json");
    writeText(file, cube.substr(0, length));
    expectBadInput("info " + quote(file), file + ": not valid JSON");
    expectBadInput("subdivide " + quote(file) + " --levels 1 --out " + quote(path("o.json")),
                   file + ": not valid JSON");
  }
  EXPECT_FALSE(fs::exists(path("o.json")));
}

TEST_F(CliTest, GarbageNeverCrashes) {
  std::mt19937 rng(12345);
  std::vector<std::string> garbage = {
      "",   std::string(1, '\0'),  "\xff\xfe\xfd",          "null", "{}",
      "[]", "{\"format\": 1e999}", std::string(100000, '[')};
  for (size_t size : {16, 256, 4096, 65536}) {
    std::string bytes(size, '\0');
    for (char& ch : bytes) ch = static_cast<char>(rng() & 0xff);
    garbage.push_back(bytes);
  }
  const std::string jsonish = "[]{}\",:0123456789.-eE truefalsnul";
  for (int i = 0; i < 4; ++i) {
    std::string text(200 + rng() % 2000, ' ');
    for (char& ch : text) ch = jsonish[rng() % jsonish.size()];
    garbage.push_back(text);
  }
  for (size_t i = 0; i < garbage.size(); ++i) {
    const std::string file = path("garbage_" + std::to_string(i) + ".json");
    writeText(file, garbage[i]);
    expectBadInput("info " + quote(file), file);
    expectBadInput("subdivide " + quote(file) + " --levels 1 --out " + quote(path("o.vtk")), file);
  }
}

TEST_F(CliTest, MutatedMeshesExitCleanly) {
  // Small edits of a valid file may still be valid; whatever happens, it is 0 or 2, never a
  // signal, and a failure is one line.
  const std::string house = readText(kData + "house_small.json");
  std::mt19937 rng(777);
  const std::string alphabet = "0123456789-.,[]\" e";
  for (int i = 0; i < 24; ++i) {
    std::string text = house;
    for (int e = 0; e < 1 + i % 3; ++e)
      text[rng() % text.size()] = alphabet[rng() % alphabet.size()];
    const std::string file = path("mutated_" + std::to_string(i) + ".json");
    writeText(file, text);
    for (const std::string& args :
         {"info " + quote(file) + " --levels 1",
          "subdivide " + quote(file) + " --levels 2 --out " + quote(path("m.vtk"))}) {
      SCOPED_TRACE(args);
      const CliResult result = run(args);
      EXPECT_FALSE(result.signaled) << result.err;
      EXPECT_TRUE(result.exitCode == 0 || result.exitCode == 2) << result.exitCode;
      if (result.exitCode == 2) {
        EXPECT_EQ(result.errLines().size(), 1u) << result.err;
      }
    }
  }
}

TEST_F(CliTest, SubdivideCubeWritesJsonThatLoadsAgain) {
  const std::string cube = quote(kData + "cube.json");
  for (int levels : {1, 2}) {
    const std::string out = path("cube_" + std::to_string(levels) + ".json");
    const CliResult result =
        run("subdivide " + cube + " --levels " + std::to_string(levels) + " --out " + quote(out));
    ASSERT_EQ(result.exitCode, 0) << result.err;
    const CellComplex mesh = loadControlMeshJson(out);
    EXPECT_EQ(mesh.numCells(), levels == 1 ? 8u : 64u);
    EXPECT_EQ(mesh.numVertices(), levels == 1 ? 27u : 125u);
    EXPECT_TRUE(isValid(validate(mesh)));
    EXPECT_NE(result.out.find("wrote " + out + " (cells=" + std::to_string(mesh.numCells()) +
                              ", vertices=" + std::to_string(mesh.numVertices()) + ")"),
              std::string::npos)
        << result.out;
    // The written file is a control mesh in its own right: refine it once more.
    const CliResult again = run("info " + quote(out) + " --levels 1");
    EXPECT_EQ(again.exitCode, 0) << again.err;
  }
}

TEST_F(CliTest, LevelZeroWritesTheControlMesh) {
  const std::string out = path("same.json");
  ASSERT_EQ(
      run("subdivide " + quote(kData + "house_small.json") + " --levels 0 --out " + quote(out))
          .exitCode,
      0);
  const CellComplex original = loadControlMeshJson(kData + "house_small.json");
  const CellComplex written = loadControlMeshJson(out);
  EXPECT_EQ(written.positions, original.positions);
  EXPECT_EQ(written.cellFaceBegin, original.cellFaceBegin);
  EXPECT_EQ(written.loopBegin, original.loopBegin);
  EXPECT_EQ(written.loopVertices, original.loopVertices);
  EXPECT_EQ(written.creases, original.creases);
  EXPECT_EQ(written.corners, original.corners);
}

TEST_F(CliTest, SubdivideWritesVtkAndBoundaryObj) {
  const std::string vtk = path("house.vtk");
  const std::string obj = path("house.obj");
  const CliResult result = run("subdivide " + quote(kData + "house_small.json") +
                               " --levels 1 --out " + quote(vtk) + " --boundary " + quote(obj));
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const std::string text = readText(vtk);
  EXPECT_EQ(text.rfind("# vtk DataFile Version 4.2\n", 0), 0u);
  EXPECT_NE(text.find("CELL_TYPES 13\n"), std::string::npos);  // 8 + 5 children
  EXPECT_NE(readText(obj).find("\nf "), std::string::npos);
  EXPECT_NE(result.out.find("wrote " + obj), std::string::npos);
  // Writing into a folder that does not exist names the output file.
  expectBadInput("subdivide " + quote(kData + "cube.json") + " --levels 1 --out " +
                     quote(path("no_dir/x.vtk")),
                 "x.vtk");
}

TEST_F(CliTest, InfoReportsCountsAndValidation) {
  const CliResult valid = run("info " + quote(kData + "house_small.json") + " --levels 1");
  ASSERT_EQ(valid.exitCode, 0) << valid.err;
  for (const char* line :
       {"vertices: 9\n", "cells: 2\n", "cells_by_shape: pyramid=1 hex=1\n", "boundary_faces: 9\n",
        "creases: 4\n", "corners: 4\n", "bounding_box_max: 1 1 1.5\n", "validation: valid\n",
        "level 1:\n", "  cells: 13\n", "  cells_by_shape: hex=12 trapezohedron=1\n",
        "  irregular: 1\n"}) {
    EXPECT_NE(valid.out.find(line), std::string::npos) << line << " not in:\n" << valid.out;
  }

  const std::string inverted = kData + "inverted_hex.json";
  const CliResult invalid = run("info " + quote(inverted) + " --levels 1");
  EXPECT_FALSE(invalid.signaled);
  EXPECT_EQ(invalid.exitCode, 2);
  EXPECT_NE(invalid.out.find("validation: invalid"), std::string::npos) << invalid.out;
  EXPECT_NE(invalid.out.find("  error: cell 0"), std::string::npos) << invalid.out;
  ASSERT_EQ(invalid.errLines().size(), 1u) << invalid.err;
  EXPECT_NE(invalid.errLines()[0].find(inverted + ": cell 0"), std::string::npos);

  expectBadInput("subdivide " + quote(inverted) + " --levels 1 --out " + quote(path("x.json")),
                 inverted + ": cell 0");
}

TEST_F(CliTest, InfoOnOutOfRangeIndicesDoesNotBuildTopology) {
  const std::string file = path("range.json");
  writeText(file, R"({"format": "sculpt-control-mesh", "version": 1,
    "vertices": [[0,0,0],[1,0,0],[0,1,0],[0,0,1]],
    "cells": [{"type": "tet", "vertices": [0, 1, 2, 40]}], "corners": [99]})");
  const CliResult result = run("info " + quote(file));
  EXPECT_FALSE(result.signaled);
  EXPECT_EQ(result.exitCode, 2);
  EXPECT_NE(result.out.find("topology: not built"), std::string::npos) << result.out;
  ASSERT_EQ(result.errLines().size(), 1u) << result.err;
}

TEST_F(CliTest, RefusesRefinementsThatWouldBeTooLarge) {
  // 6x6x6 hexes: 216 * 8^6 = 56.6 million cells at level 6.
  const std::string file = path("block6.json");
  saveControlMeshJson(test::hexGrid(6, 6, 6), file);
  expectBadInput("subdivide " + quote(file) + " --levels 6 --out " + quote(path("x.vtk")),
                 "more than 50000000");
  expectBadInput("info " + quote(file) + " --levels 6", "more than 50000000");
  EXPECT_EQ(run("info " + quote(file) + " --levels 1").exitCode, 0);
}

TEST_F(CliTest, BenchPrintsKeyValueLastLine) {
  const CliResult result =
      run("bench subdivide " + quote(kData + "cube.json") + " --levels 2 --repeat 1");
  ASSERT_EQ(result.exitCode, 0) << result.err;
  std::vector<std::string> lines;
  std::istringstream in(result.out);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  ASSERT_GE(lines.size(), 2u);
  // The last line: exactly these keys in this order; times with 3 decimals.
  const auto pairs = keyValues(lines.back());
  ASSERT_EQ(pairs.size(), 4u) << lines.back();
  EXPECT_EQ(pairs[0].first, "subdivide_ms");
  EXPECT_TRUE(isMilliseconds(pairs[0].second)) << lines.back();
  EXPECT_EQ(pairs[1].first, "apply_ms");
  EXPECT_TRUE(isMilliseconds(pairs[1].second)) << lines.back();
  EXPECT_EQ(pairs[2], (std::pair<std::string, std::string>("cells", "64")));
  EXPECT_EQ(pairs[3], (std::pair<std::string, std::string>("vertices", "125")));
  const auto before = keyValues(lines[lines.size() - 2]);
  ASSERT_GE(before.size(), 2u) << lines[lines.size() - 2];
  EXPECT_EQ(before[0].first, "composed_apply_ms");
  EXPECT_TRUE(isMilliseconds(before[0].second));
  EXPECT_EQ(before[1].first, "entries");
  EXPECT_NE(result.out.find("threads="), std::string::npos);
}

}  // namespace
}  // namespace sculpt
