// Consistent mass and damping matrices (core/fem/mass_matrix.h, FemModel::reducedMass):
// partition of unity, symmetry and definiteness, the analytic consistent mass of trilinear
// boxes, and exact zeroth / first / second moments.

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <Eigen/SparseCholesky>
#include <cmath>
#include <cstdio>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "fem/fem_model.h"
#include "fem/mass_matrix.h"
#include "fem/quadrature.h"
#include "subdiv/tricubic_patch.h"
#include "support/mesh_builders.h"
#include "support/painted_mixed_model.h"

namespace sculpt {
namespace {

using namespace sculpt::test;

std::optional<FemModel> makeModel(const CellComplex& control, int level, bool trilinear,
                                  Material material = {}) {
  std::string error;
  auto model = FemModel::create(control, FemSetup{level, trilinear, material}, &error);
  EXPECT_TRUE(model.has_value()) << error;
  return model;
}

CellComplex scaled(CellComplex m, const Eigen::Vector3d& s) {
  for (Eigen::Index i = 0; i < m.positions.rows(); ++i)
    m.positions.row(i) = m.positions.row(i).cwiseProduct(s.transpose());
  return m;
}

struct MassCase {
  std::string name;
  CellComplex control;
  int level;
  bool trilinear;
  double exactVolume;  ///< < 0 when not known in closed form
};

std::vector<MassCase> massCases() {
  return {{"box 3x2x2 (h = 0.5), trilinear", hexGrid(3, 2, 2, 0.5), 0, true, 1.5},
          {"mixed mesh, trilinear", mixedMesh(), 0, true, 3.0 + 1.3 / 3.0},
          {"pyramid cube, trilinear", pyramidCube({0.3, 0.6, 0.45}), 0, true, 1.0},
          {"octahedron, trilinear", octahedron(), 0, true, 4.0 / 3.0},
          {"octahedron, level 1", octahedron(), 1, false, -1},
          {"jittered mixed mesh, level 2", jittered(mixedMesh(), 0.05, 8), 2, false, -1},
          {"jittered 2x2x2 grid, level 2", jittered(hexGrid(2, 2, 2, 0.5), 0.05, 3), 2, false, -1}};
}

TEST(MassMatrix, EntriesSumToTotalMass) {
  Material material;
  material.density = 2700.0;
  for (const MassCase& c : massCases()) {
    auto model = makeModel(c.control, c.level, c.trilinear, material);
    ASSERT_TRUE(model) << c.name;
    const SparseMatrix& M = model->reducedMass();
    ASSERT_EQ(M.rows(), Eigen::Index(model->numControlPoints()));
    const double sum = M.sum();
    const double total = model->totalMass();
    EXPECT_NEAR(sum, total, 1e-12 * total) << c.name;
    EXPECT_NEAR(total, material.density * model->mesh().restVolume(), 1e-12 * total) << c.name;
    if (c.exactVolume > 0) {
      EXPECT_NEAR(total, material.density * c.exactVolume, 1e-13 * total) << c.name;
    }
    std::printf("%-30s sum(M~) = %.15g, totalMass = %.15g, rel. diff %.2g\n", c.name.c_str(), sum,
                total, std::abs(sum - total) / total);
  }
}

TEST(MassMatrix, SymmetricPositiveDefinite) {
  for (const MassCase& c : massCases()) {
    auto model = makeModel(c.control, c.level, c.trilinear);
    ASSERT_TRUE(model) << c.name;
    const SparseMatrix& M = model->reducedMass();
    const SparseMatrix asymmetry = M - SparseMatrix(M.transpose());
    const double asym = asymmetry.nonZeros() ? asymmetry.coeffs().cwiseAbs().maxCoeff() : 0.0;
    EXPECT_LE(asym, 1e-14 * M.coeffs().cwiseAbs().maxCoeff()) << c.name;
    Eigen::SimplicialLLT<SparseMatrix> llt(M);
    EXPECT_EQ(llt.info(), Eigen::Success) << c.name;
    const Eigen::VectorXd eig =
        Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(Eigen::MatrixXd(M)).eigenvalues();
    EXPECT_GT(eig.minCoeff(), 0.0) << c.name;
    std::printf("%-30s %4ld control points, max asymmetry %.2g, eigenvalues in [%.4g, %.4g]\n",
                c.name.c_str(), long(M.rows()), asym, eig.minCoeff(), eig.maxCoeff());
  }
}

TEST(MassMatrix, SingleBoxHexahedronIsTheAnalyticConsistentMass) {
  // Box a x b x c: M_ab = rho V prod_axes (1/3 if the corners share the coordinate, else 1/6).
  const Eigen::Vector3d size(2.0, 0.5, 1.5);
  Material material;
  material.density = 7.5;
  auto model = makeModel(scaled(unitCube(), size), 0, true, material);
  ASSERT_TRUE(model);
  const Eigen::MatrixXd M(model->reducedMass());
  const double rhoV = material.density * size.prod();
  const Points& X = model->restControl();
  double worst = 0;
  for (int a = 0; a < 8; ++a)
    for (int b = 0; b < 8; ++b) {
      double expected = rhoV;
      for (int d = 0; d < 3; ++d) expected *= X(a, d) == X(b, d) ? 1.0 / 3.0 : 1.0 / 6.0;
      worst = std::max(worst, std::abs(M(a, b) - expected) / expected);
      EXPECT_NEAR(M(a, b), expected, 1e-14 * rhoV) << a << ", " << b;
    }
  std::printf(
      "box hex consistent mass: diagonal %.15g (rho V / 27 = %.15g), worst rel. error "
      "%.2g\n",
      M(0, 0), rhoV / 27, worst);
}

TEST(MassMatrix, BoxGridIsTensorProductOfOneDimensionalMasses) {
  // Structured n1 x n2 x n3 grid with spacings hx, hy, hz: M = rho Mx (x) My (x) Mz with the
  // assembled 1D linear-element masses (h/6 [2 1; 1 2] per element).
  const int n[3] = {3, 2, 2};
  const Eigen::Vector3d h(0.5, 0.25, 0.75);
  auto model = makeModel(scaled(hexGrid(n[0], n[1], n[2]), h), 0, true);
  ASSERT_TRUE(model);
  auto mass1d = [](int cells, double step) {
    Eigen::MatrixXd m = Eigen::MatrixXd::Zero(cells + 1, cells + 1);
    for (int e = 0; e < cells; ++e) {
      m(e, e) += step / 3;
      m(e + 1, e + 1) += step / 3;
      m(e, e + 1) += step / 6;
      m(e + 1, e) += step / 6;
    }
    return m;
  };
  const Eigen::MatrixXd Mx = mass1d(n[0], h[0]), My = mass1d(n[1], h[1]), Mz = mass1d(n[2], h[2]);
  const Eigen::MatrixXd M(model->reducedMass());
  const double rho = Material{}.density;
  double worst = 0;
  for (int a = 0; a < M.rows(); ++a)
    for (int b = 0; b < M.cols(); ++b) {
      auto ijk = [&](int v) {
        return std::array<int, 3>{v % (n[0] + 1), (v / (n[0] + 1)) % (n[1] + 1),
                                  v / ((n[0] + 1) * (n[1] + 1))};
      };
      const auto A = ijk(a), B = ijk(b);
      const double expected = rho * Mx(A[0], B[0]) * My(A[1], B[1]) * Mz(A[2], B[2]);
      worst = std::max(worst, std::abs(M(a, b) - expected));
    }
  EXPECT_LT(worst, 1e-13 * rho * h.prod());
  std::printf("3x2x2 box grid: max |M - rho Mx(x)My(x)Mz| = %.3g (element mass %.4g)\n", worst,
              rho * h.prod());
}

TEST(MassMatrix, MomentsAreExact) {
  // 1^T M~ X = rho * integral of X (first moment), exact for hexes, pyramids and tetrahedra
  // with planar faces. Centroids by hand: a pyramid's is a quarter of the way from its base
  // centroid to the apex, a prism's is its triangle's centroid at mid-height.
  const double rho = Material{}.density;
  struct Moment {
    std::string name;
    CellComplex control;
    double volume;
    Eigen::Vector3d firstMoment;
  };
  const std::vector<Moment> cases = {
      {"pyramid cube", pyramidCube({0.3, 0.6, 0.45}), 1.0, {0.5, 0.5, 0.5}},
      {"octahedron", octahedron(), 4.0 / 3.0, {0, 0, 0}},
      {"mixed mesh", mixedMesh(), 3.0 + 1.3 / 3.0,
       Eigen::Vector3d(0.5, 0.5, 0.5) + Eigen::Vector3d(1.5, 0.5, 0.5) +
           0.5 * Eigen::Vector3d(7.0 / 3, 2.0 / 3, 0.5) +
           0.5 * Eigen::Vector3d(8.0 / 3, 1.0 / 3, 0.5) +
           0.2 * Eigen::Vector3d(0.5, 0.5, 1.0 + 0.6 / 4) +
           (0.7 / 3) * Eigen::Vector3d(1.5, 0.5, 1.0 + 0.7 / 4)}};
  for (const Moment& c : cases) {
    auto model = makeModel(c.control, 0, true);
    ASSERT_TRUE(model) << c.name;
    const SparseMatrix& M = model->reducedMass();
    const Eigen::VectorXd ones = Eigen::VectorXd::Ones(M.rows());
    const Eigen::RowVector3d first = ones.transpose() * M * model->restControl();
    EXPECT_LT((first.transpose() - rho * c.firstMoment).norm(), 1e-12 * rho * c.volume)
        << c.name << ": " << first / rho;
    std::printf("%-13s first moment / rho = (%.15g, %.15g, %.15g), exact (%.15g, %.15g, %.15g)\n",
                c.name.c_str(), first[0] / rho, first[1] / rho, first[2] / rho, c.firstMoment[0],
                c.firstMoment[1], c.firstMoment[2]);
  }
  // Second moments of a box grid: X^T M X = rho integral X X^T (exact: degree 2 per axis).
  auto box = makeModel(hexGrid(2, 2, 2, 0.5), 0, true);
  ASSERT_TRUE(box);
  const Points& X = box->restControl();
  const Eigen::Matrix3d second = X.transpose() * box->reducedMass() * X;
  Eigen::Matrix3d exact = Eigen::Matrix3d::Constant(0.25);  // unit cube: int x y = 1/4
  exact.diagonal().setConstant(1.0 / 3.0);                  //            int x^2 = 1/3
  EXPECT_LT((second / rho - exact).cwiseAbs().maxCoeff(), 1e-14);
}

TEST(MassMatrix, NodeMassMatchesGaussSumForAffineFields) {
  // Every element type reproduces affine fields, so for u_n = c . X_n + d on the nodes
  //   u^T M u = sum_q rho V_q (c . X_q + d)^2
  // with X_q the stored Gauss rest positions: ties the mass shape tables (tricubic block order,
  // pyramid rule) to the geometry map.
  auto model = makeModel(jittered(mixedMesh(), 0.05, 8), 2, false);
  ASSERT_TRUE(model);
  const FemMesh& mesh = model->mesh();
  const SparseMatrix M = assembleNodeMatrix(mesh, MassField::Density);
  const Eigen::Vector3d c(0.3, -1.2, 0.7);
  const double d = 0.4;
  const Eigen::VectorXd u = mesh.restNodes * c + Eigen::VectorXd::Constant(mesh.numNodes(), d);
  double expected = 0;
  for (uint32_t q = 0; q < mesh.numGaussPoints(); ++q) {
    const double value = c.dot(mesh.gaussRestPosition[q]) + d;
    expected += mesh.gaussMaterial[q].density * mesh.gaussVolume[q] * value * value;
  }
  const double got = u.dot(M * u);
  EXPECT_NEAR(got, expected, 1e-12 * expected);
  std::printf("level-2 mixed mesh: u^T M u = %.15g, Gauss sum = %.15g\n", got, expected);
}

TEST(MassMatrix, TricubicEntriesAreTheQuadratureOfTheSquaredField) {
  // u^T M u = sum_q rho V_q u(X_q)^2 for any node values u, with u(X_q) the tricubic B-spline
  // sum at the Gauss point: checks every entry of the tricubic element matrices (which are
  // summed one axis at a time) against the plain triple sum. u is zero on the nodes of linear
  // elements, so only tricubic elements contribute.
  auto model = makeModel(jittered(hexGrid(3, 3, 3, 1.0 / 3), 0.04, 5), 2, false);
  ASSERT_TRUE(model);
  const FemMesh& mesh = model->mesh();
  ASSERT_GT(mesh.numTricubic(), 0u);
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> uniform(-1, 1);
  Eigen::VectorXd u(mesh.numNodes());
  for (Eigen::Index n = 0; n < u.size(); ++n) u[n] = uniform(rng);
  for (const auto& nodes : mesh.linearNodes)
    for (uint32_t n : nodes) u[n] = 0;
  const QuadratureRule rule = gaussLegendre(4);
  double B[4][4];
  for (int q = 0; q < 4; ++q) cubicBSplineBasis(rule.points[q], B[q]);
  double expected = 0;
  int nonzeroElements = 0;
  for (uint32_t e = 0; e < mesh.numTricubic(); ++e) {
    const auto& ids = mesh.tricubicNodes[e];
    bool any = false;
    for (int q = 0; q < 64; ++q) {
      double value = 0;
      for (int a = 0; a < 64; ++a)
        value += B[q / 16][a / 16] * B[(q / 4) % 4][(a / 4) % 4] * B[q % 4][a % 4] * u[ids[a]];
      const uint32_t g = mesh.gaussBegin(e) + uint32_t(q);
      expected += mesh.gaussMaterial[g].density * mesh.gaussVolume[g] * value * value;
      any = any || value != 0;
    }
    nonzeroElements += any;
  }
  ASSERT_GT(nonzeroElements, 8);
  const double got = u.dot(assembleNodeMatrix(mesh, MassField::Density) * u);
  EXPECT_NEAR(got, expected, 1e-12 * expected);
  std::printf("%d tricubic elements: u^T M u = %.15g, Gauss sum = %.15g\n", nonzeroElements, got,
              expected);
}

// The jittered mixed mesh at `level`, density 1200 kg/m^3 and damping 30 kg/(m^3 s).
constexpr double kDampedDensity = 1200, kDampedDamping = 30;
std::optional<FemModel> dampedMixedModel(int level) {
  Material material;
  material.density = kDampedDensity;
  material.damping = kDampedDamping;
  return makeModel(jittered(mixedMesh(), 0.05, 8), level, false, material);
}

TEST(MassMatrix, DampingMatrixIsDampingOverDensityTimesMass) {
  auto model = dampedMixedModel(1);
  ASSERT_TRUE(model);
  const SparseMatrix difference =
      model->reducedDamping() - (kDampedDamping / kDampedDensity) * model->reducedMass();
  EXPECT_LT(Eigen::MatrixXd(difference).cwiseAbs().maxCoeff(),
            1e-14 * Eigen::MatrixXd(model->reducedDamping()).cwiseAbs().maxCoeff());
  auto undamped = makeModel(mixedMesh(), 1, false);
  ASSERT_TRUE(undamped);
  EXPECT_EQ(undamped->reducedDamping().nonZeros(), 0);
}

TEST(MassMatrix, ReducedMatrixIsTheSparseProductOfTheStencilsAndTheNodeMatrix) {
  // reducedNodeMatrix builds A^T M A column by column without forming M A; Eigen's sparse
  // products give it independently. A painted ball makes density and damping vary between Gauss
  // points (and damping no longer proportional to density), on tricubic, trilinear and pyramid
  // elements.
  Material painted;
  painted.density = 7000;
  painted.damping = 40;
  auto model = test::paintedMixedModel(painted);
  ASSERT_TRUE(model);
  const FemMesh& mesh = model->mesh();
  const SparseMatrix& A = model->stencilMatrix();
  for (MassField field : {MassField::Density, MassField::Damping}) {
    const SparseMatrix M = assembleNodeMatrix(mesh, field);
    const double largest = Eigen::MatrixXd(M).cwiseAbs().maxCoeff();
    EXPECT_LT(Eigen::MatrixXd(M - SparseMatrix(M.transpose())).cwiseAbs().maxCoeff(),
              1e-14 * largest);
    const Eigen::MatrixXd expected = Eigen::MatrixXd(SparseMatrix(A.transpose()) * (M * A));
    const SparseMatrix reduced = reducedNodeMatrix(mesh, A, field);
    ASSERT_EQ(reduced.rows(), A.cols());
    ASSERT_EQ(reduced.cols(), A.cols());
    EXPECT_LT((Eigen::MatrixXd(reduced) - expected).cwiseAbs().maxCoeff(),
              1e-13 * expected.cwiseAbs().maxCoeff());
    // The same pattern as the product's nonzeros, exact zeros left out.
    EXPECT_EQ(reduced.nonZeros(), (expected.array() != 0.0).count());
  }
}

TEST(MassMatrix, PaintedMatricesAreWhatARebuildGives) {
  // Once assembled, the reduced mass and damping follow a paint dab by the change on the painted
  // elements alone; they must equal matrices rebuilt from the painted materials, and come back
  // to the first ones when the materials do (undo).
  auto model = dampedMixedModel(2);
  ASSERT_TRUE(model);
  const FemMesh& mesh = model->mesh();
  const SparseMatrix mass0 = model->reducedMass(), damping0 = model->reducedDamping();
  const std::vector<Material> original = mesh.gaussMaterial;
  const auto relativeDifference = [](const SparseMatrix& a, const SparseMatrix& b) {
    return Eigen::MatrixXd(a - b).cwiseAbs().maxCoeff() /
           Eigen::MatrixXd(b).cwiseAbs().maxCoeff();
  };

  Material painted;
  painted.density = 9000;
  painted.damping = 400;
  const Eigen::Vector3d corner = model->restControl().colwise().minCoeff().transpose();
  const long samples = model->paintMaterial(corner, 0.5, painted);
  ASSERT_GT(samples, 0);
  ASSERT_LT(samples, long(mesh.numGaussPoints()) / 8);  // a dab, not a repaint of everything
  const SparseMatrix& A = model->stencilMatrix();
  const SparseMatrix rebuiltMass = reducedNodeMatrix(mesh, A, MassField::Density);
  const SparseMatrix rebuiltDamping = reducedNodeMatrix(mesh, A, MassField::Damping);
  EXPECT_GT(relativeDifference(rebuiltMass, mass0), 1e-3);  // the dab changed the mass
  EXPECT_LT(relativeDifference(model->reducedMass(), rebuiltMass), 1e-13);
  EXPECT_LT(relativeDifference(model->reducedDamping(), rebuiltDamping), 1e-13);

  std::string error;
  ASSERT_TRUE(model->setMaterials(original, &error)) << error;
  EXPECT_LT(relativeDifference(model->reducedMass(), mass0), 1e-13);
  EXPECT_LT(relativeDifference(model->reducedDamping(), damping0), 1e-13);
}

}  // namespace
}  // namespace sculpt
