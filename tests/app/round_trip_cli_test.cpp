// sculpt-cli's documented round trip: whatever `info` accepts, `subdivide --levels 1` writes as
// a file that `info` accepts too: every asset, the test meshes, cubes at any scale. What info
// refuses (a cell inside out, one inverted at a corner, one of two separate solids), subdivide
// refuses as well, naming the cell.

#include <gtest/gtest.h>

#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "io/control_mesh_json.h"
#include "support/cli_fixture.h"
#include "support/mesh_builders.h"

namespace sculpt {
namespace {

namespace fs = std::filesystem;

using test::CliResult;
using test::quote;

const std::string kData = SCULPT_SOURCE_DIR "/tests/data/";

class RoundTripCliTest : public test::CliFixture {
 protected:
  RoundTripCliTest() : CliFixture("sculpt_round_trip_test_") {}

  /// Runs info on `file` and, when it accepts it, on its level-1 subdivision; returns whether
  /// info accepted `file`.
  bool expectRoundTrip(const std::string& file) const {
    SCOPED_TRACE(file);
    const CliResult info = run("info " + quote(file));
    EXPECT_FALSE(info.signaled) << info.err;
    const std::string level1 = path("level1.json");
    const CliResult subdivide =
        run("subdivide " + quote(file) + " --levels 1 --out " + quote(level1));
    EXPECT_FALSE(subdivide.signaled) << subdivide.err;
    if (info.exitCode != 0) {
      EXPECT_EQ(info.exitCode, 2) << info.err;
      EXPECT_EQ(subdivide.exitCode, 2) << subdivide.err;
      return false;
    }
    EXPECT_EQ(subdivide.exitCode, 0) << subdivide.err;
    const CliResult again = run("info " + quote(level1));
    EXPECT_EQ(again.exitCode, 0) << "info accepts " << file << " but not its level 1:\n"
                                 << again.err;
    EXPECT_NE(again.out.find("validation: valid"), std::string::npos) << again.out;
    return true;
  }
};

TEST_F(RoundTripCliTest, WhatInfoAcceptsSubdividesIntoWhatInfoAccepts) {
  std::vector<std::string> files;
  for (const auto& entry : fs::directory_iterator(SCULPT_SOURCE_DIR "/assets")) {
    if (entry.path().extension() != ".json") continue;
    // The mock stylus' device scripts live there too.
    if (test::readText(entry.path()).find("\"sculpt-device-script\"") != std::string::npos)
      continue;
    files.push_back(entry.path().string());
  }
  ASSERT_GE(files.size(), 8u);
  for (const char* name : {"cube.json", "house_small.json", "inverted_hex.json",
                           "inverted_corner_hex.json", "disjoint_cell.json"})
    files.push_back(kData + name);
  size_t accepted = 0;
  for (const std::string& file : files) accepted += expectRoundTrip(file);
  EXPECT_EQ(accepted, files.size() - 3) << "all but the three invalid test meshes";

  expectBadInput("info " + quote(kData + "inverted_hex.json"), "cell 0 has negative volume");
  expectBadInput("info " + quote(kData + "inverted_corner_hex.json"),
                 "inverted_corner_hex.json: cell 0 is inverted at vertex 7: ");
  expectBadInput("subdivide " + quote(kData + "inverted_corner_hex.json") + " --levels 1 --out " +
                     quote(path("x.json")),
                 "cell 0 is inverted at vertex 7: ");
  expectBadInput("info " + quote(kData + "disjoint_cell.json"),
                 "disjoint_cell.json: cell 0 is not one solid: its faces form 2 separate closed "
                 "surfaces");
}

TEST_F(RoundTripCliTest, CubesAtAnyScaleAreAccepted) {
  const std::array<std::array<double, 3>, 7> scales = {{{100, 0.1, 0.1},
                                                        {1e4, 1e-2, 1e-2},
                                                        {1e-2, 1e4, 1e-2},
                                                        {1e-150, 1e-150, 1e-150},
                                                        {1e150, 1e150, 1e150},
                                                        {1e300, 1e300, 1e300},
                                                        {1e300, 1e-150, 1e-150}}};
  for (const auto& s : scales) {
    CellComplex cube = test::hexGrid(2, 1, 1);
    for (Eigen::Index k = 0; k < 3; ++k) cube.positions.col(k) *= s[static_cast<size_t>(k)];
    const std::string file = path("scaled.json");
    saveControlMeshJson(cube, file);
    SCOPED_TRACE(test::readText(file));
    EXPECT_TRUE(expectRoundTrip(file));
    const CliResult levels = run("info " + quote(file) + " --levels 2");
    EXPECT_EQ(levels.exitCode, 0) << levels.err;
    EXPECT_FALSE(levels.signaled);
  }
  // Flat stays refused at any scale.
  for (double s : {1e-150, 1.0, 1e300}) {
    CellComplex flat = test::unitCube();
    flat.positions.col(2).setZero();
    flat.positions *= s;
    const std::string file = path("flat.json");
    saveControlMeshJson(flat, file);
    expectBadInput("info " + quote(file), "flat.json: cell 0 has zero volume: it is flat");
  }
}

}  // namespace
}  // namespace sculpt
