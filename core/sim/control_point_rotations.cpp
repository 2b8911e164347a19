#include "sim/control_point_rotations.h"

#include <Eigen/LU>

#include "fem/polar_rotation.h"
#include "sim/linear_stiffness.h"
#include "util/parallel_for.h"

namespace sculpt {

ControlPointRotations::ControlPointRotations(const FemModel& model)
    : rotations_(model.numControlPoints(), Eigen::Matrix3d::Identity()) {
  const FemMesh& mesh = model.mesh();
  const RowSparseMatrix rowsOfA = model.stencilMatrix();
  std::vector<Eigen::Triplet<double>> entries;
  for (uint32_t e = 0; e < mesh.numElements(); ++e)
    for (uint32_t node : elementCorners(mesh, e))
      for (RowSparseMatrix::InnerIterator it(rowsOfA, node); it; ++it)
        entries.emplace_back(int(it.col()), int(e), it.value());
  weights_.resize(rowsOfA.cols(), Eigen::Index(mesh.numElements()));
  weights_.setFromTriplets(entries.begin(), entries.end());  // sums the repeated entries
  // Normalised per point, so that the mean of agreeing rotations is that rotation.
  for (Eigen::Index i = 0; i < weights_.rows(); ++i) {
    const double total = weights_.row(i).sum();
    if (total > 0) weights_.row(i) /= total;
  }
}

void ControlPointRotations::update(const std::vector<Eigen::Matrix3d>& elementRotations) {
  parallelChunks(uint32_t(weights_.rows()), 256, [&](uint32_t begin, uint32_t end, unsigned) {
    for (uint32_t i = begin; i < end; ++i) {
      Eigen::Matrix3d sum = Eigen::Matrix3d::Zero();
      for (RowSparseMatrix::InnerIterator it(weights_, i); it; ++it)
        sum += it.value() * elementRotations[size_t(it.col())];
      // Warm-started from the last one: a step turns a point only a little.
      if (sum.determinant() > 0) rotations_[i] = polarRotation(sum, rotations_[i]);
    }
  });
}

}  // namespace sculpt
