// Undo of topology edits: for every operation, recording the edit and undoing it gives back the
// project whose save is byte for byte the save before the edit; redo gives the edited save.

#include <gtest/gtest.h>

#include <functional>

#include "edit/project_edit.h"
#include "project/project_file.h"
#include "project/undo_history.h"
#include "support/edit_fixtures.h"

namespace sculpt {
namespace {

// A project on `mesh` with materials painted at K = 1 and some pins.
Project projectOn(const CellComplex& mesh) {
  Project project;
  project.controlMesh = mesh;
  const auto model = test::buildModel(mesh, 1, false);
  Material soft;
  soft.youngs = 3.0e4;
  EXPECT_GT(model->paintMaterial(Eigen::Vector3d(0.5, 0.5, 0.5), 0.8, soft), 0);
  project.materials = captureMaterials(model->mesh(), 1);
  project.pins = {0, 1, 5, mesh.numVertices() - 1};
  return project;
}

struct UndoCase {
  const char* name;
  std::function<CellComplex()> mesh;
  std::function<TopologyEdit(const CellComplex&)> edit;
};

TEST(TopologyUndo, UndoRestoresTheExactSaveAndRedoTheEditedOne) {
  const auto block = [] { return test::block3(); };
  const std::array<uint32_t, 2> crease[] = {{48, 49}};
  const UndoCase cases[] = {
      {"delete", block,
       [](const CellComplex& m) { return deleteCells(m, std::vector<uint32_t>{26}); }},
      {"extrude", block,
       [](const CellComplex& m) {
         return extrudeFaces(m, std::vector<FaceRef>{{22, 1}, {21, 1}}, 0.5);
       }},
      {"bridge",
       [] {
         return test::twoParts(test::block3(), test::unitCube(), {4, 1, 1});
       },
       [](const CellComplex& m) {
         return bridgeFaces(m, {14, 3}, {27, 5});
       }},
      {"weld",
       [] {
         return test::twoParts(test::block3(), test::unitCube(), {3, 1, 1});
       },
       [](const CellComplex& m) {
         return weldFaces(m, {14, 3}, {27, 5}, 1e-9);
       }},
      {"subdivide", block,
       [](const CellComplex& m) { return subdivideCells(m, std::vector<uint32_t>{13}); }},
      {"crease", block, [&](const CellComplex& m) { return setCreases(m, crease, true); }},
      {"corner", block,
       [](const CellComplex& m) {
         return setCorners(m, std::vector<uint32_t>{0, 3}, true);
       }},
  };
  for (const UndoCase& c : cases) {
    SCOPED_TRACE(c.name);
    Project project = projectOn(c.mesh());
    const std::string before = serializeProject(project);
    const Project original = project;
    const TopologyEdit edit = c.edit(project.controlMesh);
    applyTopologyEdit(project, edit);
    const std::string after = serializeProject(project);
    ASSERT_NE(before, after);

    UndoHistory history;
    ASSERT_TRUE(history.record(edit.label, original, project));
    EXPECT_EQ(history.undoLabel(), edit.label);
    ASSERT_TRUE(history.undo(project));
    EXPECT_EQ(serializeProject(project), before);
    ASSERT_TRUE(history.redo(project));
    EXPECT_EQ(serializeProject(project), after);
  }
}

}  // namespace
}  // namespace sculpt
