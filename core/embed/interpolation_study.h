#pragma once
// The accuracy experiments of James 2020 (its Fig. 10 and the Kelvinlet comparison), computed
// with this program's own deformer: an analytic deformation is sampled at the nodes of a mesh,
// interpolated to test points by each method, and compared with the analytic value there.

#include <array>
#include <functional>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "embed/gradient_scheme.h"
#include "embed/interpolation_method.h"
#include "mesh/cell_complex.h"
#include "mesh/volume_mesh.h"

namespace sculpt {

using AnalyticDeformation = std::function<Eigen::Vector3d(const Eigen::Vector3d&)>;

inline constexpr std::array<InterpolationMethod, 4> kAllMethods = {
    InterpolationMethod::Linear, InterpolationMethod::Vertex, InterpolationMethod::Phong,
    InterpolationMethod::Attribute};

/// Errors |f_method(X) - phi(X)| over the test points, per method (kAllMethods order).
struct MethodErrors {
  std::array<double, 4> max{};
  std::array<double, 4> rms{};
};

/// Deforms `mesh` by phi at its nodes and measures each method at `testPoints` (double precision,
/// attribute radius 1.5 x mean edge length) with node gradients by `scheme` (eps regularises
/// the averaging weights).
MethodErrors measureInterpolationErrors(const VolumeMesh& mesh, const Points& testPoints,
                                        const AnalyticDeformation& phi,
                                        GradientScheme scheme = kDefaultGradientScheme,
                                        double eps = 1.0);

/// The smooth test deformation of the convergence experiment: a bend of radius 1.5 about the
/// y axis followed by a twist about z of 0.8 rad per unit length.
Eigen::Vector3d bendAndTwist(const Eigen::Vector3d& X);

enum class StudyCells { Tetrahedra, Hexahedra };
enum class StudyPlacement {
  Interior,  ///< the test cube has three layers of cubes on every side
  Surface,   ///< the test cube is in the top layer: nothing above it
  Corner,    ///< the test cube is at a corner of the lattice: nothing above it, in +x or in +y
};

struct ConvergenceRow {
  double spacing = 0.0;     ///< cube edge h
  double meanEdge = 0.0;    ///< mean cell edge length of the mesh
  MethodErrors errors;
};

struct ConvergenceSeries {
  StudyCells cells = StudyCells::Tetrahedra;
  StudyPlacement placement = StudyPlacement::Interior;
  GradientScheme scheme = kDefaultGradientScheme;
  std::vector<ConvergenceRow> rows;
  std::array<double, 4> slopes{};  ///< least-squares log-log slopes of max error vs mean edge
};

/// The convergence experiment: a lattice of cubes of edge h (split into 6 tetrahedra each, or
/// hexahedra) translated so that a fixed test cube [P0, P0 + h]^3 keeps 25 test points at the
/// same local positions for every h; bendAndTwist as the deformation.
/// `eps` is the regulariser of the averaged node gradients (default 1).
ConvergenceSeries runConvergenceStudy(StudyCells cells, StudyPlacement placement,
                                      std::span<const double> spacings,
                                      GradientScheme scheme = kDefaultGradientScheme,
                                      double eps = 1.0);

enum class KelvinletBrush { Grab, Twist, Pinch };

struct KelvinletRow {
  KelvinletBrush brush = KelvinletBrush::Grab;
  double spacingOverEps = 0.0;  ///< h / eps
  bool jittered = false;
  MethodErrors errors;
  double rmsRatio = 0.0;  ///< linear / phong, l2 (rms) vertex error
  double maxRatio = 0.0;  ///< linear / phong, largest vertex error
};

/// The Kelvinlet comparison: a regularized Kelvinlet (eps = 1, nu = 0.45, scaled to a largest
/// displacement of eps / 4 in the test ball) deforms a tet lattice of [-2, 2]^3 with cube edge
/// h = ratio * eps (regular, or with interior nodes jittered by 15% of h) and 2000 test points
/// in the ball of radius 1.5 eps; the analytic map is the truth at both.
std::vector<KelvinletRow> runKelvinletStudy(std::span<const double> spacingOverEps,
                                            bool jittered,
                                            GradientScheme scheme = kDefaultGradientScheme);

const char* brushName(KelvinletBrush brush);

/// Least-squares slope of log(y) against log(x).
double logLogSlope(std::span<const double> x, std::span<const double> y);

}  // namespace sculpt
