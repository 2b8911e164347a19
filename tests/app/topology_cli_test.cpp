// simulate --script with topology events: they edit the control mesh before the model is built
// (docs/file-formats.md "Topology events"), so the run simulates the edited solid; an event
// that cannot be applied is bad input naming the script and the event.

#include <gtest/gtest.h>

#include <string>

#include "support/cli_fixture.h"

namespace sculpt::test {
namespace {

class TopologyCliTest : public CliFixture {
 protected:
  TopologyCliTest() : CliFixture("sculpt_topology_cli_test_") {}
};

TEST_F(TopologyCliTest, ScriptTopologyEventsEditTheSimulatedMesh) {
  const std::string block = quote(std::string(SCULPT_SOURCE_DIR) + "/assets/block3.json");
  writeText(path("edit.json"), R"({"format": "sculpt-session", "version": 1, "events": [
    {"t": 0, "type": "pin", "box": [[-1, -1, -1], [4, 0.01, 4]]},
    {"t": 0, "type": "topology", "op": "extrude", "faces": [[26, 1], [25, 1]], "distance": 0.5},
    {"t": 0, "type": "topology", "op": "subdivide", "cells": [27]}]})");
  const CliResult result =
      run("simulate " + block + " --levels 1 --dt 0.02 --steps 2 --gravity " + "--script " +
          quote(path("edit.json")) + " --out " + quote(path("edited.vtk")));
  ASSERT_EQ(result.exitCode, 0) << result.err;
  // Extruding two top faces adds 2 cells and 6 points; subdividing one of them 7 and 19.
  EXPECT_NE(result.err.find("simulate: script: 2 topology events applied: 36 cells, 89 control "
                            "points"),
            std::string::npos)
      << result.err;
  EXPECT_NE(result.err.find("events[0] pin"), std::string::npos) << result.err;
  EXPECT_NE(readText(path("edited.vtk")).find("POINTS 89 "), std::string::npos);

  writeText(path("bad.json"), R"({"format": "sculpt-session", "version": 1, "events": [
    {"t": 0, "type": "topology", "op": "extrude", "faces": [[13, 1]], "distance": 0.5}]})");
  expectBadInput("simulate " + block + " --levels 1 --dt 0.02 --steps 2 --script " +
                     quote(path("bad.json")) + " --out " + quote(path("x.vtk")),
                 "bad.json: events[0] (topology extrude): face 1 of cell 13 is not on the "
                 "boundary.");
}

}  // namespace
}  // namespace sculpt::test
