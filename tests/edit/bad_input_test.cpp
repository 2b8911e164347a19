// Bad input to the topology tools: each case throws std::invalid_argument with one sentence
// that names the problem, and nothing is changed (the project keeps its exact save).

#include <gtest/gtest.h>

#include <functional>
#include <stdexcept>

#include "edit/project_edit.h"
#include "edit/topology_operation.h"
#include "project/project_file.h"
#include "support/edit_fixtures.h"

namespace sculpt {
namespace {

struct BadCase {
  const char* name;
  std::function<CellComplex()> mesh;
  std::function<void(const CellComplex&)> call;
  const char* expected;  ///< the whole message
};

// One sentence: a message that ends with its only full stop... or at least ends with one and
// has no line break.
void expectSentence(const std::string& message) {
  ASSERT_FALSE(message.empty());
  EXPECT_EQ(message.back(), '.') << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

TEST(TopologyBadInput, EachToolRejectsWithASentenceAndChangesNothing) {
  const auto block = [] { return test::block3(); };
  const auto gap = [] { return test::twoParts(test::block3(), test::unitCube(), {3.5, 1, 1}); };
  const auto houses = [] {
    return test::twoParts(test::houseSmall(), test::houseSmall(), {2, 0, 0});
  };
  using Cells = std::vector<uint32_t>;
  using Faces = std::vector<FaceRef>;
  const BadCase cases[] = {
      {"delete none", block, [](const CellComplex& m) { deleteCells(m, Cells{}); },
       "no cells are selected."},
      {"delete out of range", block,
       [](const CellComplex& m) {
         deleteCells(m, Cells{3, 27});
       },
       "cell 27 is out of range (the mesh has 27 cells)."},
      {"delete all", [] { return test::hexGrid(2, 1, 1); },
       [](const CellComplex& m) {
         deleteCells(m, Cells{1, 0, 1});
       },
       "cannot delete every cell (at least one must remain)."},
      // Two cells left touching along an edge only: a non-manifold boundary.
      {"delete to non-manifold", [] { return test::hexGrid(2, 2, 1); },
       [](const CellComplex& m) {
         deleteCells(m, Cells{1, 2});
       },
       "the edited mesh would be invalid: boundary edge (3, 10) has 4 boundary faces instead of 2 "
       "(non-manifold boundary)."},
      {"extrude interior face", block,
       [](const CellComplex& m) {
         extrudeFaces(m, Faces{{22, 1}, {13, 1}}, 0.5);
       },
       "face 1 of cell 13 is not on the boundary."},
      {"extrude face out of range", block,
       [](const CellComplex& m) {
         extrudeFaces(m, Faces{{0, 6}}, 0.5);
       },
       "face 6 of cell 0 is out of range (the cell has 6 faces)."},
      {"extrude cell out of range", block,
       [](const CellComplex& m) {
         extrudeFaces(m, Faces{{40, 0}}, 0.5);
       },
       "cell 40 is out of range (the mesh has 27 cells)."},
      {"extrude nothing", block, [](const CellComplex& m) { extrudeFaces(m, Faces{}, 0.5); },
       "no faces are selected."},
      {"extrude by zero", block,
       [](const CellComplex& m) {
         extrudeFaces(m, Faces{{22, 1}}, 0.0);
       },
       "the extrusion distance must be a finite number > 0 (got 0)."},
      {"bridge different sizes", houses,
       [](const CellComplex& m) {
         bridgeFaces(m, {0, 3}, {3, 4});
       },
       "face 3 of cell 0 has 4 vertices and face 4 of cell 3 has 3; they must have as many to "
       "bridge them."},
      {"bridge a face with itself", block,
       [](const CellComplex& m) {
         bridgeFaces(m, {22, 1}, {22, 1});
       },
       "cannot bridge a face with itself."},
      {"bridge touching faces", block,
       [](const CellComplex& m) {
         bridgeFaces(m, {18, 1}, {19, 1});
       },
       "face 1 of cell 18 and face 1 of cell 19 share vertex 49; only faces that share no vertex "
       "can be bridged."},
      {"weld apart", gap,
       [](const CellComplex& m) {
         weldFaces(m, {14, 3}, {27, 5}, 1e-3);
       },
       "face 3 of cell 14 and face 5 of cell 27 do not coincide: vertex 23 is 0.5 m from vertex "
       "64 (tolerance 0.001 m)."},
      {"weld negative tolerance", gap,
       [](const CellComplex& m) {
         weldFaces(m, {14, 3}, {27, 5}, -1);
       },
       "the weld tolerance must be a finite number >= 0 (got -1)."},
      {"subdivide out of range", block, [](const CellComplex& m) { subdivideCells(m, Cells{27}); },
       "cell 27 is out of range (the mesh has 27 cells)."},
      {"crease interior edge", block,
       [](const CellComplex& m) {
         const std::array<uint32_t, 2> e[] = {{21, 22}};
         setCreases(m, e, true);
       },
       "edge (21, 22) is an interior edge; only boundary edges can be creases."},
      {"crease non-edge", block,
       [](const CellComplex& m) {
         const std::array<uint32_t, 2> e[] = {{0, 63}};
         setCreases(m, e, true);
       },
       "edge (0, 63) is not an edge of the mesh."},
      {"corner interior vertex", block,
       [](const CellComplex& m) { setCorners(m, Cells{21}, true); },
       "vertex 21 is an interior vertex; only boundary vertices can be corners."},
      {"corner out of range", block, [](const CellComplex& m) { setCorners(m, Cells{64}, false); },
       "vertex 64 is out of range (the mesh has 64 vertices)."},
      {"invalid input",
       [] {
         return loadControlMeshJson(std::filesystem::path(SCULPT_SOURCE_DIR) / "tests" / "data" /
                                    "inverted_hex.json");
       },
       [](const CellComplex& m) { subdivideCells(m, Cells{0}); },
       "the mesh is invalid before the edit: "},
      {"bridge with one face", block,
       [](const CellComplex& m) {
         TopologyOperation op;
         op.op = TopologyOp::Bridge;
         op.faces = {{22, 1}};
         applyTopologyOperation(m, op);
       },
       "bridge needs exactly 2 faces (got 1)."},
  };
  for (const BadCase& c : cases) {
    SCOPED_TRACE(c.name);
    const CellComplex mesh = c.mesh();
    const CellComplex copy = mesh;
    try {
      c.call(mesh);
      ADD_FAILURE() << "no exception";
    } catch (const std::invalid_argument& e) {
      const std::string message = e.what();
      expectSentence(message);
      if (std::string(c.expected).back() == ' ') {
        EXPECT_EQ(message.rfind(c.expected, 0), 0u) << message;
      } else {
        EXPECT_EQ(message, c.expected);
      }
    }
    EXPECT_TRUE(sameControlMesh(mesh, copy));
  }
}

TEST(TopologyBadInput, ApplyingAMismatchedEditLeavesTheProjectUnchanged) {
  Project project;
  project.controlMesh = test::block3();
  const auto model = test::buildModel(project.controlMesh, 1, false);
  project.materials = captureMaterials(model->mesh(), 1);
  project.pins = {3, 4};
  const std::string before = serializeProject(project);

  // An edit made for another mesh: its vertex map has the wrong size.
  TopologyEdit foreign = extrudeFaces(test::houseSmall(), std::vector<FaceRef>{{0, 2}}, 0.2);
  try {
    applyTopologyEdit(project, foreign);
    ADD_FAILURE() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "the edit maps 9 vertices but the project's mesh has 64.");
  }
  EXPECT_EQ(serializeProject(project), before);

  // A map that fits but a mesh that is not valid (the first cell turned inside out).
  TopologyEdit inverted = subdivideCells(project.controlMesh, std::vector<uint32_t>{13});
  inverted.mesh.positions.col(2) *= -1.0;
  try {
    applyTopologyEdit(project, inverted);
    ADD_FAILURE() << "no exception";
  } catch (const std::invalid_argument& e) {
    expectSentence(e.what());
    EXPECT_EQ(std::string(e.what()).rfind("the edited mesh is invalid: ", 0), 0u) << e.what();
  }
  EXPECT_EQ(serializeProject(project), before);
}

}  // namespace
}  // namespace sculpt
