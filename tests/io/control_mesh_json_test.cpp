// The control-mesh JSON format: round trips, and one clear FileError per kind of malformed input.

#include "io/control_mesh_json.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "mesh/standard_cell.h"
#include "mesh/validation.h"

namespace sculpt {
namespace {

// A hexahedron written as face loops with a typed pyramid on top, tags, and coordinates that
// only survive a round trip when every digit is kept.
const char* const kHouse = R"({
  "format": "sculpt-control-mesh", "version": 1,
  "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0],
               [0, 0, 1], [1, 0, 1], [0, 1, 1], [1, 1, 1], [0.1, 0.33333333333333331, 1.5]],
  "cells": [
    [[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [1, 3, 7, 5], [3, 2, 6, 7], [2, 0, 4, 6]],
    {"type": "pyramid", "vertices": [4, 5, 7, 6, 8]}
  ],
  "creases": [[0, 1], [1, 3]],
  "corners": [0, 3]
})";

std::vector<std::vector<uint32_t>> faceLoops(const CellComplex& mesh, uint32_t c) {
  std::vector<std::vector<uint32_t>> loops;
  for (uint32_t j = 0; j < mesh.numFacesOfCell(c); ++j) {
    const auto loop = mesh.cellFace(c, j);
    loops.emplace_back(loop.begin(), loop.end());
  }
  return loops;
}

void expectSameMesh(const CellComplex& a, const CellComplex& b) {
  ASSERT_EQ(a.numVertices(), b.numVertices());
  for (uint32_t v = 0; v < a.numVertices(); ++v) {
    for (Eigen::Index k = 0; k < 3; ++k) EXPECT_EQ(a.positions(v, k), b.positions(v, k));
  }
  EXPECT_EQ(a.cellFaceBegin, b.cellFaceBegin);
  EXPECT_EQ(a.loopBegin, b.loopBegin);
  EXPECT_EQ(a.loopVertices, b.loopVertices);
  EXPECT_EQ(a.creases, b.creases);
  EXPECT_EQ(a.corners, b.corners);
}

// The FileError message of parsing `text` as "bad.json" (empty when it parses).
std::string parseError(const std::string& text) {
  try {
    parseControlMeshJson(text, "bad.json");
  } catch (const FileError& error) {
    return error.what();
  }
  return {};
}

std::string withCells(const std::string& cells, const std::string& extra = "") {
  return R"({"format": "sculpt-control-mesh", "version": 1,
    "vertices": [[0,0,0],[1,0,0],[0,1,0],[1,1,0],[0,0,1],[1,0,1],[0,1,1],[1,1,1]],
    "cells": )" +
         cells + extra + "}";
}

TEST(ControlMeshJson, ParsesFaceLoopsTypedCellsAndTags) {
  const CellComplex mesh = parseControlMeshJson(kHouse, "house.json");
  ASSERT_EQ(mesh.numVertices(), 9u);
  ASSERT_EQ(mesh.numCells(), 2u);
  EXPECT_EQ(mesh.numFacesOfCell(0), 6u);
  EXPECT_EQ(faceLoops(mesh, 0)[3], (std::vector<uint32_t>{1, 3, 7, 5}));
  const std::vector<uint32_t> pyramid{4, 5, 7, 6, 8};
  EXPECT_EQ(faceLoops(mesh, 1), standardCellFaces(StandardCell::Pyramid, pyramid));
  EXPECT_EQ(mesh.creases, (std::vector<std::array<uint32_t, 2>>{{0, 1}, {1, 3}}));
  EXPECT_EQ(mesh.corners, (std::vector<uint32_t>{0, 3}));
  EXPECT_EQ(mesh.positions(8, 0), 0.1);
  EXPECT_EQ(mesh.positions(8, 1), 1.0 / 3.0);
  EXPECT_TRUE(isValid(validate(mesh)));
}

TEST(ControlMeshJson, RoundTripKeepsEverythingBitForBit) {
  CellComplex mesh = parseControlMeshJson(kHouse, "house.json");
  // Values that need all 17 digits, and extremes.
  mesh.positions(8, 0) = 0.1 + 0.2;
  mesh.positions(8, 1) = -1e-300;
  mesh.positions(8, 2) = 1.7976931348623157e308;
  const std::string text = controlMeshToJson(mesh);
  expectSameMesh(parseControlMeshJson(text, "again.json"), mesh);
  // One vertex and one cell per line.
  EXPECT_NE(text.find("\n    [0, 0, 0],\n"), std::string::npos);
  EXPECT_NE(text.find("\"creases\": [[0, 1], [1, 3]]"), std::string::npos);
  EXPECT_NE(text.find("\"corners\": [0, 3]"), std::string::npos);
}

