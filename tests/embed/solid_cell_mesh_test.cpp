// The level-K cells of the subdivided solid as a cell mesh: valid, and the deformer on it
// reproduces a rigid motion of the solid exactly.

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "embed/embedded_deformer.h"
#include "embed/solid_cell_mesh.h"
#include "io/control_mesh_json.h"
#include "subdiv/mj_refiner.h"

namespace sculpt {
namespace {

TEST(SolidCellMesh, RefinedMixedSolidIsAValidHexMeshThatMovesRigidly) {
  // mixed.json has hexahedra and a pyramid: the cells around the pyramid's apex stay
  // non-hexahedral at every level and are split around a centre node.
  const CellComplex control = loadControlMeshJson(SCULPT_SOURCE_DIR "/assets/mixed.json");
  const auto subdivision = subdivide(control, 2);
  ASSERT_TRUE(subdivision);
  const SolidCellMesh solid = solidCellMesh(subdivision->finest(), subdivision->finestTopology());
  const VolumeMesh& mesh = solid.mesh;
  EXPECT_GT(solid.centreVertices.numRows(), 0u);
  EXPECT_GT(mesh.numCells(), subdivision->finest().numCells());
  EXPECT_EQ(findVolumeMeshProblem(mesh), "");
  // The cells fill the same volume as the complex's hexahedra plus the split cells: compare the
  // embedded volume with a direct count of inside points further below (all cell centres are
  // inside some cell).

  // Points: the cell centres plus points a little outside the bounding box.
  Points points(mesh.numCells() + 8, 3);
  Eigen::AlignedBox3d box;
  for (uint32_t c = 0; c < mesh.numCells(); ++c) {
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    for (uint32_t v : mesh.cells.row(c))
      centre += mesh.positions.row(v).transpose() / static_cast<double>(mesh.cells.rowSize(c));
    points.row(c) = centre.transpose();
    box.extend(centre);
  }
  for (int k = 0; k < 8; ++k)
    points.row(mesh.numCells() + k) =
        (box.corner(static_cast<Eigen::AlignedBox3d::CornerType>(k)) + 0.1 * box.sizes())
            .transpose();
  EmbeddedDeformer deformer(mesh, points);
  EXPECT_EQ(deformer.embedding().outsideCount, 8u);
  const Eigen::Matrix3d R =
      Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  const Eigen::Vector3d t(0.5, -1.0, 2.0);
  const Points& vertices = subdivision->finest().positions;
  Points movedVertices(vertices.rows(), 3);
  for (Eigen::Index i = 0; i < vertices.rows(); ++i)
    movedVertices.row(i) = (R * vertices.row(i).transpose() + t).transpose();
  deformer.setFrame(solid.nodePositions(movedVertices), InterpolationMethod::Phong);
  const Points result = deformer.positions();
  for (Eigen::Index p = 0; p < points.rows(); ++p)
    EXPECT_LT((result.row(p).transpose() - (R * points.row(p).transpose() + t)).norm(), 1e-10) << p;
}

}  // namespace
}  // namespace sculpt
