// The "topology" event of session scripts: parsing (good events of every op and malformed
// ones, each a one-sentence FileError), applying the events to a control mesh in file order
// (tools/script_topology.h), and ScriptPlayer refusing topology events.

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "io/file_error.h"
#include "support/edit_fixtures.h"
#include "tools/script_topology.h"
#include "tools/session_script.h"

namespace sculpt {
namespace {

std::string wrap(const std::string& events) {
  return R"({"format": "sculpt-session", "version": 1, "events": [)" + events + "]}";
}

TEST(TopologyScript, ParsesEveryOp) {
  const SessionScript script =
      parseSessionScript(wrap(R"({"t": 0, "type": "topology", "op": "delete", "cells": [26, 3]},
    {"t": 0, "type": "topology", "op": "extrude", "faces": [[22, 1], [21, 1]], "distance": 0.5},
    {"t": 0, "type": "topology", "op": "bridge", "faces": [[14, 3], [27, 5]]},
    {"t": 0, "type": "topology", "op": "weld", "faces": [[14, 3], [27, 5]], "tolerance": 0.01},
    {"t": 0, "type": "topology", "op": "subdivide", "cells": [13]},
    {"t": 0, "type": "topology", "op": "crease", "edges": [[48, 49]], "untag": true},
    {"t": 0, "type": "topology", "op": "corner", "vertices": [0, 3]})"),
                         "s.json");
  ASSERT_EQ(script.events.size(), 7u);
  std::vector<TopologyEvent> ops;
  for (const ScriptEvent& e : script.events) {
    EXPECT_STREQ(e.typeName(), "topology");
    EXPECT_EQ(e.endTime(), 0.0);
    ops.push_back(std::get<TopologyEvent>(e.action));
  }
  EXPECT_EQ(ops[0].op, TopologyOp::Delete);
  EXPECT_EQ(ops[0].cells, (std::vector<uint32_t>{26, 3}));
  EXPECT_EQ(ops[1].op, TopologyOp::Extrude);
  EXPECT_EQ(ops[1].faces, (std::vector<FaceRef>{{22, 1}, {21, 1}}));
  EXPECT_EQ(ops[1].distanceM, 0.5);
  EXPECT_EQ(ops[2].op, TopologyOp::Bridge);
  EXPECT_EQ(ops[3].op, TopologyOp::Weld);
  EXPECT_EQ(ops[3].toleranceM, 0.01);
  EXPECT_EQ(ops[4].op, TopologyOp::Subdivide);
  EXPECT_EQ(ops[4].cells, (std::vector<uint32_t>{13}));
  EXPECT_EQ(ops[5].op, TopologyOp::Crease);
  EXPECT_EQ(ops[5].edges, (std::vector<std::array<uint32_t, 2>>{{48, 49}}));
  EXPECT_TRUE(ops[5].untag);
  EXPECT_EQ(ops[6].op, TopologyOp::Corner);
  EXPECT_EQ(ops[6].vertices, (std::vector<uint32_t>{0, 3}));
  EXPECT_FALSE(ops[6].untag);
}

TEST(TopologyScript, MalformedEventsAreOneSentence) {
  const std::pair<std::string, std::string> cases[] = {
      {R"({"t": 0.5, "type": "topology", "op": "subdivide", "cells": [1]})",
       "s.json: events[0] (topology): 't' must be 0 (topology edits are applied before the "
       "simulation starts)."},
      {R"({"t": 0, "type": "topology", "cells": [1]})",
       "s.json: events[0] (topology): 'op' is missing (one of delete, extrude, bridge, weld, "
       "subdivide, crease, corner)."},
      {R"({"t": 0, "type": "topology", "op": "explode"})",
       "s.json: events[0] (topology): 'op' must be one of delete, extrude, bridge, weld, "
       "subdivide, crease, corner (got \"explode\")."},
      {R"({"t": 0, "type": "topology", "op": "delete"})",
       "s.json: events[0] (topology): 'cells' is missing (a non-empty array of cell indexes)."},
      {R"({"t": 0, "type": "topology", "op": "delete", "cells": []})",
       "s.json: events[0] (topology): 'cells' must be a non-empty array of cell indexes."},
      {R"({"t": 0, "type": "topology", "op": "delete", "cells": [1, -2]})",
       "s.json: events[0] (topology): 'cells[1]' must be a cell index: an integer >= 0."},
      {R"({"t": 0, "type": "topology", "op": "extrude", "faces": [[1, 2, 3]], "distance": 1})",
       "s.json: events[0] (topology): 'faces[0]' must be [cell, face]."},
      {R"({"t": 0, "type": "topology", "op": "extrude", "faces": [[1, 0.5]], "distance": 1})",
       "s.json: events[0] (topology): 'faces[0]' must be [cell, face] with integers >= 0."},
      {R"({"t": 0, "type": "topology", "op": "extrude", "faces": [[1, 2]], "distance": 0})",
       "s.json: events[0] (topology): 'distance' must be a finite number > 0 (m) (got 0)."},
      {R"({"t": 0, "type": "topology", "op": "bridge", "faces": [[1, 2]]})",
       "s.json: events[0] (topology): 'faces' must hold exactly 2 faces [cell, face]."},
      {R"({"t": 0, "type": "topology", "op": "bridge", "faces": [[1, 2], [3, 4]], "tolerance": 1})",
       "s.json: events[0] (topology): unknown field 'tolerance'."},
      {R"({"t": 0, "type": "topology", "op": "weld", "faces": [[1, 2], [3, 4]], "tolerance": -1})",
       "s.json: events[0] (topology): 'tolerance' must be a finite number >= 0 (m) (got -1)."},
      {R"({"t": 0, "type": "topology", "op": "crease", "edges": [[1, 2]], "untag": "yes"})",
       "s.json: events[0] (topology): 'untag' must be true or false."},
      {R"({"t": 0, "type": "topology", "op": "corner", "vertices": [[1]]})",
       "s.json: events[0] (topology): 'vertices[0]' must be a vertex index: an integer >= 0."},
  };
  for (const auto& [events, expected] : cases) {
    SCOPED_TRACE(events);
    try {
      parseSessionScript(wrap(events), "s.json");
      ADD_FAILURE() << "no error";
    } catch (const FileError& e) {
      EXPECT_EQ(std::string(e.what()), expected);
    }
  }
}

TEST(TopologyScript, EventsApplyInFileOrderAndLeaveTheOthers) {
  SessionScript script =
      parseSessionScript(wrap(R"({"t": 0, "type": "pin", "box": [[-1, -1, -1], [4, 4, 0.01]]},
    {"t": 0, "type": "topology", "op": "extrude", "faces": [[26, 1], [25, 1]], "distance": 0.5},
    {"t": 0, "type": "topology", "op": "subdivide", "cells": [27]},
    {"t": 0, "type": "topology", "op": "crease", "edges": [[0, 1]]})"),
                         "s.json");
  const CellComplex edited = applyTopologyEvents(test::block3(), script);
  // Extrude: 2 cells, 6 vertices; subdividing the first new cell: 7 cells, 19 vertices.
  EXPECT_EQ(edited.numCells(), 27u + 2u + 7u);
  EXPECT_EQ(edited.numVertices(), 64u + 6u + 19u);
  EXPECT_EQ(edited.creases, (std::vector<std::array<uint32_t, 2>>{{0, 1}}));
  EXPECT_TRUE(test::validMesh(edited));
  ASSERT_EQ(script.events.size(), 1u);
  EXPECT_STREQ(script.events[0].typeName(), "pin");
  EXPECT_EQ(script.events[0].index, 0u);

  SessionScript bad =
      parseSessionScript(wrap(R"({"t": 0, "type": "topology", "op": "subdivide", "cells": [13]},
    {"t": 0, "type": "topology", "op": "extrude", "faces": [[13, 1]], "distance": 0.5})"),
                         "s.json");
  try {
    applyTopologyEvents(test::block3(), bad);
    ADD_FAILURE() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(),
                 "events[1] (topology extrude): face 1 of cell 13 is not on the boundary.");
  }
  EXPECT_EQ(bad.events.size(), 2u);  // unchanged on failure
}

TEST(TopologyScript, PlayerRefusesTopologyEvents) {
  const auto model = test::buildModel(test::unitCube(), 1, true);
  Simulator simulator(*model);
  SessionScript script =
      parseSessionScript(wrap(R"({"t": 0, "type": "pin", "box": [[-1, -1, -1], [2, 2, 0.01]]},
    {"t": 0, "type": "topology", "op": "subdivide", "cells": [0]})"),
                         "s.json");
  try {
    ScriptPlayer player(simulator, script);
    ADD_FAILURE() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(),
                 "events[1] (topology): a topology edit cannot be replayed on a running "
                 "simulation; apply the script's topology events to the control mesh before "
                 "building the model.");
  }
  // Once applied, the rest plays, and the log names events by their place in the file.
  const CellComplex edited = applyTopologyEvents(test::unitCube(), script);
  EXPECT_EQ(edited.numCells(), 8u);
  ScriptPlayer player(simulator, script);
  player.step();
  const std::vector<std::string> log = player.takeLog();
  ASSERT_EQ(log.size(), 1u);
  EXPECT_EQ(log[0].rfind("t=0 s: events[0] pin", 0), 0u) << log[0];
}

}  // namespace
}  // namespace sculpt
