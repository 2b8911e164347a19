#include "embed/gradient_weights.h"

#include <cmath>
#include <stdexcept>

#include <Eigen/Cholesky>

#include "embed/cell_coordinates.h"

namespace sculpt {

CompressedRows<CellWeight> cellToNodeWeights(const VolumeMesh& mesh, double eps) {
  if (!(eps >= 0.0) || !std::isfinite(eps))
    throw std::invalid_argument("the regulariser eps must be a finite number >= 0");
  const CompressedRows<uint32_t> nodeCells = invertIncidence(mesh.cells, mesh.numNodes());
  std::vector<Eigen::Vector3d> centroids(mesh.numCells());
  for (uint32_t c = 0; c < mesh.numCells(); ++c) centroids[c] = cellCentroid(mesh, c);

  CompressedRows<CellWeight> weights;
  weights.offsets.reserve(mesh.numNodes() + 1);
  weights.values.reserve(nodeCells.values.size());
  std::vector<Eigen::Vector3d> directions;
  std::vector<double> lengths;
  for (uint32_t node = 0; node < mesh.numNodes(); ++node) {
    const auto cells = nodeCells.row(node);
    directions.clear();
    lengths.clear();
    Eigen::Matrix3d A = eps * Eigen::Matrix3d::Identity();
    Eigen::Vector3d b = Eigen::Vector3d::Zero();
    for (uint32_t cell : cells) {
      const Eigen::Vector3d r = centroids[cell] - mesh.positions.row(node).transpose();
      const double length = r.norm();
      const Eigen::Vector3d rhat = r / length;
      directions.push_back(rhat);
      lengths.push_back(length);
      A += rhat * rhat.transpose();
      b -= rhat;
    }
    // With eps = 0 and neighbours on one side only A is singular: LDLT still returns a finite
    // least-norm-like answer, and the weights below are finite because every w_k is divided by a
    // positive length.
    const Eigen::Vector3d lambda =
        cells.empty() ? Eigen::Vector3d::Zero().eval() : Eigen::Vector3d(A.ldlt().solve(b));
    double sum = 0.0;
    const size_t first = weights.values.size();
    for (size_t k = 0; k < cells.size(); ++k) {
      const double w = (1.0 + lambda.dot(directions[k])) / lengths[k];
      weights.values.push_back({cells[k], w});
      sum += w;
    }
    // A non-positive sum only happens for pathological fans with eps = 0; plain inverse-distance
    // weights are the robust answer there.
    if (!(std::abs(sum) > 1e-12) || !std::isfinite(sum)) {
      sum = 0.0;
      for (size_t k = 0; k < cells.size(); ++k) {
        weights.values[first + k].weight = 1.0 / lengths[k];
        sum += 1.0 / lengths[k];
      }
    }
    for (size_t k = first; k < weights.values.size(); ++k) weights.values[k].weight /= sum;
    weights.closeRow();
  }
  return weights;
}

}  // namespace sculpt
