// Bad inputs are refused with a sentence naming the problem: inverted elements, bad levels,
// faces that pyramids cannot use, invalid materials.

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <numbers>
#include <string>

#include "fem/fem_mesh.h"
#include "fem/fem_model.h"
#include "io/control_mesh_json.h"
#include "support/mesh_builders.h"

namespace sculpt {
namespace {

using namespace sculpt::test;

bool contains(const std::string& text, const std::string& word) {
  return text.find(word) != std::string::npos;
}

TEST(FemRejection, InvertedHexFromFile) {
  const CellComplex control = loadControlMeshJson(std::filesystem::path(SCULPT_SOURCE_DIR) /
                                                  "tests" / "data" / "inverted_hex.json");
  std::string error;
  auto model = FemModel::create(control, FemSetup{0, true, Material{}}, &error);
  EXPECT_FALSE(model);
  EXPECT_TRUE(contains(error, "element 0")) << error;
  EXPECT_TRUE(contains(error, "inverted")) << error;
  EXPECT_TRUE(contains(error, "det J = -")) << error;
  std::printf("inverted_hex.json: %s\n", error.c_str());
}

TEST(FemRejection, InvertedSecondCellIsNamed) {
  // Fold cell 1 of a 2x1x1 grid by moving its far face (x = 2) back to x = 0.5: cell 0 is
  // untouched, cell 1 is inverted everywhere.
  CellComplex control = hexGrid(2, 1, 1);
  for (Eigen::Index v = 0; v < control.positions.rows(); ++v)
    if (control.positions(v, 0) == 2.0) control.positions(v, 0) = 0.5;
  std::string error;
  EXPECT_FALSE(FemModel::create(control, FemSetup{0, true, Material{}}, &error));
  EXPECT_TRUE(contains(error, "element 1 ")) << error;
  EXPECT_TRUE(contains(error, "cell 1")) << error;
  EXPECT_TRUE(contains(error, "trilinear")) << error;
  // A flat (degenerate) cell: the top face pressed onto the bottom one.
  CellComplex flat = unitCube();
  for (Eigen::Index v = 0; v < flat.positions.rows(); ++v) flat.positions(v, 2) = 0.0;
  error.clear();
  EXPECT_FALSE(FemModel::create(flat, FemSetup{0, true, Material{}}, &error));
  EXPECT_TRUE(contains(error, "degenerate")) << error;
}

TEST(FemRejection, LevelOutOfRange) {
  for (int level : {0, -1, 7}) {
    std::string error;
    EXPECT_FALSE(FemModel::create(unitCube(), FemSetup{level, false, Material{}}, &error)) << level;
    EXPECT_TRUE(contains(error, "level " + std::to_string(level))) << error;
  }
  // The level is ignored in trilinear mode.
  std::string error;
  EXPECT_TRUE(FemModel::create(unitCube(), FemSetup{0, true, Material{}}, &error)) << error;
}

TEST(FemRejection, PentagonalFacesNeedSubdivision) {
  // A pentagonal prism: its two pentagons cannot be pyramid bases in trilinear mode; at level 1
  // every face is a quadrilateral, every corner has valence 3, so the 10 children are hexes.
  std::vector<Eigen::Vector3d> p;
  for (int z = 0; z < 2; ++z)
    for (int i = 0; i < 5; ++i)
      p.emplace_back(std::cos(2 * std::numbers::pi * i / 5), std::sin(2 * std::numbers::pi * i / 5),
                     z);
  Loops loops = {{4, 3, 2, 1, 0}, {5, 6, 7, 8, 9}};
  for (uint32_t i = 0; i < 5; ++i) loops.push_back({i, (i + 1) % 5, 5 + (i + 1) % 5, 5 + i});
  const CellComplex prism = makeComplex(p, {loops});
  ASSERT_GT(signedVolume(prism, 0), 0.0);
  std::string error;
  EXPECT_FALSE(FemModel::create(prism, FemSetup{0, true, Material{}}, &error));
  EXPECT_TRUE(contains(error, "5 vertices")) << error;
  error.clear();
  auto subdivided = FemModel::create(prism, FemSetup{1, false, Material{}}, &error);
  ASSERT_TRUE(subdivided) << error;
  EXPECT_EQ(subdivided->mesh().counts().trilinear, 10u);
  EXPECT_EQ(subdivided->mesh().counts().total(), 10u);
}

TEST(FemRejection, InvalidMaterialAtCreation) {
  Material bad;
  bad.poisson = 0.7;
  std::string error;
  EXPECT_FALSE(FemModel::create(unitCube(), FemSetup{1, false, bad}, &error));
  EXPECT_TRUE(contains(error, "invalid material")) << error;
  EXPECT_TRUE(contains(error, "Poisson")) << error;
}

}  // namespace
}  // namespace sculpt
