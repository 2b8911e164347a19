// Applying a topology edit to a project (core/edit/project_edit.h): painted materials are carried
// over by position to the Gauss points of the edited solid, pins follow their vertices.

#include "edit/project_edit.h"

#include <gtest/gtest.h>

#include "project/project_file.h"
#include "support/edit_fixtures.h"
#include "tools/material_brush.h"

namespace sculpt {
namespace {

const Eigen::Vector3d kCentre(1.5, 1.5, 1.5);
constexpr double kRadius = 1.0;
constexpr double kStiff = 4.0e7;

// block3 at K = 1 with a stiff sphere painted (constant falloff: E = kStiff exactly inside).
Project paintedBlock3() {
  Project project;
  project.controlMesh = test::block3();
  const auto model = test::buildModel(project.controlMesh, 1, false);
  MaterialBrushSettings brush;
  brush.radius = kRadius;
  brush.falloff = Falloff::Constant;
  brush.fields = {false, false, true, false};
  brush.target.youngs = kStiff;
  brush.mirror.x = false;
  EXPECT_GT(paintDab(*model, kCentre, brush), 0);
  project.materials = captureMaterials(model->mesh(), 1);
  project.pins = {0, 1, 2, 63};
  return project;
}

// Gauss points clearly inside the sphere are stiff, clearly outside the default; the samples
// are exactly the Gauss points of the edited mesh at K = 1.
void expectSphereCarried(const Project& project) {
  const MaterialSamples& samples = project.materials;
  EXPECT_EQ(samples.level, 1);
  const auto model = test::buildModel(project.controlMesh, 1, false);
  ASSERT_EQ(samples.size(), model->mesh().numGaussPoints());
  EXPECT_EQ(samples.restPositions, model->mesh().gaussRestPosition);
  // Old samples are at most ~0.1 m apart at K = 1; 0.25 m keeps clear of the sphere's rim.
  constexpr double kMargin = 0.25;
  size_t inside = 0, outside = 0;
  for (size_t q = 0; q < samples.size(); ++q) {
    const double r = (samples.restPositions[q] - kCentre).norm();
    if (r < kRadius - kMargin) {
      ++inside;
      EXPECT_EQ(samples.materials[q].youngs, kStiff) << "sample " << q << " at r = " << r;
    } else if (r > kRadius + kMargin) {
      ++outside;
      EXPECT_EQ(samples.materials[q].youngs, Material{}.youngs)
          << "sample " << q << " at r = " << r;
    }
  }
  EXPECT_GT(inside, 100u);
  EXPECT_GT(outside, 100u);
}

TEST(ProjectEdit, SubdividingACellInsideThePaintKeepsTheSphere) {
  Project project = paintedBlock3();
  const size_t before = project.materials.size();
  applyTopologyEdit(project, subdivideCells(project.controlMesh, std::vector<uint32_t>{13}));
  EXPECT_EQ(project.controlMesh.numCells(), 34u);
  EXPECT_NE(project.materials.size(), before);  // new elements (irregular ones have fewer points)
  expectSphereCarried(project);
  EXPECT_EQ(project.pins, (std::vector<uint32_t>{0, 1, 2, 63}));  // ids kept, new ones unpinned
}

TEST(ProjectEdit, ExtrudingElsewhereKeepsTheSphereAndThePins) {
  Project project = paintedBlock3();
  applyTopologyEdit(project, extrudeFaces(project.controlMesh, std::vector<FaceRef>{{20, 1}}, 0.5));
  EXPECT_EQ(project.controlMesh.numCells(), 28u);
  expectSphereCarried(project);
  EXPECT_EQ(project.pins, (std::vector<uint32_t>{0, 1, 2, 63}));
}

TEST(ProjectEdit, DeletingACornerCellDropsAndRenumbersPins) {
  Project project = paintedBlock3();
  // Deleting cell 0 removes vertex 0 only: 1 -> 0, 2 -> 1, 63 -> 62.
  applyTopologyEdit(project, deleteCells(project.controlMesh, std::vector<uint32_t>{0}));
  EXPECT_EQ(project.pins, (std::vector<uint32_t>{0, 1, 62}));
  expectSphereCarried(project);
}

TEST(ProjectEdit, WeldingPinsBothSidesOnceAndProjectsWithoutPaintStayUnpainted) {
  Project project;
  project.controlMesh = test::twoParts(test::block3(), test::unitCube(), {3, 1, 1});
  project.materials.level = 2;  // no samples: uniform default material
  // Cube vertex 64 = (3,1,1) is welded onto block vertex 23 = (3,1,1).
  project.pins = {23, 64, 65};
  applyTopologyEdit(project, weldFaces(project.controlMesh, {14, 3}, {27, 5}, 1e-9));
  EXPECT_EQ(project.pins, (std::vector<uint32_t>{23, 64}));  // 65 (4,1,1) is renumbered to 64
  EXPECT_EQ(project.materials.size(), 0u);
  EXPECT_EQ(project.materials.level, 2);
}

}  // namespace
}  // namespace sculpt
