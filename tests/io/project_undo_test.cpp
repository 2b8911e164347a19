// Undo history: undoing any kind of edit restores the exact previous project (byte-identical
// save), redo re-applies it identically, and the bounds drop the oldest entries.

#include <gtest/gtest.h>

#include <string>

#include "project/project_file.h"
#include "project/undo_history.h"

namespace sculpt::test {
Project block3Project();  // project_file_test.cpp
}  // namespace sculpt::test

namespace sculpt {
namespace {

// Edits of every kind; each returns the edited copy of `p`.
Project paintSamples(Project p) {
  for (size_t i = 0; i < p.materials.size(); i += 7) p.materials.materials[i].youngs = 3.0e6;
  return p;
}
Project movePoints(Project p) {
  p.controlMesh.positions.row(5) += Eigen::RowVector3d(0.1, -0.2, 0.05);
  p.controlMesh.positions(40, 2) = -0.0;
  return p;
}
Project tagCreases(Project p) {
  p.controlMesh.creases.push_back({4, 5});
  p.controlMesh.corners.clear();
  return p;
}
Project pinAndUnpin(Project p) {
  p.pins = {1, 2, 3, 17, 30, 31};  // 0 removed; 30 and 31 added
  return p;
}
// A topology edit: delete the last cell (its unused vertices stay) and resample the materials
// onto fewer points, as a real edit does.
Project deleteLastCell(Project p) {
  CellComplex& m = p.controlMesh;
  const uint32_t loops = m.cellFaceBegin[m.numCells() - 1];
  m.cellFaceBegin.pop_back();
  m.loopBegin.resize(loops + 1);
  m.loopVertices.resize(m.loopBegin.back());
  MaterialSamples resampled;
  resampled.level = p.materials.level;
  resampled.restPositions.assign(p.materials.restPositions.begin(),
                                 p.materials.restPositions.end() - 64);
  resampled.materials = resampleMaterials(p.materials, resampled.restPositions);
  p.materials = resampled;
  return p;
}
Project replaceSurface(Project p) {
  p.surface = {"other.obj", contentHash("x"), false, ""};
  return p;
}

struct Case {
  const char* label;
  Project (*edit)(Project);
};
const Case kCases[] = {
    {"Paint Young's modulus", paintSamples},
    {"Move control points", movePoints},
    {"Tag creases", tagCreases},
    {"Pin", pinAndUnpin},
    {"Delete cell", deleteLastCell},
    {"Replace surface", replaceSurface},
};

TEST(UndoHistory, UndoOfEveryKindRestoresTheExactSave) {
  for (const Case& c : kCases) {
    SCOPED_TRACE(c.label);
    Project project = test::block3Project();
    const std::string before = serializeProject(project);
    UndoHistory history;
    EXPECT_FALSE(history.canUndo());
    const Project edited = c.edit(project);
    const std::string after = serializeProject(edited);
    ASSERT_NE(before, after) << "the edit changed nothing";
    ASSERT_TRUE(history.record(c.label, project, edited));
    project = edited;
    EXPECT_EQ(history.undoLabel(), c.label);

    ASSERT_TRUE(history.undo(project));
    EXPECT_EQ(serializeProject(project), before);
    EXPECT_FALSE(history.canUndo());
    EXPECT_EQ(history.redoLabel(), c.label);
    ASSERT_TRUE(history.redo(project));
    EXPECT_EQ(serializeProject(project), after);
    EXPECT_FALSE(history.redo(project));
  }
}

TEST(UndoHistory, ChainOfEditsUndoesAndRedoesInOrder) {
  Project project = test::block3Project();
  UndoHistory history;
  std::vector<std::string> saves{serializeProject(project)};
  for (const Case& c : kCases) {
    Project edited = c.edit(project);
    ASSERT_TRUE(history.record(c.label, project, edited));
    project = std::move(edited);
    saves.push_back(serializeProject(project));
  }
  EXPECT_EQ(history.undoCount(), std::size(kCases));
  for (size_t i = saves.size() - 1; i > 0; --i) {
    ASSERT_TRUE(history.undo(project));
    EXPECT_EQ(serializeProject(project), saves[i - 1]) << "after undoing step " << i;
  }
  for (size_t i = 1; i < saves.size(); ++i) {
    ASSERT_TRUE(history.redo(project));
    EXPECT_EQ(serializeProject(project), saves[i]) << "after redoing step " << i;
  }
}

TEST(UndoHistory, SettingsAreNotEditsAndAreLeftAlone) {
  Project project = test::block3Project();
  UndoHistory history;
  Project changed = project;
  changed.tools["brush.radius"] = 9.0;
  changed.camera.distance = 1.0;
  changed.simulation.timeStepS = 0.5;
  EXPECT_FALSE(history.record("Brush radius", project, changed));
  EXPECT_FALSE(history.canUndo());

  // Undo of a paint keeps the tool settings the user has since changed.
  Project painted = paintSamples(project);
  ASSERT_TRUE(history.record("Paint", project, painted));
  painted.tools["brush.radius"] = 9.0;
  ASSERT_TRUE(history.undo(painted));
  EXPECT_EQ(std::get<double>(painted.tools["brush.radius"]), 9.0);
  EXPECT_TRUE(sameMaterialSamples(painted.materials, project.materials));
}

TEST(UndoHistory, NewEditClearsTheRedoTail) {
  Project project = test::block3Project();
  UndoHistory history;
  Project a = paintSamples(project);
  history.record("Paint", project, a);
  Project b = pinAndUnpin(a);
  history.record("Pin", a, b);
  ASSERT_TRUE(history.undo(b));  // b is now a again
  EXPECT_TRUE(history.canRedo());
  Project c = movePoints(b);
  history.record("Move", b, c);
  EXPECT_FALSE(history.canRedo());
  EXPECT_EQ(history.redoLabel(), "");
  EXPECT_EQ(history.undoLabel(), "Move");
  EXPECT_EQ(history.undoCount(), 2u);
}

TEST(UndoHistory, MismatchedProjectIsRefusedAndLeftUnchanged) {
  Project project = test::block3Project();
  UndoHistory history;
  Project edited = deleteLastCell(project);
  history.record("Delete cell", project, edited);
  // Undo applied to the unedited project (the edit was lost): refused, nothing changes.
  const std::string bytes = serializeProject(project);
  EXPECT_THROW(history.undo(project), std::logic_error);
  EXPECT_EQ(serializeProject(project), bytes);
  EXPECT_TRUE(history.canUndo());
}

TEST(UndoHistory, StepBoundDropsTheOldest) {
  Project project = test::block3Project();
  const std::string original = serializeProject(project);
  UndoHistory history(UndoHistory::Limits{3, size_t{1} << 30});
  std::vector<std::string> saves{original};
  for (int i = 0; i < 5; ++i) {
    Project edited = project;
    edited.controlMesh.positions(0, 0) += 0.5;
    history.record(std::string("Move ").append(std::to_string(i)), project, edited);
    project = std::move(edited);
    saves.push_back(serializeProject(project));
  }
  EXPECT_EQ(history.undoCount(), 3u);
  while (history.undo(project)) {
  }
  // Only the last three edits could be undone: the state after the second edit.
  EXPECT_EQ(serializeProject(project), saves[2]);
  EXPECT_NE(serializeProject(project), original);
}

TEST(UndoHistory, MemoryBoundDropsTheOldestButKeepsTheNewest) {
  Project project = test::block3Project();
  // One paint of every sample stores 2 materials per sample: measure one entry, allow two.
  UndoHistory probe;
  Project all = project;
  for (Material& m : all.materials.materials) m.youngs *= 2;
  probe.record("Paint all", project, all);
  const size_t oneEntry = probe.bytes();
  EXPECT_GE(oneEntry, 2 * sizeof(Material) * project.materials.size());
  EXPECT_LT(oneEntry, 3 * sizeof(Material) * project.materials.size() + 4096);

  UndoHistory history(UndoHistory::Limits{100, 2 * oneEntry + oneEntry / 2});
  for (int i = 0; i < 4; ++i) {
    Project edited = project;
    for (Material& m : edited.materials.materials) m.youngs *= 2;
    history.record(std::string("Paint ").append(std::to_string(i)), project, edited);
    project = std::move(edited);
  }
  EXPECT_EQ(history.undoCount(), 2u);
  EXPECT_LE(history.bytes(), history.limits().maxBytes);
  EXPECT_EQ(history.undoLabel(), "Paint 3");

  UndoHistory tiny(UndoHistory::Limits{100, 16});
  Project edited = paintSamples(project);
  tiny.record("Paint", project, edited);
  EXPECT_EQ(tiny.undoCount(), 1u);  // the newest entry stays even over the bound
}

TEST(UndoHistory, PaintDeltaIsCompact) {
  Project project = test::block3Project();
  Project edited = project;
  edited.materials.materials[10].density = 10.0;
  UndoHistory history;
  history.record("Paint density", project, edited);
  // One changed sample: far less than a copy of all samples.
  EXPECT_LT(history.bytes(), project.materials.size() * sizeof(Material) / 10);
}

TEST(MaterialResampling, NearestSampleByRestPosition) {
  MaterialSamples from;
  from.level = 1;
  from.restPositions = {{0, 0, 0}, {1, 0, 0}, {0, 2, 0}, {1, 0, 0}};
  from.materials.resize(4);
  for (int i = 0; i < 4; ++i) from.materials[static_cast<size_t>(i)].youngs = 1.0e5 * (i + 1);
  const std::vector<Eigen::Vector3d> to = {{0.1, 0, 0}, {0.9, 0.1, 0}, {0, 1.6, 0}, {0.5, 0, 0}};
  const std::vector<Material> m = resampleMaterials(from, to);
  EXPECT_EQ(m[0].youngs, 1.0e5);
  EXPECT_EQ(m[1].youngs, 2.0e5);  // sample 3 coincides with 1: the lower index wins
  EXPECT_EQ(m[2].youngs, 3.0e5);
  EXPECT_EQ(m[3].youngs, 1.0e5);  // equidistant from 0 and 1: the lower index wins
  Material fallback;
  fallback.youngs = 7.0;
  EXPECT_EQ(resampleMaterials(MaterialSamples{}, to, fallback)[2].youngs, 7.0);

  // Against brute force on the block's samples.
  const Project project = test::block3Project();
  std::vector<Eigen::Vector3d> queries;
  for (int i = 0; i < 200; ++i) {
    queries.emplace_back(0.017 * i, 3.0 - 0.013 * i, 0.5 + 0.004 * i);
  }
  const std::vector<Material> fast = resampleMaterials(project.materials, queries);
  for (size_t q = 0; q < queries.size(); ++q) {
    size_t best = 0;
    for (size_t s = 1; s < project.materials.size(); ++s) {
      if ((project.materials.restPositions[s] - queries[q]).squaredNorm() <
          (project.materials.restPositions[best] - queries[q]).squaredNorm()) {
        best = s;
      }
    }
    EXPECT_TRUE(sameBits(fast[q], project.materials.materials[best])) << q;
  }
}

}  // namespace
}  // namespace sculpt
