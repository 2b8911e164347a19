// (docs/design/mj-subdivision.md §5.4, §7.4): the boundary of the MJ-refined
// lattice at levels 1..3 equals OpenSubdiv's Catmull–Clark refinement of the level-0 boundary
// (Sdc::SCHEME_CATMARK, creases as infinitely sharp edges, corners as infinitely sharp vertices),
// point for point, to 1e-12 of the bounding-box diagonal (support/opensubdiv_oracle.h).

#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <string>

#include "io/control_mesh_json.h"
#include "support/mesh_builders.h"
#include "support/opensubdiv_oracle.h"

namespace sculpt {
namespace {

using test::compareWithOpenSubdiv;
using test::jittered;
using test::NamedMesh;
using test::taggedMixed;

/// All box edges of an nx by ny by nz grid as creases, and its 8 corners tagged.
CellComplex boxCreasedGrid(int nx, int ny, int nz) {
  CellComplex m = test::hexGrid(nx, ny, nz);
  auto g = [&](int i, int j, int k) { return test::gridVertex(nx, ny, i, j, k); };
  for (int j : {0, ny})
    for (int k : {0, nz})
      for (int i = 0; i < nx; ++i) m.creases.push_back({g(i, j, k), g(i + 1, j, k)});
  for (int i : {0, nx})
    for (int k : {0, nz})
      for (int j = 0; j < ny; ++j) m.creases.push_back({g(i, j, k), g(i, j + 1, k)});
  for (int i : {0, nx})
    for (int j : {0, ny})
      for (int k = 0; k < nz; ++k) m.creases.push_back({g(i, j, k), g(i, j, k + 1)});
  for (int i : {0, nx})
    for (int j : {0, ny})
      for (int k : {0, nz}) m.corners.push_back(g(i, j, k));
  test::jitter(m, 0.05, 31);
  return m;
}

class OwnMeshes : public ::testing::TestWithParam<NamedMesh> {};

TEST_P(OwnMeshes, BoundaryEqualsOpenSubdiv) { compareWithOpenSubdiv(GetParam().build()); }

const NamedMesh kOwnMeshes[] = {
    {"Block3x2x2Perturbed", [] { return jittered(test::hexGrid(3, 2, 2), 0.12, 1); }},
    {"KuhnCube", [] { return jittered(test::kuhnCube(), 0.04, 2); }},
    {"PyramidCube",
     [] {
       return jittered(test::pyramidCube({0.5, 0.5, 0.75}), 0.04, 3);
     }},
    {"PrismCube", [] { return jittered(test::prismCube(), 0.04, 4); }},
    {"Octahedron", [] { return jittered(test::octahedron(), 0.04, 5); }},
    {"MixedJittered", [] { return jittered(test::mixedMesh(), 0.05, 6); }},
    {"MixedTagged", taggedMixed},
    {"Block3x2x2BoxCreased", [] { return boxCreasedGrid(3, 2, 2); }},
};
INSTANTIATE_TEST_SUITE_P(Meshes, OwnMeshes, ::testing::ValuesIn(kOwnMeshes),
                         [](const auto& p) { return p.param.name; });

class Assets : public ::testing::TestWithParam<std::string> {};

TEST_P(Assets, BoundaryEqualsOpenSubdiv) {
  const std::filesystem::path path =
      std::filesystem::path(SCULPT_SOURCE_DIR) / "assets" / (GetParam() + ".json");
  ASSERT_TRUE(std::filesystem::exists(path)) << "missing asset " << path.string();
  CellComplex control;
  try {
    control = loadControlMeshJson(path);
  } catch (const std::exception& e) {
    FAIL() << "cannot load " << path.string() << ": " << e.what();
  }
  compareWithOpenSubdiv(control);
}

INSTANTIATE_TEST_SUITE_P(Assets, Assets,
                         ::testing::Values("cube", "block3", "beam", "ring", "chair", "house",
                                           "tet", "mixed"),
                         [](const auto& p) { return p.param; });

}  // namespace
}  // namespace sculpt
