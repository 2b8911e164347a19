// Element volumes (FemMesh::gaussVolume, the Gauss weights times det J) against exact volumes
// computed independently: boxes, affine images, bilinear-faced hexahedra by the divergence
// theorem, pyramids and tetrahedra by base * height / 3.

#include <gtest/gtest.h>

#include <Eigen/LU>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

#include "fem/fem_mesh.h"
#include "fem/fem_model.h"
#include "support/mesh_builders.h"

namespace sculpt {
namespace {

using namespace sculpt::test;

std::optional<FemModel> makeModel(const CellComplex& control, int level, bool trilinear) {
  std::string error;
  auto model = FemModel::create(control, FemSetup{level, trilinear, Material{}}, &error);
  EXPECT_TRUE(model.has_value()) << error;
  return model;
}

/// Volume of the elements of each control / level-K cell (sum of their Gauss volumes).
std::vector<double> volumePerCell(const FemMesh& mesh, uint32_t numCells) {
  std::vector<double> v(numCells, 0.0);
  for (uint32_t e = 0; e < mesh.numElements(); ++e)
    for (uint32_t q = mesh.gaussBegin(e); q < mesh.gaussBegin(e) + mesh.gaussCount(e); ++q)
      v[mesh.elementCell[e]] += mesh.gaussVolume[q];
  return v;
}

CellComplex affineImage(CellComplex m, const Eigen::Matrix3d& F, const Eigen::Vector3d& t) {
  for (Eigen::Index i = 0; i < m.positions.rows(); ++i)
    m.positions.row(i) = (F * m.positions.row(i).transpose() + t).transpose();
  return m;
}

Eigen::Matrix3d shear() {
  Eigen::Matrix3d F;
  F << 1.2, 0.3, -0.1, 0.1, 0.9, 0.2, 0.05, -0.2, 1.1;
  return F;
}

TEST(ElementVolume, BoxHexahedraAreExact) {
  auto model = makeModel(hexGrid(2, 3, 1, 0.5), 0, true);
  ASSERT_TRUE(model);
  const FemMesh& mesh = model->mesh();
  EXPECT_EQ(mesh.counts().trilinear, 6u);
  EXPECT_EQ(mesh.counts().total(), 6u);
  for (double v : volumePerCell(mesh, 6)) EXPECT_NEAR(v, 0.125, 1e-16);
  EXPECT_NEAR(mesh.restVolume(), 0.75, 1e-15);
  // Each Gauss point of a box carries an eighth of its element.
  for (double g : mesh.gaussVolume) EXPECT_NEAR(g, 0.125 / 8, 1e-17);
}

TEST(ElementVolume, AffineBoxScalesByDeterminant) {
  const Eigen::Matrix3d F = shear();
  const double det = F.determinant();
  auto model = makeModel(affineImage(hexGrid(3, 2, 2, 0.5), F, {1, -2, 3}), 0, true);
  ASSERT_TRUE(model);
  double worst = 0;
  for (double v : volumePerCell(model->mesh(), 12))
    worst = std::max(worst, std::abs(v - det * 0.125) / (det * 0.125));
  EXPECT_LT(worst, 1e-14);
  EXPECT_NEAR(model->mesh().restVolume(), det * 1.5, 1e-14);
  std::printf("affine box: det F = %.17g, volume %.17g (exact %.17g), worst cell rel. error %.3g\n",
              det, model->mesh().restVolume(), det * 1.5, worst);
}

TEST(ElementVolume, JitteredHexahedraMatchDivergenceTheorem) {
  // Non-planar (bilinear) faces: the trilinear hexahedron's volume equals the flux of x/3
  // through its bilinear faces, which the face fan from the vertex average reproduces exactly.
  const CellComplex control = jittered(hexGrid(3, 3, 3), 0.2, 5);
  auto model = makeModel(control, 0, true);
  ASSERT_TRUE(model);
  const std::vector<double> perCell = volumePerCell(model->mesh(), control.numCells());
  double worst = 0, total = 0;
  for (uint32_t c = 0; c < control.numCells(); ++c) {
    const double exact = signedVolume(control, c);
    total += exact;
    worst = std::max(worst, std::abs(perCell[c] - exact) / exact);
  }
  EXPECT_LT(worst, 1e-13);
  EXPECT_NEAR(model->mesh().restVolume(), total, 1e-13 * total);
  std::printf(
      "jittered 3x3x3 hex: volume %.17g vs divergence theorem %.17g, worst cell rel. "
      "error %.3g\n",
      model->mesh().restVolume(), total, worst);
}

TEST(ElementVolume, PyramidCubeCellsArePyramids) {
  // Six pyramids on the faces of the unit cube with an off-centre apex: each control cell is
  // split into 5 pyramid elements (one on its square, four tetrahedra on its triangles) around
  // its centroid; together they fill the pyramid, volume = face area * apex distance / 3.
  const Eigen::Vector3d apex(0.3, 0.6, 0.45);
  const CellComplex control = pyramidCube(apex);
  auto model = makeModel(control, 0, true);
  ASSERT_TRUE(model);
  const FemMesh& mesh = model->mesh();
  EXPECT_EQ(mesh.counts().pyramid, 30u);
  EXPECT_EQ(mesh.counts().total(), 30u);
  // Faces in pyramidCube's order: z=0, z=1, y=0, y=1, x=0, x=1.
  const double distance[6] = {apex.z(),     1 - apex.z(), apex.y(),
                              1 - apex.y(), apex.x(),     1 - apex.x()};
  const std::vector<double> perCell = volumePerCell(mesh, 6);
  double worst = 0;
  for (uint32_t c = 0; c < 6; ++c) {
    const double exact = distance[c] / 3.0;
    worst = std::max(worst, std::abs(perCell[c] - exact) / exact);
    EXPECT_NEAR(perCell[c], exact, 1e-15) << "cell " << c;
  }
  EXPECT_NEAR(mesh.restVolume(), 1.0, 1e-14);
  std::printf("pyramidCube: total volume %.17g (exact 1), worst cell rel. error %.3g\n",
              mesh.restVolume(), worst);
}

TEST(ElementVolume, OctahedronIsEightTetrahedra) {
  auto model = makeModel(octahedron(), 0, true);
  ASSERT_TRUE(model);
  const FemMesh& mesh = model->mesh();
  EXPECT_EQ(mesh.counts().pyramid, 8u);
  for (uint32_t e = 0; e < 8; ++e) {
    double v = 0;
    for (uint32_t q = mesh.gaussBegin(e); q < mesh.gaussBegin(e) + 8; ++q) v += mesh.gaussVolume[q];
    EXPECT_NEAR(v, 1.0 / 6.0, 1e-15) << "element " << e;  // tetrahedron 0, e_x, e_y, e_z
  }
  EXPECT_NEAR(mesh.restVolume(), 4.0 / 3.0, 1e-15);
  // The virtual centre node is the centroid of the 6 vertices.
  ASSERT_EQ(mesh.numNodes(), 7u);
  EXPECT_LT(mesh.restNodes.row(6).norm(), 1e-16);
}

TEST(ElementVolume, MixedMeshInTrilinearMode) {
  // 2 unit hexes, 2 half-cube prisms, pyramids of height 0.6 and 0.7 on unit squares.
  auto model = makeModel(mixedMesh(), 0, true);
  ASSERT_TRUE(model);
  const FemMesh& mesh = model->mesh();
  EXPECT_EQ(mesh.counts().trilinear, 2u);
  EXPECT_EQ(mesh.counts().pyramid, 20u);
  const double expected[6] = {1, 1, 0.5, 0.5, 0.6 / 3, 0.7 / 3};
  const std::vector<double> perCell = volumePerCell(mesh, 6);
  for (uint32_t c = 0; c < 6; ++c) EXPECT_NEAR(perCell[c], expected[c], 1e-15) << "cell " << c;
  EXPECT_NEAR(mesh.restVolume(), 3.0 + 1.3 / 3.0, 1e-14 * 3.5);
}

/// True when the 64 block nodes of tricubic element t form a uniform lattice with axis-aligned
/// edges of length h (the block's u, v, w may point along any of +-x, +-y, +-z).
bool uniformBlock(const FemMesh& mesh, uint32_t t, double h) {
  const auto& ids = mesh.tricubicNodes[t];
  auto X = [&](int a, int b, int g) -> Eigen::RowVector3d {
    return mesh.restNodes.row(ids[size_t(a * 16 + b * 4 + g)]);
  };
  const Eigen::RowVector3d du = X(1, 0, 0) - X(0, 0, 0), dv = X(0, 1, 0) - X(0, 0, 0),
                           dw = X(0, 0, 1) - X(0, 0, 0);
  for (const Eigen::RowVector3d& d : {du, dv, dw})
    if (std::abs(d.cwiseAbs().maxCoeff() - h) > 1e-14 || std::abs(d.norm() - h) > 1e-14)
      return false;
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b)
      for (int g = 0; g < 4; ++g)
        if ((X(a, b, g) - X(0, 0, 0) - a * du - b * dv - g * dw).norm() > 1e-14) return false;
  return true;
}

TEST(ElementVolume, TricubicElementOnUniformLatticeIsItsCell) {
  // At level 2 of a 3x3x3 unit grid the lattice edge is 1/4; blocks far from the boundary are
  // uniform, and the B-spline patch of a uniform block is exactly its centre cell.
  auto model = makeModel(hexGrid(3, 3, 3), 2, false);
  ASSERT_TRUE(model);
  const FemMesh& mesh = model->mesh();
  uint32_t uniform = 0;
  double worst = 0;
  for (uint32_t t = 0; t < mesh.numTricubic(); ++t) {
    if (!uniformBlock(mesh, t, 0.25)) continue;
    ++uniform;
    double v = 0;
    for (uint32_t q = mesh.gaussBegin(t); q < mesh.gaussBegin(t) + 64; ++q)
      v += mesh.gaussVolume[q];
    worst = std::max(worst, std::abs(v - 1.0 / 64) * 64);
    // The first Gauss point lies in the cell [1, 2]^3 of the block at the smallest Gauss
    // abscissa along u, v and w.
    const auto& ids = mesh.tricubicNodes[t];
    const Eigen::Vector3d corner = mesh.restNodes.row(ids[21]).transpose();
    const Eigen::Vector3d du = mesh.restNodes.row(ids[37]).transpose() - corner;
    const Eigen::Vector3d dv = mesh.restNodes.row(ids[25]).transpose() - corner;
    const Eigen::Vector3d dw = mesh.restNodes.row(ids[22]).transpose() - corner;
    const double g0 = 0.5 * (1 - 0.8611363115940525752);
    const Eigen::Vector3d first = mesh.gaussRestPosition[mesh.gaussBegin(t)];
    EXPECT_LT((first - corner - g0 * (du + dv + dw)).norm(), 1e-14);
  }
  EXPECT_GT(uniform, 0u);
  EXPECT_LT(worst, 1e-13);
  // For the record: tricubic elements cover their B-spline patches, trilinear ones their
  // lattice cells; where the lattice is not uniform the two do not tile exactly.
  const CellComplex& lattice = model->subdivision().finest();
  double latticeVolume = 0, tricubicVolume = 0, tricubicCells = 0;
  for (uint32_t c = 0; c < lattice.numCells(); ++c) latticeVolume += signedVolume(lattice, c);
  for (uint32_t t = 0; t < mesh.numTricubic(); ++t) {
    tricubicCells += signedVolume(lattice, mesh.elementCell[t]);
    for (uint32_t q = mesh.gaussBegin(t); q < mesh.gaussBegin(t) + 64; ++q)
      tricubicVolume += mesh.gaussVolume[q];
  }
  std::printf(
      "element volume %.15g, level-2 lattice volume %.15g; tricubic elements %.15g vs "
      "their lattice cells %.15g\n",
      mesh.restVolume(), latticeVolume, tricubicVolume, tricubicCells);
  std::printf(
      "3x3x3 grid level 2: %u tricubic elements, %u with uniform blocks, worst rel. "
      "volume error %.3g\n",
      mesh.numTricubic(), uniform, worst);
}

TEST(ElementVolume, AffineImageScalesEveryElementTypeByDeterminant) {
  // Subdivision commutes with affine maps, so every element (tricubic, trilinear, pyramid) of
  // the mapped model has det F times the volume of the original.
  const Eigen::Matrix3d F = shear();
  auto base = makeModel(mixedMesh(), 2, false);
  auto mapped = makeModel(affineImage(mixedMesh(), F, {0.5, 0.25, -1}), 2, false);
  ASSERT_TRUE(base && mapped);
  const FemMesh& a = base->mesh();
  const FemMesh& b = mapped->mesh();
  ASSERT_EQ(a.numGaussPoints(), b.numGaussPoints());
  EXPECT_GT(a.counts().tricubic, 0u);
  EXPECT_GT(a.counts().trilinear, 0u);
  EXPECT_GT(a.counts().pyramid, 0u);
  double worst = 0;
  for (uint32_t q = 0; q < a.numGaussPoints(); ++q)
    worst = std::max(
        worst, std::abs(b.gaussVolume[q] - F.determinant() * a.gaussVolume[q]) / a.gaussVolume[q]);
  EXPECT_LT(worst, 1e-12);
  std::printf(
      "mixed mesh level 2 (%u tricubic, %u trilinear, %u pyramid): volume %.15g, affine "
      "image worst rel. error %.3g\n",
      a.counts().tricubic, a.counts().trilinear, a.counts().pyramid, a.restVolume(), worst);
}

}  // namespace
}  // namespace sculpt