TEST(ControlMeshJson, OmitsEmptyTagsAndRejectsNonFinitePositions) {
  CellComplex mesh = parseControlMeshJson(withCells(R"([{"type": "hex",
      "vertices": [0, 1, 3, 2, 4, 5, 7, 6]}])"),
                                          "cube.json");
  const std::string text = controlMeshToJson(mesh);
  EXPECT_EQ(text.find("creases"), std::string::npos);
  EXPECT_EQ(text.find("corners"), std::string::npos);
  expectSameMesh(parseControlMeshJson(text, "cube.json"), mesh);
  mesh.positions(2, 1) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(controlMeshToJson(mesh), std::domain_error);
}

TEST(ControlMeshJson, AcceptsIntegralFloatIndices) {
  const CellComplex mesh = parseControlMeshJson(
      withCells(R"([{"type": "hex", "vertices": [0, 1.0, 3, 2, 4, 5, 7, 6e0]}])"), "x.json");
  EXPECT_EQ(mesh.cellFace(0, 0)[1], 2u);
}

struct BadInput {
  const char* name;
  std::string text;
  std::vector<std::string> expected;  // substrings of the message besides "bad.json: "
};

TEST(ControlMeshJson, EveryMalformedInputGivesOneLineNamingFileAndElement) {
  const std::string valid = withCells(R"([{"type": "hex", "vertices": [0,1,3,2,4,5,7,6]}])");
  const std::vector<BadInput> cases = {
      {"truncated", valid.substr(0, valid.size() / 2), {"not valid JSON", "byte"}},
      {"garbage", std::string("\x01\xff\xfe garbage \x80"), {"not valid JSON"}},
      {"empty", "", {"not valid JSON", "empty"}},
      {"whitespace", " \n\t ", {"not valid JSON", "empty"}},
      {"trailing", valid + "]", {"not valid JSON"}},
      {"not an object", "[1, 2, 3]", {"top level must be a JSON object"}},
      {"no format", R"({"version": 1, "vertices": [], "cells": []})", {"\"format\""}},
      {"wrong format",
       R"({"format": "obj", "version": 1, "vertices": [], "cells": []})",
       {"\"format\" must be \"sculpt-control-mesh\"", "\"obj\""}},
      {"newer version",
       R"({"format": "sculpt-control-mesh", "version": 7, "vertices": [], "cells": []})",
       {"version 7 is newer than this program understands (1)"}},
      {"bad version",
       R"({"format": "sculpt-control-mesh", "version": "1", "vertices": [], "cells": []})",
       {"\"version\" must be a positive integer"}},
      {"no vertices",
       R"({"format": "sculpt-control-mesh", "version": 1, "cells": []})",
       {"\"vertices\" is missing"}},
      {"no cells",
       R"({"format": "sculpt-control-mesh", "version": 1, "vertices": []})",
       {"\"cells\" is missing"}},
      {"bad vertex",
       R"({"format": "sculpt-control-mesh", "version": 1, "vertices": [[0,0,0],[1,"a",0]],
           "cells": []})",
       {"vertex 1: coordinate 1 must be a number"}},
      {"short vertex",
       R"({"format": "sculpt-control-mesh", "version": 1, "vertices": [[0,0]], "cells": []})",
       {"vertex 0: must have 3 coordinates, got 2"}},
      {"non-integer index",
       withCells("[[[0, 2, 3, 1], [4, 5, 2.5, 6]]]"),
       {"cell 0, face 1: vertex index 2.5 is not a non-negative integer"}},
      {"negative index",
       withCells("[[[0, 2, 3, 1]], [[0, -1, 3]]]"),
       {"cell 1, face 0: vertex index -1 is negative"}},
      {"string index", withCells(R"([[[0, 2, "3"]]])"), {"cell 0, face 0: vertex index", "\"3\""}},
      {"huge index", withCells("[[[0, 2, 99999999999]]]"), {"cell 0, face 0:", "too large"}},
      {"short face", withCells("[[[0, 2]]]"), {"cell 0, face 0: a face needs at least 3"}},
      {"no faces", withCells("[[]]"), {"cell 0: has no faces"}},
      {"cell kind", withCells("[7]"), {"cell 0: must be a list of faces"}},
      {"wrong vertex count",
       withCells(R"([{"type": "hex", "vertices": [0,1,3,2,4,5,7]}])"),
       {"cell 0: a hex needs 8 vertices, got 7"}},
      {"unknown type",
       withCells(R"([{"type": "octahedron", "vertices": [0,1,2,3,4,5]}])"),
       {"cell 0: unknown cell type \"octahedron\""}},
      {"typed negative",
       withCells(R"([{"type": "tet", "vertices": [0,1,-2,3]}])"),
       {"cell 0: vertex index -2 is negative"}},
      {"bad crease",
       withCells("[]", R"(, "creases": [[0, 1], [2]])"),
       {"crease 1: must be a pair"}},
      {"bad corner", withCells("[]", R"(, "corners": [0, 1.5])"), {"corner 1: vertex index 1.5"}},
      {"deep nesting",
       std::string(10000, '[') + std::string(10000, ']'),
       {"not valid JSON", "nested deeper"}},
      {"newline in type",
       withCells(R"([{"type": "a\nb", "vertices": []}])"),
       {"cell 0: unknown cell type \"a?b\""}},
  };
  for (const BadInput& bad : cases) {
    SCOPED_TRACE(bad.name);
    const std::string message = parseError(bad.text);
    ASSERT_FALSE(message.empty()) << "parsed without error";
    EXPECT_EQ(message.rfind("bad.json: ", 0), 0u) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    for (const std::string& part : bad.expected) {
      EXPECT_NE(message.find(part), std::string::npos) << "'" << part << "' not in: " << message;
    }
  }
}

