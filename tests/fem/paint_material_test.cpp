// FemModel::paintMaterial against a brute-force classification of independently computed Gauss
// points, and its effect on energy, mass and the material version.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "fem/fem_model.h"
#include "support/mesh_builders.h"

namespace sculpt {
namespace {

using namespace sculpt::test;

/// Gauss points of a trilinear n^3 unit-cube grid, computed by hand: cell corner + (1 -+
/// 1/sqrt3)/2.
std::vector<std::array<double, 3>> gridGaussPoints(int n) {
  const double g[2] = {0.5 - 0.5 / std::sqrt(3.0), 0.5 + 0.5 / std::sqrt(3.0)};
  std::vector<std::array<double, 3>> points;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k)
        for (int a = 0; a < 2; ++a)
          for (int b = 0; b < 2; ++b)
            for (int c = 0; c < 2; ++c) points.push_back({i + g[a], j + g[b], k + g[c]});
  return points;
}

bool inside(const Eigen::Vector3d& p, const Eigen::Vector3d& centre, double radius) {
  return (p - centre).norm() <= radius;
}

class PaintMaterial : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string error;
    model_ = FemModel::create(hexGrid(kN, kN, kN), FemSetup{0, true, base_}, &error);
    ASSERT_TRUE(model_) << error;
  }
  static constexpr int kN = 4;
  Material base_;
  std::optional<FemModel> model_;
  const Eigen::Vector3d centre_{2.1, 1.9, 2.2};
  const double radius_ = 1.3;
};

TEST_F(PaintMaterial, GaussPointsAreWhereTheyShouldBe) {
  // The stored rest positions are the hand-computed Gauss points (as sets).
  auto expected = gridGaussPoints(kN);
  std::vector<std::array<double, 3>> stored;
  for (const Eigen::Vector3d& p : model_->mesh().gaussRestPosition)
    stored.push_back({p.x(), p.y(), p.z()});
  ASSERT_EQ(stored.size(), expected.size());
  auto rounded = [](std::vector<std::array<double, 3>> v) {
    for (auto& p : v)
      for (double& x : p) x = std::round(x * 1e9) / 1e9;
    std::sort(v.begin(), v.end());
    return v;
  };
  EXPECT_EQ(rounded(stored), rounded(expected));
}

TEST_F(PaintMaterial, ChangesExactlyTheSamplesInsideTheSphere) {
  Material stiff;
  stiff.youngs = 3.0e6;
  stiff.poisson = 0.45;
  stiff.density = 500;
  long bruteForce = 0;
  for (const auto& p : gridGaussPoints(kN))
    bruteForce += inside({p[0], p[1], p[2]}, centre_, radius_);
  ASSERT_GT(bruteForce, 0);
  ASSERT_LT(bruteForce, long(kN * kN * kN * 8));
  const uint64_t version = model_->materialVersion();
  std::string error;
  const long changed = model_->paintMaterial(centre_, radius_, stiff, &error);
  EXPECT_EQ(changed, bruteForce);
  EXPECT_TRUE(error.empty()) << error;
  EXPECT_EQ(model_->materialVersion(), version + 1);
  const FemMesh& mesh = model_->mesh();
  // Lame parameters from the textbook formulas.
  const double lambda =
      stiff.youngs * stiff.poisson / ((1 + stiff.poisson) * (1 - 2 * stiff.poisson));
  const double mu = stiff.youngs / (2 * (1 + stiff.poisson));
  long painted = 0;
  for (uint32_t q = 0; q < mesh.numGaussPoints(); ++q) {
    const bool in = inside(mesh.gaussRestPosition[q], centre_, radius_);
    const Material& m = mesh.gaussMaterial[q];
    const Material& want = in ? stiff : base_;
    EXPECT_EQ(m.youngs, want.youngs) << q;
    EXPECT_EQ(m.poisson, want.poisson) << q;
    EXPECT_EQ(m.density, want.density) << q;
    if (in) {
      ++painted;
      EXPECT_NEAR(mesh.gaussLame[q].lambda, lambda, 1e-9 * lambda);
      EXPECT_NEAR(mesh.gaussLame[q].mu, mu, 1e-9 * mu);
    }
  }
  EXPECT_EQ(painted, bruteForce);
  std::printf(
      "sphere c = (2.1, 1.9, 2.2), r = 1.3 on the 4^3 grid: %ld of %u samples painted "
      "(brute force %ld)\n",
      changed, mesh.numGaussPoints(), bruteForce);

  // Mass: painted samples carry 1/8 of a unit cell each.
  const double expectedMass = base_.density * (64.0 - double(bruteForce) / 8.0) +
                              stiff.density * (double(bruteForce) / 8.0);
  EXPECT_NEAR(model_->totalMass(), expectedMass, 1e-12 * expectedMass);
  EXPECT_NEAR(model_->reducedMass().sum(), expectedMass, 1e-12 * expectedMass);

  // Painting the same material again changes no field, so the version stays (the return value
  // still counts the samples in the sphere).
  const long again = model_->paintMaterial(centre_, radius_, stiff, &error);
  EXPECT_EQ(model_->materialVersion(), version + 1);
  std::printf("repainting the same material returns %ld, version stays %llu\n", again,
              static_cast<unsigned long long>(model_->materialVersion()));
}

