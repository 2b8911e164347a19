#include "embed/cell_interpolant.h"

#include <Eigen/Geometry>
#include <Eigen/LU>

#include "embed/cell_coordinates.h"
#include "fem/trilinear_shape.h"

namespace sculpt {
namespace {

/// Weights and their local derivatives (columns d/dxi) at xi. Returns the node count.
int weightsAndDerivatives(bool tetrahedron, const Eigen::Vector3d& xi, double weights[8],
                          Eigen::Vector3d derivatives[8]) {
  if (tetrahedron) {
    cellNodeWeights(true, xi, weights);
    derivatives[0] = Eigen::Vector3d::Constant(-1.0);
    for (int a = 1; a < 4; ++a) derivatives[a] = Eigen::Vector3d::Unit(a - 1);
    return 4;
  }
  double dN[8][3];
  trilinearShape(xi, weights, dN);
  for (int a = 0; a < 8; ++a) derivatives[a] = Eigen::Vector3d(dN[a][0], dN[a][1], dN[a][2]);
  return 8;
}

}  // namespace

InterpolantValue evaluateCellInterpolant(const VolumeMesh& rest, const NodeFrame& frame,
                                         uint32_t cell, const Eigen::Vector3d& xi, double alpha) {
  const auto nodes = rest.cells.row(cell);
  double beta[8];
  Eigen::Vector3d dbeta[8];
  const int n = weightsAndDerivatives(nodes.size() == 4, xi, beta, dbeta);
  Eigen::Vector3d X = Eigen::Vector3d::Zero();
  Eigen::Matrix3d dXdxi = Eigen::Matrix3d::Zero();
  for (int a = 0; a < n; ++a) {
    const Eigen::Vector3d Xa = rest.positions.row(nodes[a]).transpose();
    X += beta[a] * Xa;
    dXdxi += Xa * dbeta[a].transpose();
  }
  InterpolantValue value;
  value.position.setZero();
  Eigen::Matrix3d dfdxi = Eigen::Matrix3d::Zero();
  Eigen::Matrix3d blendedGradient = Eigen::Matrix3d::Zero();
  for (int a = 0; a < n; ++a) {
    Eigen::Vector3d model = frame.positions->row(nodes[a]).transpose();
    if (alpha != 0.0) {
      const Eigen::Matrix3d& Fa = (*frame.gradients)[nodes[a]];
      model += alpha * Fa * (X - rest.positions.row(nodes[a]).transpose());
      blendedGradient += beta[a] * alpha * Fa;
    }
    value.position += beta[a] * model;
    dfdxi += model * dbeta[a].transpose();
  }
  // d f/d X = (d f/d xi) (d X/d xi)^-1 + sum beta_a alpha F_a (the models' own gradients).
  value.gradient = dfdxi * dXdxi.inverse() + blendedGradient;
  return value;
}

Eigen::Vector3d interpolatePosition(const VolumeMesh& rest, const NodeFrame& frame, uint32_t cell,
                                    const Eigen::Vector3d& xi, double alpha) {
  const auto nodes = rest.cells.row(cell);
  double beta[8];
  const int n = cellNodeWeights(nodes.size() == 4, xi, beta);
  Eigen::Vector3d X = Eigen::Vector3d::Zero();
  for (int a = 0; a < n; ++a) X += beta[a] * rest.positions.row(nodes[a]).transpose();
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  for (int a = 0; a < n; ++a) {
    Eigen::Vector3d model = frame.positions->row(nodes[a]).transpose();
    if (alpha != 0.0)
      model += alpha * (*frame.gradients)[nodes[a]] *
               (X - rest.positions.row(nodes[a]).transpose());
    position += beta[a] * model;
  }
  return position;
}

Eigen::Vector3d deformNormal(const Eigen::Matrix3d& gradient, const Eigen::Vector3d& restNormal) {
  // Cofactor matrix columns: cross products of the gradient's columns (no inverse needed, and
  // the orientation is kept for any non-degenerate gradient).
  Eigen::Matrix3d cofactor;
  cofactor.col(0) = gradient.col(1).cross(gradient.col(2));
  cofactor.col(1) = gradient.col(2).cross(gradient.col(0));
  cofactor.col(2) = gradient.col(0).cross(gradient.col(1));
  const Eigen::Vector3d normal = cofactor * restNormal;
  const double length = normal.norm();
  if (!(length > 1e-300) || !normal.allFinite()) return restNormal;
  return normal / length;
}

}  // namespace sculpt
