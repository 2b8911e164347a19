// Every form against finite differences (energy vs gradient, gradient vs Hessian-vector product)
// on models with all element types, plus independent truths: enclosed volume, zero net pressure
// force, gravity's total weight, spring equilibrium, contact area, and rejection of absurd input.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <limits>
#include <memory>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "fem/fem_model.h"
#include "io/control_mesh_json.h"
#include "sim/load_forms.h"
#include "sim/material_point.h"
#include "sim/standard_forms.h"
#include "support/fem_builders.h"
#include "support/mesh_builders.h"

namespace sculpt {
namespace {

using test::block3;
using test::buildModel;
using test::randomPoints;

double sizeOf(const Points& p) {
  return (p.colwise().maxCoeff() - p.colwise().minCoeff()).norm();
}

// Total gradient on the control points: control + A^T nodes.
Points totalGradient(const FemModel& model, const Form& form, const Points& p) {
  Points nodes;
  model.nodesFromControl(p, nodes);
  FormGradient g;
  g.setZero(p.rows(), nodes.rows());
  form.addGradient(FormState{p, nodes}, g);
  model.addToControl(g.nodes, g.control);
  return g.control;
}

Points totalHessianProduct(const FemModel& model, const Form& form, const Points& p,
                           const Points& d) {
  Points nodes, dNodes;
  model.nodesFromControl(p, nodes);
  model.nodesFromControl(d, dNodes);
  FormGradient r;
  r.setZero(p.rows(), nodes.rows());
  form.addHessianProduct(FormState{p, nodes}, FormState{d, dNodes}, r);
  model.addToControl(r.nodes, r.control);
  return r.control;
}

double energyAt(const FemModel& model, const Form& form, const Points& p) {
  Points nodes;
  model.nodesFromControl(p, nodes);
  return form.energy(FormState{p, nodes});
}

struct DifferenceCheck {
  double energyError = 0;     // |fd - g.d| / |g.d|
  double hessianError = 0;    // |fd(g) - H d| / |H d|   (or / |g| when H d = 0)
  double directional = 0;     // g.d
  double hessianNorm = 0;     // |H d|
};

// Central differences along d at p with step eps.
DifferenceCheck differences(const FemModel& model, const Form& form, const Points& p,
                            const Points& d, double eps) {
  DifferenceCheck c;
  const Points plus = p + eps * d, minus = p - eps * d;
  const Points g = totalGradient(model, form, p);
  c.directional = g.cwiseProduct(d).sum();
  const double fd = (energyAt(model, form, plus) - energyAt(model, form, minus)) / (2 * eps);
  c.energyError = std::abs(fd - c.directional) / std::max(std::abs(c.directional), 1e-300);
  const Points Hd = totalHessianProduct(model, form, p, d);
  const Points fdH =
      (totalGradient(model, form, plus) - totalGradient(model, form, minus)) / (2 * eps);
  c.hessianNorm = Hd.norm();
  const double scale = c.hessianNorm > 0 ? c.hessianNorm : std::max(g.norm(), 1e-300);
  c.hessianError = (fdH - Hd).norm() / scale;
  return c;
}

// A model, a base state and a direction.
struct Scene {
  std::string name;
  std::unique_ptr<FemModel> model;
  Points base, direction, other;
  double size = 1;
};

Scene makeScene(const std::string& name, const CellComplex& control, const FemSetup& setup,
                uint64_t seed) {
  Scene s;
  s.name = name;
  s.model = buildModel(control, setup);
  if (!s.model) return s;
  // Heterogeneous material: a stiffer, denser, more damped ball.
  Material hard = setup.material;
  hard.youngs *= 7;
  hard.density *= 2;
  hard.damping = 11;
  hard.poisson = 0.41;
  const Points& rest = s.model->restControl();
  s.size = sizeOf(rest);
  s.model->paintMaterial(rest.row(0).transpose(), 0.5 * s.size, hard);
  std::mt19937_64 rng(seed);
  s.base = rest + randomPoints(rest.rows(), 0.03 * s.size, rng);
  s.direction = randomPoints(rest.rows(), 1.0, rng);
  s.other = rest + randomPoints(rest.rows(), 0.03 * s.size, rng);
  return s;
}

FemSetup setupFor(int level, bool trilinear) {
  FemSetup setup;
  setup.level = level;
  setup.trilinear = trilinear;
  setup.material.damping = 3.0;
  setup.material.youngs = 2.0e5;
  return setup;
}

std::vector<Scene> scenes() {
  std::vector<Scene> all;
  // Level 1 of the mixed mesh: trilinear hexahedra and pyramids (from its prisms and pyramids).
  all.push_back(makeScene("mixed level 1", test::jittered(test::mixedMesh(), 0.04, 5),
                          setupFor(1, false), 11));
  // Level 1 of the 3^3 block: tricubic interior elements, trilinear boundary.
  all.push_back(makeScene("block3 level 1", test::jittered(block3(), 0.08, 6), setupFor(1, false),
                          12));
  // The mixed mesh in trilinear mode: hexahedron and pyramids on the control cells (A = I).
  all.push_back(makeScene("mixed trilinear", test::jittered(test::mixedMesh(), 0.04, 7),
                          setupFor(1, true), 13));
  return all;
}

MaterialPoint someTricubicOrLinearPoint(const FemModel& model, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  std::uniform_int_distribution<uint32_t> pick(0, model.mesh().numElements() - 1);
  MaterialPoint point;
  point.element = pick(rng);
  point.local = Eigen::Vector3d(uni(rng), uni(rng), uni(rng));
  return point;
}

// Node-level boundary check: no contact node within `margin` of the kink along p +- eps d.
double medianBoundaryHeight(const FemModel& model, const Points& p, const Eigen::Vector3d& n) {
  Points nodes;
  model.nodesFromControl(p, nodes);
  const Topology& topology = model.subdivision().finestTopology();
  std::vector<double> heights;
  for (uint32_t v = 0; v < topology.numVertices; ++v)
    if (topology.vertexIsBoundary[v]) heights.push_back(n.dot(nodes.row(v).transpose()));
  std::sort(heights.begin(), heights.end());
  // Midway between two neighbouring heights near the median: away from every node.
  const size_t m = heights.size() / 2;
  return 0.5 * (heights[m] + heights[m + 1]);
}

TEST(FormsTest, FiniteDifferencesOfEveryForm) {
  for (Scene& s : scenes()) {
    ASSERT_TRUE(s.model) << s.name;
    FemModel& model = *s.model;
    const ElementCounts counts = model.mesh().counts();
    std::printf("[%s] %u tricubic, %u trilinear, %u pyramid elements, %u control points\n",
                s.name.c_str(), counts.tricubic, counts.trilinear, counts.pyramid,
                model.numControlPoints());
    std::mt19937_64 rng(99);
    std::vector<std::unique_ptr<Form>> forms;
    {
      auto elastic = std::make_unique<ElasticForm>(model, true);
      Points nodes;
      model.nodesFromControl(s.base, nodes);
      elastic->prepare(FormState{s.base, nodes});  // rotations frozen at the base state
      forms.push_back(std::move(elastic));
    }
    {
      auto inertia = std::make_unique<InertiaForm>(model, 0.01);
      inertia->setPrediction(s.other);
      forms.push_back(std::move(inertia));
      auto damping = std::make_unique<DampingForm>(model, 0.01);
      damping->setStart(s.other);
      forms.push_back(std::move(damping));
    }
    forms.push_back(std::make_unique<GravityForm>(model, Eigen::Vector3d(0.3, -1.2, -9.81)));
    forms.push_back(std::make_unique<PointForceForm>(model, someTricubicOrLinearPoint(model, rng),
                                                     Eigen::Vector3d(3, -2, 7)));
    forms.push_back(std::make_unique<PenaltySpringForm>(
        model, someTricubicOrLinearPoint(model, rng), Eigen::Vector3d(0.4, 5, -1), 1234.5));
    forms.push_back(std::make_unique<PressureForm>(model, 2500.0));
    const Eigen::Vector3d regionCentre = model.restControl().colwise().mean().transpose();
    auto partial = std::make_unique<PressureForm>(model, -1700.0,
                                                  SphereRegion{regionCentre, 0.45 * s.size});
    ASSERT_GT(partial->numTriangles(), 0u);
    forms.push_back(std::move(partial));
    const Eigen::Vector3d normal = Eigen::Vector3d(0.2, 0.3, 1.0).normalized();
    auto contact = std::make_unique<GroundContactForm>(
        model, normal, medianBoundaryHeight(model, s.base, normal), 3.0e6);
    {
      Points nodes;
      model.nodesFromControl(s.base, nodes);
      ASSERT_GT(contact->numInContact(nodes), 0u);
      ASSERT_LT(contact->numInContact(nodes), contact->nodeAreas().size());
    }
    forms.push_back(std::move(contact));

    // Step: small against the size of the model, large against rounding. The contact form
    // needs the active set unchanged within the step: checked below.
    const double eps = 1e-6 * s.size;
    for (const auto& form : forms) {
      if (form->name() == "ground contact") {
        const auto& c = static_cast<const GroundContactForm&>(*form);
        Points plus, minus;
        model.nodesFromControl(s.base + eps * s.direction, plus);
        model.nodesFromControl(s.base - eps * s.direction, minus);
        Points nodes;
        model.nodesFromControl(s.base, nodes);
        ASSERT_EQ(c.numInContact(plus), c.numInContact(nodes));
        ASSERT_EQ(c.numInContact(minus), c.numInContact(nodes));
      }
      const DifferenceCheck check = differences(model, *form, s.base, s.direction, eps);
      std::printf("  %-15s g.d = %+.6e  energy rel err %.2e   |Hd| = %.3e  Hessian rel err %.2e\n",
                  form->name().c_str(), check.directional, check.energyError, check.hessianNorm,
                  check.hessianError);
      EXPECT_LT(check.energyError, 1e-6) << s.name << ": " << form->name();
      EXPECT_LT(check.hessianError, 1e-6) << s.name << ": " << form->name();
      EXPECT_NE(check.directional, 0.0) << s.name << ": " << form->name();
    }
  }
}

// A 3 x 2 x 2 box of half-metre hexahedra on [0,1.5] x [0,1] x [0,1] whose interior vertices are
// jittered: the boundary stays planar, so the faceted volume and the element volume are both
// exactly the box's.
CellComplex jitteredBox() {
  CellComplex box = test::hexGrid(3, 2, 2, 0.5);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> uni(-0.08, 0.08);
  for (Eigen::Index v = 0; v < box.positions.rows(); ++v) {
    const Eigen::Vector3d x = box.positions.row(v).transpose();
    const bool interior = x[0] > 1e-9 && x[0] < 1.5 - 1e-9 && x[1] > 1e-9 && x[1] < 1 - 1e-9 &&
                          x[2] > 1e-9 && x[2] < 1 - 1e-9;
    if (interior)
      for (int d = 0; d < 3; ++d) box.positions(v, d) += uni(rng);
  }
  return box;
}

TEST(FormsTest, TheParallelRowProductIsTheScalarMatrixProduct) {
  // The inertia and damping forms apply M~ and D~ through applyScalarMatrix, rows split over the
  // workers (1,000 control points here); against Eigen's sparse product.
  auto model = buildModel(test::hexGrid(9, 9, 9), 1, false);
  ASSERT_TRUE(model);
  ASSERT_EQ(model->numControlPoints(), 1000);
  const double h = 1.0 / 60;
  const SparseMatrix S = (1 / (h * h)) * model->reducedMass() + (1 / h) * model->reducedDamping();
  std::mt19937_64 rng(11);
  const Points x = randomPoints(model->numControlPoints(), 1.0, rng);
  const Points out = applyScalarMatrix(S, x);
  const Eigen::MatrixXd columns = x;
  const Points expected = S * columns;
  EXPECT_LT((out - expected).cwiseAbs().maxCoeff(), 1e-12 * expected.cwiseAbs().maxCoeff());
}

TEST(FormsTest, PressureEnclosesTheBoxVolume) {
  auto model = buildModel(jitteredBox(), setupFor(1, true));
  ASSERT_TRUE(model);
  const double P = 1234.0;
  PressureForm pressure(*model, P);
  EXPECT_EQ(pressure.numTriangles(), 2u * 2u * (6 + 6 + 4));  // 16 boundary quads on each
  const Points& rest = model->restControl();
  const double volume = -energyAt(*model, pressure, rest) / P;
  std::printf("box: -E/P = %.15f, element volume = %.15f, exact 1.5\n", volume,
              model->mesh().restVolume());
  EXPECT_NEAR(volume, 1.5, 1e-13);
  EXPECT_NEAR(model->mesh().restVolume(), 1.5, 1e-13);
  // Positive pressure pushes the faces outward: the force -grad on a node of the x = 1.5 face
  // points along +x.
  const Points g = totalGradient(*model, pressure, rest);
  for (Eigen::Index v = 0; v < rest.rows(); ++v)
    if (std::abs(rest(v, 0) - 1.5) < 1e-12) {
      EXPECT_LT(g(v, 0), 0.0) << v;
    }
}

// On a subdivided (curved) solid the faceted volume of the finest lattice equals the volume of
// the same cells as trilinear hexahedra up to the bulge of non-planar boundary quadrilaterals.
// With tricubic elements the element volume is a little smaller: a tricubic element is the
// B-spline image of its cell, not the lattice hexahedron, so it does not conform to its trilinear
// neighbours. Both gaps are printed.
TEST(FormsTest, FacetedVolumeMatchesTheLatticeVolume) {
  for (int level = 1; level <= 2; ++level) {
    auto model = buildModel(block3(), setupFor(level, false));
    ASSERT_TRUE(model);
    PressureForm pressure(*model, 1.0);
    const double faceted = -energyAt(*model, pressure, model->restControl());
    FemMeshOptions options;
    options.allowTricubic = false;
    std::string error;
    const auto lattice = buildFemMesh(model->subdivision().finest(),
                                      model->subdivision().finestTopology(),
                                      model->subdivision().stencils, options, &error);
    ASSERT_TRUE(lattice.has_value()) << error;
    const double trilinear = lattice->restVolume();
    const double elements = model->mesh().restVolume();
    std::printf("block3 level %d: faceted %.9f, all-trilinear elements %.9f (gap %.1e), "
                "model elements %.9f (gap %.1e)\n",
                level, faceted, trilinear, std::abs(faceted - trilinear) / trilinear, elements,
                std::abs(faceted - elements) / elements);
    // The gap is the volume between each non-planar boundary quadrilateral's two triangles and
    // its bilinear patch; it falls fast with the level as the boundary flattens.
    EXPECT_LT(std::abs(faceted - trilinear), (level == 1 ? 1e-3 : 1e-5) * trilinear);
    EXPECT_LT(std::abs(faceted - elements), 1e-2 * elements);
  }
}

TEST(FormsTest, PressureOnAClosedSurfaceHasNoNetForceOrTorque) {
  for (Scene& s : scenes()) {
    ASSERT_TRUE(s.model);
    PressureForm pressure(*s.model, 5000.0);
    Points nodes;
    s.model->nodesFromControl(s.base, nodes);
    FormGradient g;
    g.setZero(s.base.rows(), nodes.rows());
    pressure.addGradient(FormState{s.base, nodes}, g);
    Eigen::Vector3d force = Eigen::Vector3d::Zero(), torque = Eigen::Vector3d::Zero();
    double magnitude = 0;
    for (Eigen::Index v = 0; v < nodes.rows(); ++v) {
      const Eigen::Vector3d f = -g.nodes.row(v).transpose();
      force += f;
      torque += nodes.row(v).transpose().cross(f);
      magnitude += f.norm();
    }
    std::printf("[%s] |net force| / sum |f_i| = %.2e, |net torque| / (size sum |f_i|) = %.2e\n",
                s.name.c_str(), force.norm() / magnitude, torque.norm() / (s.size * magnitude));
    EXPECT_LT(force.norm(), 1e-12 * magnitude) << s.name;
    EXPECT_LT(torque.norm(), 1e-12 * s.size * magnitude) << s.name;
    // Also on the control points (A has unit row sums).
    const Points total = totalGradient(*s.model, pressure, s.base);
    EXPECT_LT(total.colwise().sum().norm(), 1e-11 * magnitude) << s.name;
  }
}

TEST(FormsTest, GravityWeighsTheTotalMass) {
  for (Scene& s : scenes()) {
    ASSERT_TRUE(s.model);
    const Eigen::Vector3d g(0.5, -2.0, -9.81);
    GravityForm gravity(*s.model, g);
    const Points gradient = totalGradient(*s.model, gravity, s.base);
    const Eigen::Vector3d force = -gradient.colwise().sum().transpose();
    const Eigen::Vector3d expected = s.model->totalMass() * g;
    std::printf("[%s] total mass %.9g kg, |F - m g| / |m g| = %.2e\n", s.name.c_str(),
                s.model->totalMass(), (force - expected).norm() / expected.norm());
    EXPECT_LT((force - expected).norm(), 1e-10 * expected.norm()) << s.name;
  }
}

TEST(FormsTest, SpringAtItsTargetIsInEquilibrium) {
  for (Scene& s : scenes()) {
    ASSERT_TRUE(s.model);
    std::mt19937_64 rng(4);
    const MaterialPoint point = someTricubicOrLinearPoint(*s.model, rng);
    PenaltySpringForm spring(*s.model, point, Eigen::Vector3d::Zero(), 800.0);
    Points nodes;
    s.model->nodesFromControl(s.base, nodes);
    const Eigen::Vector3d here = materialPointPosition(s.model->mesh(), nodes, point);
    // The control-level position equals the node-level one.
    EXPECT_LT((spring.position(s.base) - here).norm(), 1e-12 * s.size) << s.name;
    spring.setTarget(here);
    EXPECT_LT(energyAt(*s.model, spring, s.base), 1e-20) << s.name;
    const Points g = totalGradient(*s.model, spring, s.base);
    EXPECT_LT(g.norm(), 1e-9) << s.name;  // 800 N/m times about a picometre of rounding
    // Moved target: the net force on the solid is k (target - x).
    const Eigen::Vector3d target = here + Eigen::Vector3d(0.1, -0.2, 0.3);
    spring.setTarget(target);
    const Eigen::Vector3d net =
        -totalGradient(*s.model, spring, s.base).colwise().sum().transpose();
    EXPECT_LT((net - 800.0 * (target - here)).norm(), 1e-10) << s.name;
  }
}

TEST(FormsTest, PointForceSumsToTheForceAndDoesWork) {
  for (Scene& s : scenes()) {
    ASSERT_TRUE(s.model);
    std::mt19937_64 rng(8);
    const MaterialPoint point = someTricubicOrLinearPoint(*s.model, rng);
    const Eigen::Vector3d f(1.5, -4, 2.5);
    PointForceForm load(*s.model, point, f);
    const Eigen::Vector3d net = -totalGradient(*s.model, load, s.base).colwise().sum().transpose();
    EXPECT_LT((net - f).norm(), 1e-12 * f.norm()) << s.name;
    Points nodes;
    s.model->nodesFromControl(s.base, nodes);
    const Eigen::Vector3d x = materialPointPosition(s.model->mesh(), nodes, point);
    EXPECT_NEAR(-energyAt(*s.model, load, s.base), f.dot(x), 1e-12 * f.norm() * s.size);
  }
}

TEST(FormsTest, ContactAreaWeightsAddUpToTheBoundaryArea) {
  auto model = buildModel(jitteredBox(), setupFor(1, true));
  ASSERT_TRUE(model);
  const double k = 1e5;
  GroundContactForm ground(*model, Eigen::Vector3d(0, 0, 2), -0.25, k);  // plane z = -0.25
  EXPECT_NEAR(ground.normal().norm(), 1.0, 1e-15);
  double area = 0;
  for (const auto& [v, a] : ground.nodeAreas()) area += a;
  EXPECT_NEAR(area, 2 * (1.5 * 1 + 1.5 * 1 + 1 * 1), 1e-12);
  const Points& rest = model->restControl();
  // Resting above the plane: no energy, no force.
  EXPECT_EQ(energyAt(*model, ground, rest), 0.0);
  EXPECT_EQ(totalGradient(*model, ground, rest).norm(), 0.0);
  // Every node 1 cm under the plane: energy k/2 (0.01)^2 * area, force k * 0.01 * area along n.
  Points sunk = rest;
  sunk.col(2).setConstant(-0.26);
  EXPECT_NEAR(energyAt(*model, ground, sunk), 0.5 * k * 1e-4 * area, 1e-9);
  const Eigen::Vector3d net = -totalGradient(*model, ground, sunk).colwise().sum().transpose();
  EXPECT_LT((net - Eigen::Vector3d(0, 0, k * 0.01 * area)).norm(), 1e-9);
}

template <typename F>
void expectRejected(F&& make, const std::string& fragment) {
  try {
    make();
    ADD_FAILURE() << "accepted input that should be rejected (" << fragment << ")";
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(fragment), std::string::npos) << what;
  }
}

TEST(FormsTest, AbsurdInputsAreRejectedWithASentence) {
  auto model = buildModel(test::unitCube(), setupFor(1, false));
  ASSERT_TRUE(model);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const MaterialPoint good{0, {0.5, 0.5, 0.5}};
  const Eigen::Vector3d zero = Eigen::Vector3d::Zero();
  expectRejected([&] { PenaltySpringForm(*model, good, zero, -1.0); }, "stiffness");
  expectRejected([&] { PenaltySpringForm(*model, good, zero, nan); }, "stiffness");
  expectRejected([&] { PenaltySpringForm(*model, good, Eigen::Vector3d(nan, 0, 0), 1.0); },
                 "target");
  expectRejected([&] { PenaltySpringForm(*model, {9999, {0.5, 0.5, 0.5}}, zero, 1.0); },
                 "out of range");
  expectRejected([&] { PenaltySpringForm(*model, {0, {0.5, nan, 0.5}}, zero, 1.0); }, "local");
  expectRejected([&] { PointForceForm(*model, {0, {1.5, 0.5, 0.5}}, zero); }, "local");
  expectRejected([&] { PointForceForm(*model, good, Eigen::Vector3d(0, inf, 0)); }, "force");
  expectRejected([&] { PressureForm(*model, nan); }, "pressure");
  expectRejected([&] { PressureForm(*model, 1.0, SphereRegion{zero, -2.0}); }, "radius");
  expectRejected([&] { PressureForm(*model, 1.0, SphereRegion{Eigen::Vector3d(nan, 0, 0), 1}); },
                 "centre");
  expectRejected([&] { GroundContactForm(*model, zero, 0.0, 1.0); }, "normal");
  expectRejected([&] { GroundContactForm(*model, Eigen::Vector3d::UnitZ(), nan, 1.0); }, "offset");
  expectRejected([&] { GroundContactForm(*model, Eigen::Vector3d::UnitZ(), 0.0, -5.0); },
                 "stiffness");
  PenaltySpringForm spring(*model, good, zero, 1.0);
  expectRejected([&] { spring.setStiffness(-3); }, "stiffness");
  expectRejected([&] { spring.setTarget(Eigen::Vector3d(0, 0, nan)); }, "target");
  EXPECT_EQ(spring.stiffness(), 1.0);  // a rejected setter leaves the form unchanged
}

}  // namespace
}  // namespace sculpt