TEST_F(PaintMaterial, EnergyAndMassFollowThePaint) {
  // Uniform strain: the energy density scales with E at fixed nu, so painting E' = 2E into n
  // samples of volume 1/8 multiplies the energy by (64 + n/8) / 64.
  Points nodes = model_->restControl();
  nodes.col(0) *= 1.001;
  model_->elastic().resetRotations();
  model_->reducedMass();  // build the matrices before painting (they must refresh afterwards)
  const double before = model_->elastic().energy(nodes);
  Material twice = base_;
  twice.youngs *= 2;
  const long n = model_->paintMaterial(centre_, radius_, twice);
  ASSERT_GT(n, 0);
  const double after = model_->elastic().energy(nodes);
  EXPECT_NEAR(after / before, (64.0 + double(n) / 8.0) / 64.0, 1e-12);
  // Everything (infinite radius), density tripled: mass triples, also in the reduced matrix.
  Material heavy = base_;
  heavy.density *= 3;
  const uint64_t version = model_->materialVersion();
  EXPECT_EQ(model_->paintMaterial({0, 0, 0}, std::numeric_limits<double>::infinity(), heavy),
            long(model_->mesh().numGaussPoints()));
  EXPECT_EQ(model_->materialVersion(), version + 1);
  EXPECT_NEAR(model_->totalMass(), 3 * base_.density * 64, 1e-9);
  EXPECT_NEAR(model_->reducedMass().sum(), 3 * base_.density * 64, 1e-9);
  EXPECT_NEAR(model_->elastic().energy(nodes), before, 1e-12 * before);  // E back to base
}

TEST_F(PaintMaterial, SphereMissingTheModelChangesNothing) {
  const uint64_t version = model_->materialVersion();
  Material other;
  other.youngs = 7;
  EXPECT_EQ(model_->paintMaterial({100, 100, 100}, 1.0, other), 0);
  EXPECT_EQ(model_->materialVersion(), version);
  for (const Material& m : model_->mesh().gaussMaterial) EXPECT_EQ(m.youngs, base_.youngs);
}

TEST_F(PaintMaterial, InvalidMaterialIsRejected) {
  const uint64_t version = model_->materialVersion();
  struct Bad {
    Material material;
    std::string word;
  };
  std::vector<Bad> bad(5);
  bad[0].material.poisson = 0.5;
  bad[0].word = "Poisson";
  bad[1].material.youngs = -1;
  bad[1].word = "Young";
  bad[2].material.density = std::numeric_limits<double>::quiet_NaN();
  bad[2].word = "density";
  bad[3].material.damping = -0.1;
  bad[3].word = "damping";
  bad[4].material.poisson = -1.0;
  bad[4].word = "Poisson";
  for (const Bad& b : bad) {
    std::string error;
    EXPECT_EQ(model_->paintMaterial(centre_, radius_, b.material, &error), -1) << b.word;
    EXPECT_NE(error.find(b.word), std::string::npos) << error;
    EXPECT_NE(error.find("invalid material"), std::string::npos) << error;
    EXPECT_EQ(model_->paintMaterial(centre_, radius_, b.material, nullptr), -1);
  }
  EXPECT_EQ(model_->materialVersion(), version);
  for (const Material& m : model_->mesh().gaussMaterial) {
    EXPECT_EQ(m.youngs, base_.youngs);
    EXPECT_EQ(m.poisson, base_.poisson);
  }
}

}  // namespace
}  // namespace sculpt
