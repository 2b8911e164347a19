#include "embed/interpolation_study.h"

#include <cmath>
#include <random>

#include <Eigen/Geometry>

#include "embed/embedded_deformer.h"
#include "embed/kelvinlet.h"
#include "mesh/lattice_mesh.h"

namespace sculpt {

MethodErrors measureInterpolationErrors(const VolumeMesh& mesh, const Points& testPoints,
                                        const AnalyticDeformation& phi, GradientScheme scheme,
                                        double eps) {
  DeformerSettings settings;
  settings.eps = eps;
  settings.gradients = scheme;
  EmbeddedDeformer deformer(mesh, testPoints, settings);
  Points nodes(mesh.positions.rows(), 3);
  for (Eigen::Index i = 0; i < nodes.rows(); ++i)
    nodes.row(i) = phi(mesh.positions.row(i).transpose()).transpose();
  Points truth(testPoints.rows(), 3);
  for (Eigen::Index p = 0; p < testPoints.rows(); ++p)
    truth.row(p) = phi(testPoints.row(p).transpose()).transpose();
  MethodErrors errors;
  for (size_t m = 0; m < kAllMethods.size(); ++m) {
    deformer.setFrame(nodes, kAllMethods[m]);
    const Points result = deformer.positions();
    const Eigen::VectorXd distance = (result - truth).rowwise().norm();
    errors.max[m] = distance.maxCoeff();
    errors.rms[m] = std::sqrt(distance.squaredNorm() / static_cast<double>(distance.size()));
  }
  return errors;
}

Eigen::Vector3d bendAndTwist(const Eigen::Vector3d& X) {
  constexpr double kBendRadius = 1.5, kTwistRate = 0.8;
  // Bend: the x-z plane wrapped around a circle of radius R about the y axis.
  const double angle = X.z() / kBendRadius;
  const Eigen::Vector3d bent((kBendRadius + X.x()) * std::cos(angle) - kBendRadius, X.y(),
                             (kBendRadius + X.x()) * std::sin(angle));
  // Twist about z, proportional to height.
  const double twist = kTwistRate * bent.z();
  return Eigen::AngleAxisd(twist, Eigen::Vector3d::UnitZ()) * bent;
}

ConvergenceSeries runConvergenceStudy(StudyCells cells, StudyPlacement placement,
                                      std::span<const double> spacings,
                                      GradientScheme scheme, double eps) {
  // The test cube's corner is fixed; three layers of cubes surround it (none above it in the
  // surface case, none above and in +x and +y at a corner), so the mesh shrinks with h around
  // fixed test points.
  const Eigen::Vector3d P0(0.1, 0.2, 0.3);
  constexpr uint32_t kLayers = 3;
  std::mt19937 random(2020);
  std::uniform_real_distribution<double> uniform(0.05, 0.95);
  std::vector<Eigen::Vector3d> unitPositions(25);
  for (auto& q : unitPositions)
    q = Eigen::Vector3d(uniform(random), uniform(random), uniform(random));

  ConvergenceSeries series;
  series.cells = cells;
  series.placement = placement;
  series.scheme = scheme;
  for (double h : spacings) {
    LatticeSpec spec;
    const uint32_t above = placement == StudyPlacement::Interior ? kLayers : 0;
    const uint32_t beside = placement == StudyPlacement::Corner ? 0 : kLayers;
    spec.cubes = {kLayers + 1 + beside, kLayers + 1 + beside, kLayers + 1 + above};
    spec.spacing = h;
    spec.origin = P0 - h * Eigen::Vector3d(kLayers, kLayers, kLayers);
    const VolumeMesh mesh = cells == StudyCells::Tetrahedra ? tetLattice(spec) : hexLattice(spec);
    Points testPoints(static_cast<Eigen::Index>(unitPositions.size()), 3);
    for (size_t k = 0; k < unitPositions.size(); ++k)
      testPoints.row(static_cast<Eigen::Index>(k)) = (P0 + h * unitPositions[k]).transpose();
    ConvergenceRow row;
    row.spacing = h;
    row.meanEdge = meanEdgeLength(mesh);
    row.errors = measureInterpolationErrors(mesh, testPoints, bendAndTwist, scheme, eps);
    series.rows.push_back(row);
  }
  std::vector<double> x, y;
  for (size_t m = 0; m < kAllMethods.size(); ++m) {
    x.clear();
    y.clear();
    for (const ConvergenceRow& row : series.rows) {
      x.push_back(row.meanEdge);
      y.push_back(row.errors.max[m]);
    }
    series.slopes[m] = logLogSlope(x, y);
  }
  return series;
}

const char* brushName(KelvinletBrush brush) {
  switch (brush) {
    case KelvinletBrush::Grab: return "grab";
    case KelvinletBrush::Twist: return "twist";
    case KelvinletBrush::Pinch: return "pinch";
  }
  return "?";
}

namespace {

RegularizedKelvinlet makeBrush(KelvinletBrush brush, double amplitude) {
  const Eigen::Vector3d centre(0.013, -0.021, 0.017);  // off the lattice's symmetry points
  const double eps = 1.0;
  switch (brush) {
    case KelvinletBrush::Grab:
      return RegularizedKelvinlet::grab(centre, amplitude * Eigen::Vector3d(1.0, 0.5, -0.3), eps);
    case KelvinletBrush::Twist:
      return RegularizedKelvinlet::twist(centre, amplitude * Eigen::Vector3d(0.2, 0.3, 1.0), eps);
    case KelvinletBrush::Pinch: {
      Eigen::Matrix3d F;
      F << 1.0, 0.3, 0.0, 0.3, -0.5, 0.2, 0.0, 0.2, -0.5;
      return RegularizedKelvinlet::pinch(centre, amplitude * F, eps);
    }
  }
  return RegularizedKelvinlet::grab(centre, Eigen::Vector3d::Zero(), eps);
}

}  // namespace

std::vector<KelvinletRow> runKelvinletStudy(std::span<const double> spacingOverEps,
                                            bool jittered, GradientScheme scheme) {
  std::mt19937 random(17);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Points testPoints(2000, 3);
  for (Eigen::Index p = 0; p < testPoints.rows();) {
    const Eigen::Vector3d X(uniform(random), uniform(random), uniform(random));
    if (X.norm() <= 1.0) testPoints.row(p++) = 1.5 * X.transpose();
  }
  std::vector<KelvinletRow> rows;
  for (double ratio : spacingOverEps) {
    LatticeSpec spec;
    const uint32_t cubes = static_cast<uint32_t>(std::lround(4.0 / ratio));
    spec.cubes = {cubes, cubes, cubes};
    spec.spacing = 4.0 / cubes;
    spec.origin = Eigen::Vector3d::Constant(-2.0);
    VolumeMesh mesh = tetLattice(spec);
    if (jittered) jitterLattice(mesh, spec, 0.15, 99);
    for (KelvinletBrush brush :
         {KelvinletBrush::Grab, KelvinletBrush::Twist, KelvinletBrush::Pinch}) {
      // Displacements are linear in the amplitude: scale the unit brush to max |u| = eps / 4.
      const RegularizedKelvinlet unit = makeBrush(brush, 1.0);
      double largest = 0.0;
      for (Eigen::Index p = 0; p < testPoints.rows(); ++p)
        largest = std::max(largest, unit.displacement(testPoints.row(p).transpose()).norm());
      const RegularizedKelvinlet kelvinlet = makeBrush(brush, 0.25 / largest);
      KelvinletRow row;
      row.brush = brush;
      row.spacingOverEps = ratio;
      row.jittered = jittered;
      row.errors = measureInterpolationErrors(
          mesh, testPoints, [&](const Eigen::Vector3d& X) { return kelvinlet.map(X); }, scheme);
      row.rmsRatio = row.errors.rms[0] / row.errors.rms[2];
      row.maxRatio = row.errors.max[0] / row.errors.max[2];
      rows.push_back(row);
    }
  }
  return rows;
}

double logLogSlope(std::span<const double> x, std::span<const double> y) {
  const size_t n = std::min(x.size(), y.size());
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (size_t i = 0; i < n; ++i) {
    const double lx = std::log(x[i]), ly = std::log(y[i]);
    sx += lx, sy += ly, sxx += lx * lx, sxy += lx * ly;
  }
  const double count = static_cast<double>(n);
  return (count * sxy - sx * sy) / (count * sxx - sx * sx);
}

}  // namespace sculpt