TEST(ControlMeshJson, RejectsGiganticCellsAndFaces) {
  std::string face = "[0";
  for (int i = 1; i <= 10000; ++i) face += ",1";
  face += "]";
  EXPECT_NE(parseError(withCells("[[" + face + "]]")).find("cell 0, face 0: has 10001 vertices"),
            std::string::npos);
  std::string cell = "[[0,1,2]";
  for (int i = 1; i <= 10000; ++i) cell += ",[0,1,2]";
  cell += "]";
  EXPECT_NE(parseError(withCells("[" + cell + "]")).find("cell 0: has 10001 faces"),
            std::string::npos);
}

TEST(ControlMeshJson, RandomMutationsNeverEscapeAsAnythingButFileError) {
  const std::string valid = kHouse;
  std::mt19937 rng(20240611);
  const std::string alphabet("[]{},:\"-.eE0123456789 \0\xff", 24);
  for (int round = 0; round < 3000; ++round) {
    std::string text = valid;
    const int edits = 1 + static_cast<int>(rng() % 4);
    for (int e = 0; e < edits; ++e) {
      const size_t at = rng() % text.size();
      switch (rng() % 3) {
        case 0:
          text[at] = alphabet[rng() % alphabet.size()];
          break;
        case 1:
          text.erase(at, 1 + rng() % 8);
          break;
        default:
          text.insert(at, 1, alphabet[rng() % alphabet.size()]);
          break;
      }
    }
    try {
      parseControlMeshJson(text, "fuzz.json");
    } catch (const FileError& error) {
      const std::string message = error.what();
      ASSERT_EQ(message.rfind("fuzz.json: ", 0), 0u) << message;
      ASSERT_EQ(message.find('\n'), std::string::npos) << message;
    }
  }
}

TEST(ControlMeshJson, LoadAndSaveThroughFiles) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("sculpt_json_test_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const CellComplex mesh = parseControlMeshJson(kHouse, "house.json");
  saveControlMeshJson(mesh, dir / "house.json");
  expectSameMesh(loadControlMeshJson(dir / "house.json"), mesh);
  // Only the destination is left behind: no temporary files.
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir),
                          std::filesystem::directory_iterator()),
            1);
  try {
    loadControlMeshJson(dir / "missing.json");
    ADD_FAILURE() << "no error for a missing file";
  } catch (const FileError& error) {
    EXPECT_NE(std::string(error.what()).find("missing.json: cannot open"), std::string::npos);
  }
  EXPECT_THROW(saveControlMeshJson(mesh, dir / "no_such_dir" / "x.json"), FileError);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace sculpt
