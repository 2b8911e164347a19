#include "fem/barrier_stress.h"

namespace sculpt {
namespace {

// The groups of `lanes` points of one element's record, with the kernels' own determinant and
// cofactor.
template <int kLanes>
void recordCurvatureGroups(double* record, int points, const double* volumeLambda,
                           const double* volumeMu, const InversionBarrier& barrier) {
  using V = Eigen::Array<double, kLanes, 1>;
  for (int group = 0; group < points / kLanes; ++group) {
    double* values = record + size_t(group) * 9 * kLanes;
    V A[3][3], cof[3][3];
    for (int rc = 0; rc < 9; ++rc) A[rc / 3][rc % 3] = Eigen::Map<const V>(values + rc * kLanes);
    const V t = (barrier.threshold - barrier_detail::determinant(A)).max(0.0);
    const V c = barrier_detail::coefficient<V>(Eigen::Map<const V>(volumeLambda + group * kLanes),
                                               Eigen::Map<const V>(volumeMu + group * kLanes),
                                               barrier);
    const V root = (6.0 * c * t).sqrt();  // psi = c t^3: psi'' = 6 c t
    barrier_detail::cofactor(A, cof);
    for (int rc = 0; rc < 9; ++rc)
      Eigen::Map<V>(values + rc * kLanes) = root * cof[rc / 3][rc % 3];
  }
}

}  // namespace

void recordCurvature(double* record, int points, int lanes, const double* volumeLambda,
                     const double* volumeMu, const InversionBarrier& barrier) {
  if (lanes == 4)
    recordCurvatureGroups<4>(record, points, volumeLambda, volumeMu, barrier);
  else
    recordCurvatureGroups<8>(record, points, volumeLambda, volumeMu, barrier);
}

}  // namespace sculpt
