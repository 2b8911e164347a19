// Topology events checked against memory: with a simulation level, an event that leaves a mesh
// whose simulation would not fit is refused, naming the event, before the next one runs.

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "support/edit_fixtures.h"
#include "support/scoped_environment.h"
#include "tools/script_topology.h"
#include "tools/session_script.h"

namespace sculpt {
namespace {

// Three subdivisions of every cell of block3: 216, 1728, then 13824 cells.
SessionScript threeWholeMeshSubdivisions() {
  return parseSessionScript(test::block3SubdividedThreeTimesScript(), "s.json");
}

TEST(TopologyScriptLimits, AnEventWhoseResultCannotBeSimulatedIsRefused) {
  test::ScopedEnvironment limit("SCULPT_MEMORY_LIMIT_MB", "8000");
  SessionScript script = threeWholeMeshSubdivisions();
  try {
    applyTopologyEvents(test::block3(), script, 2);
    ADD_FAILURE() << "no error";
  } catch (const std::invalid_argument& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind("events[2] (topology subdivide): level 2 of the edited mesh (13824 "
                            "cells) needs about ",
                            0),
              0u)
        << message;
    EXPECT_NE(message.find("(884,736 cells); SCULPT_MEMORY_LIMIT_MB allows 8.4 GB"),
              std::string::npos)
        << message;
  }
  EXPECT_EQ(script.events.size(), 3u);  // unchanged on failure

  // Trilinear elements on the edited mesh itself fit; without a level nothing is checked.
  EXPECT_EQ(applyTopologyEvents(test::block3(), script, 0).numCells(), 13824u);
  SessionScript unchecked = threeWholeMeshSubdivisions();
  EXPECT_EQ(applyTopologyEvents(test::block3(), unchecked).numCells(), 13824u);
}

}  // namespace
}  // namespace sculpt
