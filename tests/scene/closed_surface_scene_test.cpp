// SceneGeometry::closedOutward, which lets the renderer skip back faces: set for the scenes whose
// drawn surface bounds the solid facing out (the bunny, a control mesh's boundary, a closed OBJ)
// and not for an open OBJ or one whose faces point in.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "scene/scene_builder.h"

namespace sculpt {
namespace {

namespace fs = std::filesystem;

const std::string kAssets = std::string(SCULPT_SOURCE_DIR) + "/assets/";

bool closedOutward(const SceneSource& source) {
  const std::optional<SceneBuildPhase1> phase1 = buildSceneGeometry(source, SceneSettings{}, 1);
  if (!phase1) throw std::runtime_error("cancelled");
  EXPECT_FALSE(phase1->geometry->triangles.empty());
  return phase1->geometry->closedOutward;
}

// A unit cube as an OBJ file: six quads facing out (counter-clockwise seen from outside), or in,
// with its top face left out when `open`.
fs::path writeCube(const std::string& name, bool outward, bool open) {
  const fs::path path = fs::path(testing::TempDir()) / name;
  std::ofstream out(path);
  for (int corner = 0; corner < 8; ++corner)
    out << "v " << (corner & 1) << ' ' << ((corner >> 1) & 1) << ' ' << ((corner >> 2) & 1)
        << '\n';
  // 1-based corners, bit 0 x, bit 1 y, bit 2 z; each loop counter-clockwise seen from outside.
  const char* outwardFaces[] = {"1 3 4 2", "5 6 8 7", "1 2 6 5",
                                "3 7 8 4", "1 5 7 3", "2 4 8 6"};
  for (int f = 0; f < 6; ++f) {
    if (open && f == 3) continue;  // y = 1
    std::string face = outwardFaces[f];
    if (!outward) face = std::string(face.rbegin(), face.rend());
    out << "f " << face << '\n';
  }
  return path;
}

TEST(ClosedSurfaceScene, TheBunnyAndAControlMeshBoundaryAreClosedFacingOut) {
  EXPECT_TRUE(closedOutward(SceneSource{}));  // 235,136 triangles, Loop-refined
  EXPECT_TRUE(closedOutward({SceneKind::ControlMesh, kAssets + "block3.json"}));
  EXPECT_TRUE(closedOutward({SceneKind::ControlMesh, kAssets + "chair.json"}));
}

TEST(ClosedSurfaceScene, AnImportedCubeIsClosedOutwardOnlyWhenItIs) {
  EXPECT_TRUE(closedOutward(
      {SceneKind::ImportedSurface, writeCube("closed_cube.obj", true, false).string()}));
  EXPECT_FALSE(closedOutward(
      {SceneKind::ImportedSurface, writeCube("inward_cube.obj", false, false).string()}));
  EXPECT_FALSE(closedOutward(
      {SceneKind::ImportedSurface, writeCube("open_cube.obj", true, true).string()}));
}

}  // namespace
}  // namespace sculpt
