// Material points: shape-function weights (sum to one, right shape, same position on nodes and
// on control points), location from rest positions (round trip to 1e-9 in jittered trilinear
// solids, pyramids and level-2 tricubic elements), snapping of outside points, absurd input.

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <limits>
#include <memory>
#include <random>
#include <string>

#include "fem/fem_model.h"
#include "io/control_mesh_json.h"
#include "sim/material_point.h"
#include "subdiv/tricubic_patch.h"
#include "support/fem_builders.h"
#include "support/mesh_builders.h"

namespace sculpt {
namespace {

using test::block3;
using test::buildModel;

Eigen::Vector3d row(const Points& p, uint32_t i) { return p.row(i).transpose(); }

// The test's own trilinear map: corners in VTK order (0,0,0), (1,0,0), (1,1,0), (0,1,0), then the
// same at w = 1.
Eigen::Vector3d ownTrilinear(const std::array<Eigen::Vector3d, 8>& corners,
                             const Eigen::Vector3d& xi) {
  const int bits[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                          {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  Eigen::Vector3d x = Eigen::Vector3d::Zero();
  for (int a = 0; a < 8; ++a) {
    double w = 1;
    for (int d = 0; d < 3; ++d) w *= bits[a][d] ? xi[d] : 1 - xi[d];
    x += w * corners[size_t(a)];
  }
  return x;
}

// The test's own evaluation of an element at rest.
Eigen::Vector3d ownRestPosition(const FemMesh& mesh, const MaterialPoint& p) {
  if (p.element < mesh.numTricubic()) {
    double bu[4], bv[4], bw[4];
    cubicBSplineBasis(p.local[0], bu);
    cubicBSplineBasis(p.local[1], bv);
    cubicBSplineBasis(p.local[2], bw);
    Eigen::Vector3d x = Eigen::Vector3d::Zero();
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b)
        for (int g = 0; g < 4; ++g)
          x += bu[a] * bv[b] * bw[g] *
               row(mesh.restNodes, mesh.tricubicNodes[p.element][size_t(a * 16 + b * 4 + g)]);
    return x;
  }
  std::array<Eigen::Vector3d, 8> corners;
  for (size_t a = 0; a < 8; ++a)
    corners[a] = row(mesh.restNodes, mesh.linearNodes[p.element - mesh.numTricubic()][a]);
  return ownTrilinear(corners, p.local);
}

MaterialPoint randomPoint(uint32_t first, uint32_t last,
                          std::mt19937_64& rng) {
  std::uniform_int_distribution<uint32_t> pick(first, last);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  return {pick(rng), Eigen::Vector3d(uni(rng), uni(rng), uni(rng))};
}

TEST(MaterialPointTest, WeightsSumToOneAndAgreeOnNodesAndControlPoints) {
  auto blocky = buildModel(test::jittered(block3(), 0.1, 2), 1, false);
  auto mixed = buildModel(test::jittered(test::mixedMesh(), 0.04, 3), 1, false);
  ASSERT_TRUE(blocky && mixed);
  std::mt19937_64 rng(17);
  int seen[3] = {0, 0, 0};
  double worstSum = 0, worstPosition = 0;
  for (const FemModel* model : {blocky.get(), mixed.get()}) {
    const FemMesh& mesh = model->mesh();
    for (int trial = 0; trial < 200; ++trial) {
      const MaterialPoint p = randomPoint(0, mesh.numElements() - 1, rng);
      const ElementType type = mesh.elementType[p.element];
      ++seen[int(type)];
      const auto nodes = nodeWeights(mesh, p);
      const size_t expected = type == ElementType::Tricubic ? 64u
                              : type == ElementType::Pyramid ? 5u
                                                             : 8u;
      EXPECT_EQ(nodes.size(), expected);
      if (type == ElementType::Tricubic) {
        for (size_t i = 0; i < 64; ++i) {
          EXPECT_EQ(nodes[i].first, mesh.tricubicNodes[p.element][i]);
        }
      }
      double sum = 0;
      for (const auto& [id, w] : nodes) sum += w;
      const auto control = controlWeights(mesh, p);
      double controlSum = 0;
      Eigen::Vector3d viaControl = Eigen::Vector3d::Zero();
      for (size_t i = 0; i < control.size(); ++i) {
        if (i > 0) {
          EXPECT_LT(control[i - 1].first, control[i].first);
        }
        controlSum += control[i].second;
        viaControl += control[i].second * row(model->restControl(), control[i].first);
      }
      worstSum = std::max({worstSum, std::abs(sum - 1), std::abs(controlSum - 1)});
      const Eigen::Vector3d x = materialPointPosition(mesh, mesh.restNodes, p);
      worstPosition = std::max({worstPosition, (x - viaControl).norm(),
                                (x - ownRestPosition(mesh, p)).norm()});
    }
  }
  std::printf("element types seen %d/%d/%d; worst |sum w - 1| = %.2e, worst position gap = %.2e\n",
              seen[0], seen[1], seen[2], worstSum, worstPosition);
  EXPECT_GT(seen[0], 0);
  EXPECT_GT(seen[1], 0);
  EXPECT_GT(seen[2], 0);
  EXPECT_LT(worstSum, 1e-13);
  EXPECT_LT(worstPosition, 1e-12);
}

struct RoundTrip {
  double worst = 0;
  int sameElement = 0, total = 0;
  double microseconds = 0;
};

RoundTrip roundTrip(const FemMesh& mesh, const std::vector<Eigen::Vector3d>& targets,
                    const std::vector<uint32_t>& sources) {
  RoundTrip r;
  const MaterialPointLocator locator(mesh);
  const auto start = std::chrono::steady_clock::now();
  for (size_t i = 0; i < targets.size(); ++i) {
    const auto found = locator.locate(targets[i]);
    EXPECT_TRUE(found.has_value());
    if (!found) continue;
    EXPECT_TRUE((found->local.array() >= 0).all() && (found->local.array() <= 1).all());
    const Eigen::Vector3d x = materialPointPosition(mesh, mesh.restNodes, *found);
    r.worst = std::max(r.worst, (x - targets[i]).norm());
    r.sameElement += found->element == sources[i];
    ++r.total;
  }
  r.microseconds = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() -
                                                             start)
                       .count() /
                   std::max<double>(1, double(targets.size()));
  return r;
}

TEST(MaterialPointTest, LocatesPointsOfAJitteredTrilinearSolid) {
  // 3 x 3 x 3 unit hexahedra with every vertex moved by up to 0.15: curved-free but non-affine
  // trilinear cells (and a non-planar boundary). Targets come from the control cells directly.
  const int n = 3;
  const CellComplex solid = test::jittered(test::hexGrid(n, n, n), 0.15, 4);
  auto model = buildModel(solid, 1, true);
  ASSERT_TRUE(model);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  std::uniform_int_distribution<int> cell(0, n - 1);
  std::vector<Eigen::Vector3d> targets;
  std::vector<uint32_t> sources;
  for (int trial = 0; trial < 500; ++trial) {
    const int i = cell(rng), j = cell(rng), k = cell(rng);
    std::array<Eigen::Vector3d, 8> corners;
    const int bits[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                            {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
    for (size_t a = 0; a < 8; ++a)
      corners[a] = test::pos(solid, test::gridVertex(n, n, i + bits[a][0], j + bits[a][1],
                                                     k + bits[a][2]));
    targets.push_back(ownTrilinear(corners, Eigen::Vector3d(uni(rng), uni(rng), uni(rng))));
    sources.push_back(UINT32_MAX);  // element numbering is the mesh's business
  }
  const RoundTrip r = roundTrip(model->mesh(), targets, sources);
  std::printf("jittered trilinear: %d points, worst |x(locate(X)) - X| = %.2e m, %.1f us/point\n",
              r.total, r.worst, r.microseconds);
  EXPECT_LT(r.worst, 1e-9);
}

TEST(MaterialPointTest, LocatesPointsOfPyramidsAndTricubicElements) {
  struct Case {
    const char* name;
    std::unique_ptr<FemModel> model;
  };
  Case cases[] = {
      {"mixed trilinear (hexahedron + pyramids)",
       buildModel(test::jittered(test::mixedMesh(), 0.04, 8), 1, true)},
      {"mixed level 1 (trilinear + pyramids)",
       buildModel(test::jittered(test::mixedMesh(), 0.04, 9), 1, false)},
      {"block3 level 2 (tricubic)", buildModel(test::jittered(block3(), 0.1, 10), 2, false)},
  };
  for (Case& c : cases) {
    ASSERT_TRUE(c.model) << c.name;
    const FemMesh& mesh = c.model->mesh();
    std::mt19937_64 rng(6);
    std::vector<Eigen::Vector3d> targets;
    std::vector<uint32_t> sources;
    // Tricubic elements when there are any, else the pyramids (and hexahedra).
    const bool tricubic = mesh.numTricubic() > 0;
    for (int trial = 0; trial < 400; ++trial) {
      const MaterialPoint p = tricubic ? randomPoint(0, mesh.numTricubic() - 1, rng)
                                       : randomPoint(0, mesh.numElements() - 1, rng);
      targets.push_back(ownRestPosition(mesh, p));
      sources.push_back(p.element);
    }
    const ElementCounts counts = mesh.counts();
    const RoundTrip r = roundTrip(mesh, targets, sources);
    std::printf("%s: %u/%u/%u elements, %d points, worst |x(locate(X)) - X| = %.2e m, "
                "%d found in their source element, %.1f us/point\n",
                c.name, counts.tricubic, counts.trilinear, counts.pyramid, r.total, r.worst,
                r.sameElement, r.microseconds);
    EXPECT_LT(r.worst, 1e-9) << c.name;
    if (tricubic) {
      EXPECT_GT(counts.tricubic, 900u);
    } else {
      EXPECT_GT(counts.pyramid, 0u);
    }
  }
}

TEST(MaterialPointTest, OutsidePointsSnapToTheNearestElement) {
  // Box [0,1.5] x [0,1] x [0,1] of half-metre cells with only its interior jittered: the nearest
  // point of the solid is known exactly.
  CellComplex box = test::hexGrid(3, 2, 2, 0.5);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> uni(-0.08, 0.08);
  for (Eigen::Index v = 0; v < box.positions.rows(); ++v) {
    const Eigen::Vector3d x = box.positions.row(v).transpose();
    if (x[0] > 0.1 && x[0] < 1.4 && x[1] > 0.1 && x[1] < 0.9 && x[2] > 0.1 && x[2] < 0.9)
      for (int d = 0; d < 3; ++d) box.positions(v, d) += uni(rng);
  }
  auto model = buildModel(box, 1, true);
  ASSERT_TRUE(model);
  const FemMesh& mesh = model->mesh();
  const std::pair<Eigen::Vector3d, Eigen::Vector3d> cases[] = {
      {{-0.3, 0.7, 0.8}, {0.0, 0.7, 0.8}},   {{-1, -1, -1}, {0, 0, 0}},
      {{0.75, 0.5, 2.0}, {0.75, 0.5, 1.0}},  {{2.0, 0.3, 0.4}, {1.5, 0.3, 0.4}},
      {{0.9, -0.25, 1.5}, {0.9, 0.0, 1.0}},  {{1.5, 1.0, 1.0}, {1.5, 1.0, 1.0}},
  };
  for (const auto& [X, nearest] : cases) {
    const auto p = locateMaterialPoint(mesh, X);
    ASSERT_TRUE(p.has_value());
    EXPECT_TRUE((p->local.array() >= 0).all() && (p->local.array() <= 1).all());
    const Eigen::Vector3d x = materialPointPosition(mesh, mesh.restNodes, *p);
    std::printf("(%g, %g, %g) -> element %u at (%.12f, %.12f, %.12f)\n", X[0], X[1], X[2],
                p->element, x[0], x[1], x[2]);
    EXPECT_LT((x - nearest).norm(), 1e-9);
  }

  // A curved boundary (block3 at level 2): the snapped point is no farther than any node of a
  // linear element (those nodes are points of the solid), and it is a local minimum of the
  // distance: perturbing the local coordinates within [0,1]^3 does not get closer.
  auto blob = buildModel(block3(), 2, false);
  ASSERT_TRUE(blob);
  const FemMesh& curved = blob->mesh();
  const MaterialPointLocator locator(curved);
  std::mt19937_64 dirs(12);
  std::normal_distribution<double> n01;
  for (int trial = 0; trial < 20; ++trial) {
    const Eigen::Vector3d X = Eigen::Vector3d(1.5, 1.5, 1.5) +
                              4.0 * Eigen::Vector3d(n01(dirs), n01(dirs), n01(dirs)).normalized();
    const auto p = locator.locate(X);
    ASSERT_TRUE(p.has_value());
    const double d = (materialPointPosition(curved, curved.restNodes, *p) - X).norm();
    double nodeDistance = std::numeric_limits<double>::infinity();
    for (uint32_t l = 0; l < curved.numLinear(); ++l)
      for (uint32_t node : curved.linearNodes[l])
        nodeDistance = std::min(nodeDistance, (row(curved.restNodes, node) - X).norm());
    EXPECT_LE(d, nodeDistance + 1e-12);
    for (int probe = 0; probe < 30; ++probe) {
      MaterialPoint q = *p;
      q.local = (q.local + 1e-3 * Eigen::Vector3d(n01(dirs), n01(dirs), n01(dirs)))
                    .cwiseMax(0.0)
                    .cwiseMin(1.0);
      EXPECT_GE((materialPointPosition(curved, curved.restNodes, q) - X).norm(), d - 1e-12);
    }
  }
}

TEST(MaterialPointTest, AbsurdInputs) {
  auto model = buildModel(test::unitCube(), 1, false);
  ASSERT_TRUE(model);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(locateMaterialPoint(model->mesh(), Eigen::Vector3d(nan, 0, 0)).has_value());
  EXPECT_FALSE(locateMaterialPoint(model->mesh(),
                                   Eigen::Vector3d(0, std::numeric_limits<double>::infinity(), 0))
                   .has_value());
  EXPECT_FALSE(locateMaterialPoint(FemMesh{}, Eigen::Vector3d::Zero()).has_value());
  EXPECT_FALSE(MaterialPointLocator(FemMesh{}).locate(Eigen::Vector3d::Zero()).has_value());
  try {
    nodeWeights(model->mesh(), MaterialPoint{model->mesh().numElements(), {0.5, 0.5, 0.5}});
    ADD_FAILURE() << "an element out of range was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("out of range"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace sculpt
