// A project's painted materials go back into a simulation: capture the Gauss-sample materials of
// a painted model, save and load the project, resample onto a fresh model of the same solid and
// set them. The fresh model then holds the painted materials bit for bit, and its reduced mass
// matrix equals the painted model's.

#include <gtest/gtest.h>

#include <cstring>

#include "project/project.h"
#include "project/project_file.h"
#include "support/fem_builders.h"

namespace sculpt {
namespace {

TEST(ProjectMaterials, SavedPaintRestoresIntoAFreshModel) {
  const CellComplex control = test::block3();
  const auto painted = test::buildModel(control, 1, false);
  ASSERT_TRUE(painted);
  Material stiff;
  stiff.youngs = 4.0e7;
  stiff.density = 2500.0;
  stiff.damping = 3.0;
  ASSERT_GT(painted->paintMaterial(Eigen::Vector3d(2.5, 1.5, 1.5), 0.9, stiff), 0);

  Project project;
  project.controlMesh = control;
  project.materials = captureMaterials(painted->mesh(), 1);
  const Project loaded = parseProject(serializeProject(project), "painted.sculpt");

  const auto fresh = test::buildModel(control, 1, false);
  ASSERT_TRUE(fresh);
  const uint64_t before = fresh->materialVersion();
  const std::vector<Material> restored =
      resampleMaterials(loaded.materials, fresh->mesh().gaussRestPosition);
  std::string error;
  ASSERT_TRUE(fresh->setMaterials(restored, &error)) << error;
  EXPECT_GT(fresh->materialVersion(), before);
  const auto& a = painted->mesh().gaussMaterial;
  const auto& b = fresh->mesh().gaussMaterial;
  ASSERT_EQ(a.size(), b.size());
  for (size_t q = 0; q < a.size(); ++q) {
    EXPECT_EQ(std::memcmp(&a[q].youngs, &b[q].youngs, sizeof(double)), 0) << q;
    EXPECT_EQ(std::memcmp(&a[q].density, &b[q].density, sizeof(double)), 0) << q;
  }
  EXPECT_EQ((painted->reducedMass() - fresh->reducedMass()).norm(), 0.0);

  // A wrong count or an invalid material changes nothing and says why.
  const std::vector<Material> tooFew(3);
  EXPECT_FALSE(fresh->setMaterials(tooFew, &error));
  EXPECT_NE(error.find("3 materials for"), std::string::npos) << error;
  std::vector<Material> invalid = restored;
  invalid[5].poisson = 0.7;
  const uint64_t version = fresh->materialVersion();
  EXPECT_FALSE(fresh->setMaterials(invalid, &error));
  EXPECT_NE(error.find("material 5"), std::string::npos) << error;
  EXPECT_EQ(fresh->materialVersion(), version);
  EXPECT_EQ(fresh->mesh().gaussMaterial[5].poisson, restored[5].poisson);
}

}  // namespace
}  // namespace sculpt
