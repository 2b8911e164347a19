#include "embed/cell_coordinates.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include <Eigen/LU>

#include "fem/trilinear_shape.h"

namespace sculpt {

int cellNodeWeights(bool tetrahedron, const Eigen::Vector3d& xi, double weights[8]) {
  if (tetrahedron) {
    weights[0] = 1.0 - xi[0] - xi[1] - xi[2];
    weights[1] = xi[0];
    weights[2] = xi[1];
    weights[3] = xi[2];
    return 4;
  }
  for (int a = 0; a < 8; ++a) {
    double w = 1.0;
    for (int d = 0; d < 3; ++d) w *= kTrilinearCorner[a][d] ? xi[d] : 1.0 - xi[d];
    weights[a] = w;
  }
  return 8;
}

Eigen::Vector3d cellPoint(const VolumeMesh& mesh, uint32_t cell, const Eigen::Vector3d& xi) {
  double weights[8];
  const auto nodes = mesh.cells.row(cell);
  const int n = cellNodeWeights(nodes.size() == 4, xi, weights);
  Eigen::Vector3d X = Eigen::Vector3d::Zero();
  for (int a = 0; a < n; ++a) X += weights[a] * mesh.positions.row(nodes[a]).transpose();
  return X;
}

Eigen::Matrix3d cellJacobian(const VolumeMesh& mesh, uint32_t cell, const Eigen::Vector3d& xi) {
  const auto nodes = mesh.cells.row(cell);
  Eigen::Matrix3d J;
  if (nodes.size() == 4) {
    const Eigen::Vector3d X0 = mesh.positions.row(nodes[0]).transpose();
    for (int d = 0; d < 3; ++d) J.col(d) = mesh.positions.row(nodes[d + 1]).transpose() - X0;
    return J;
  }
  double N[8], dN[8][3];
  trilinearShape(xi, N, dN);
  J.setZero();
  for (int a = 0; a < 8; ++a)
    for (int d = 0; d < 3; ++d) J.col(d) += dN[a][d] * mesh.positions.row(nodes[a]).transpose();
  return J;
}

double localExcursion(bool tetrahedron, const Eigen::Vector3d& xi) {
  if (tetrahedron) {
    const double b0 = 1.0 - xi.sum();
    return std::max(0.0, -std::min({b0, xi[0], xi[1], xi[2]}));
  }
  double excursion = 0.0;
  for (int d = 0; d < 3; ++d) excursion = std::max({excursion, -xi[d], xi[d] - 1.0});
  return excursion;
}

Eigen::Vector3d cellLocalCoordinates(const VolumeMesh& mesh, uint32_t cell,
                                     const Eigen::Vector3d& X) {
  const bool tetrahedron = mesh.isTetrahedron(cell);
  if (tetrahedron) {
    const Eigen::Vector3d X0 = mesh.positions.row(mesh.cells.row(cell)[0]).transpose();
    return cellJacobian(mesh, cell, X0).partialPivLu().solve(X - X0);
  }
  // Newton on X(xi) = X. Steps are damped so that the residual never grows: far outside a
  // distorted cell the trilinear map can fold, and the iteration must still stop with finite
  // coordinates. Started from the centre; when that stalls (points well outside), restarted from
  // the corners and from farther out along the stalled direction, keeping the best.
  const double scale = cellJacobian(mesh, cell, cellCentreCoordinates(false)).norm();
  const auto newton = [&](Eigen::Vector3d xi) {
    Eigen::Vector3d residual = cellPoint(mesh, cell, xi) - X;
    for (int iteration = 0; iteration < 50 && residual.norm() > 1e-14 * scale; ++iteration) {
      const Eigen::FullPivLU<Eigen::Matrix3d> lu(cellJacobian(mesh, cell, xi));
      if (!lu.isInvertible()) break;
      const Eigen::Vector3d step = lu.solve(residual);
      if (!step.allFinite()) break;
      double damping = 1.0;
      bool improved = false;
      for (int halving = 0; halving < 30; ++halving, damping *= 0.5) {
        const Eigen::Vector3d trial = xi - damping * step;
        const Eigen::Vector3d trialResidual = cellPoint(mesh, cell, trial) - X;
        if (trialResidual.norm() < residual.norm()) {
          xi = trial;
          residual = trialResidual;
          improved = true;
          break;
        }
      }
      if (!improved) break;
    }
    return std::pair{xi, residual.norm()};
  };
  auto [best, bestResidual] = newton(cellCentreCoordinates(false));
  if (bestResidual <= 1e-10 * scale) return best;
  const Eigen::Vector3d stalled = best;
  for (int start = 0; start < 10 && bestResidual > 1e-10 * scale; ++start) {
    const Eigen::Vector3d xi0 =
        start < 8 ? Eigen::Vector3d(kTrilinearCorner[start][0], kTrilinearCorner[start][1],
                                    kTrilinearCorner[start][2])
                  : Eigen::Vector3d::Constant(0.5) +
                        (start - 6) * (stalled - Eigen::Vector3d::Constant(0.5));
    const auto [xi, residual] = newton(xi0);
    if (residual < bestResidual) best = xi, bestResidual = residual;
  }
  return best;
}

Eigen::Vector3d cellCentroid(const VolumeMesh& mesh, uint32_t cell) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  const auto nodes = mesh.cells.row(cell);
  for (uint32_t node : nodes) sum += mesh.positions.row(node).transpose();
  return sum / static_cast<double>(nodes.size());
}

}  // namespace sculpt
