// sculpt-cli refuses, before it allocates, work that cannot fit in memory: too many levels, a
// cell so wide that its stencils grow quadratically, topology events that multiply the cells,
// and scripts longer than the step limit. Each refusal is one error line with exit code 2 that
// says what the work would need. SCULPT_MEMORY_LIMIT_MB stands in for the machine's memory.

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <string>

#include "io/control_mesh_json.h"
#include "support/cli_fixture.h"
#include "support/mesh_builders.h"
#include "support/scoped_environment.h"

namespace sculpt::test {
namespace {

const std::string kAssets = std::string(SCULPT_SOURCE_DIR) + "/assets/";

class MemoryLimitsCliTest : public CliFixture {
 protected:
  MemoryLimitsCliTest() : CliFixture("sculpt_memory_limits_cli_test_") {}

  // A prism over an n-gon, written in the test's folder.
  std::string prism(uint32_t n) const {
    const std::string file = path("prism" + std::to_string(n) + ".json");
    saveControlMeshJson(ngonPrism(n), file);
    return file;
  }
};

TEST_F(MemoryLimitsCliTest, WideCellIsRefusedNamingTheCell) {
  // Measured: 0.4 GB for `subdivide --levels 2`, 1 GB for `info --levels 2`.
  const std::string file = prism(600);
  ScopedEnvironment limit("SCULPT_MEMORY_LIMIT_MB", "200");
  for (const std::string& command :
       {"info " + quote(file) + " --levels 2",
        "subdivide " + quote(file) + " --levels 3 --out " + quote(path("x.vtk")),
        "bench subdivide " + quote(file) + " --levels 2"}) {
    expectBadInput(command, "level ");
    const std::string error = run(command).errLines().at(0);
    EXPECT_NE(error.find(" of " + file + " needs about "), std::string::npos) << error;
    EXPECT_NE(error.find("cell 0 (602 faces, 1200 vertices) alone takes about "), std::string::npos)
        << error;
    EXPECT_NE(error.find("SCULPT_MEMORY_LIMIT_MB allows 210 MB"), std::string::npos) << error;
  }
  EXPECT_FALSE(std::filesystem::exists(path("x.vtk")));
}

TEST_F(MemoryLimitsCliTest, OutOfMemoryOnAWorkerThreadIsAnErrorLine) {
  // With the estimate out of the way and the address space capped, the stencils' composition
  // runs out of memory on the workers: one error line, not std::terminate.
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
  // The sanitizers map terabytes of shadow memory at start: under `ulimit -v` the program
  // aborts before main (AddressSanitizer: "ReserveShadowMemoryRange failed ... Perhaps you're
  // using ulimit -v"; ThreadSanitizer: "CHECK failed: sanitizer_allocator_primary64.h").
  GTEST_SKIP() << "an address-space cap and a sanitizer cannot run together";
#endif
  const std::string file = prism(600);
  const std::string command =
      "ulimit -v 400000; SCULPT_MEMORY_LIMIT_MB=1000000 SCULPT_THREADS=4 "
      "exec " +
      quote(kCli) + " subdivide " + quote(file) + " --levels 3 --out " + quote(path("x.vtk")) +
      " 2>" + quote(path("err.txt"));
  const int status = std::system(command.c_str());
  ASSERT_TRUE(WIFEXITED(status)) << "signal " << WTERMSIG(status);
  EXPECT_EQ(WEXITSTATUS(status), 2);
  const std::string err = readText(path("err.txt"));
  EXPECT_NE(err.find("error: " + file + ": out of memory"), std::string::npos) << err;
}

TEST_F(MemoryLimitsCliTest, LevelsBeyondTheMemoryAreRefused) {
  const std::string block3 = kAssets + "block3.json", block10 = kAssets + "block10.json";
  const std::string out = " --out " + quote(path("x.vtk"));
  ScopedEnvironment limit("SCULPT_MEMORY_LIMIT_MB", "1000");
  const std::string allows = "; SCULPT_MEMORY_LIMIT_MB allows 1.0 GB; use fewer levels";
  expectBadInput("simulate " + quote(block3) + " --levels 4 --dt 0.01 --steps 1" + out,
                 "level 4 of " + block3 + " needs about ");
  expectBadInput("simulate " + quote(block3) + " --levels 4 --dt 0.01 --steps 1" + out, allows);
  expectBadInput("static " + quote(block3) + " --levels 4 --fix -1,-1,-1,4,0.01,4" + out,
                 "(110,592 cells)" + allows);
  expectBadInput("info " + quote(block10) + " --levels 4",
                 "level 4 of " + block10 + " needs about ");
  expectBadInput("subdivide " + quote(block10) + " --levels 4" + out, "(4,096,000 cells)");
  expectBadInput("bench subdivide " + quote(block10) + " --levels 4", "(4,096,000 cells)");
  expectBadInput("bench fem " + quote(block10) + " --levels 3", "(512,000 cells)");
  EXPECT_FALSE(std::filesystem::exists(path("x.vtk")));

  // What fits still runs: the refinement of level 2 (0.15 GB) but not its elements (0.9 GB).
  ScopedEnvironment smaller("SCULPT_MEMORY_LIMIT_MB", "500");
  const CliResult info = run("info " + quote(block10) + " --levels 2");
  EXPECT_EQ(info.exitCode, 0) << info.err;
  EXPECT_NE(info.out.find("  cells: 64000\n"), std::string::npos) << info.out;
  EXPECT_NE(info.out.find("  fem: not built (level 2 of " + block10 + " needs about "),
            std::string::npos)
      << info.out;
  EXPECT_EQ(run("simulate " + quote(block3) + " --levels 2 --dt 0.01 --steps 1" + out).exitCode, 0);
}

TEST_F(MemoryLimitsCliTest, TopologyEventsThatMultiplyTheCellsAreRefused) {
  // Three whole-mesh subdivisions of block3's 27 cells: 216, 1728, then 13824 cells, whose
  // level 2 (884,736 cells) would take tens of GB.
  const std::string script = path("subdivide3.json");
  writeText(script, test::block3SubdividedThreeTimesScript());
  ScopedEnvironment limit("SCULPT_MEMORY_LIMIT_MB", "8000");
  expectBadInput("simulate " + quote(kAssets + "block3.json") +
                     " --levels 2 --dt 0.01 --steps 1 --script " + quote(script) + " --out " +
                     quote(path("x.vtk")),
                 script +
                     ": events[2] (topology subdivide): level 2 of the edited mesh (13824 "
                     "cells) needs about ");
}

TEST_F(MemoryLimitsCliTest, ScriptLongerThanTheStepLimitIsRefused) {
  const std::string script = path("late.json");
  writeText(script, R"({"format": "sculpt-session", "version": 1, "events": [)"
                    R"({"t": 1e9, "type": "pin", "box": [[-1, -1, -1], [4, 0.01, 4]]}]})");
  const std::string simulate = "simulate " + quote(kAssets + "block3.json") +
                               " --levels 1 --dt 0.01 --script " + quote(script) + " --out " +
                               quote(path("x.vtk"));
  expectBadInput(simulate, script +
                               ": events[0] (pin) ends at t=1e+09 s, which takes 1e+11 "
                               "steps of 0.01 s (at most 10000000)");
  // A --steps that stops before the script's end says so.
  const CliResult part = run(simulate + " --steps 3");
  EXPECT_EQ(part.exitCode, 0) << part.err;
  EXPECT_NE(part.err.find("simulate: note: --steps 3 ends at t=0.03 s, before " + script +
                          "'s events[0] (pin) ends at t=1e+09 s\n"),
            std::string::npos)
      << part.err;
}

}  // namespace
}  // namespace sculpt::test
