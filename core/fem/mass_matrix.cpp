#include "fem/mass_matrix.h"

#include <Eigen/Core>
#include <algorithm>

#include "fem/quadrature.h"
#include "fem/trilinear_shape.h"
#include "subdiv/tricubic_patch.h"

namespace sculpt {
namespace {

// Shape function values at the Gauss points of each element kind: N(q, a).
Eigen::MatrixXd tricubicShapeTable() {
  const QuadratureRule rule = gaussLegendre(4);
  double B[4][4];
  for (int i = 0; i < 4; ++i) cubicBSplineBasis(rule.points[i], B[i]);
  Eigen::MatrixXd N(kTricubicGaussPoints, kTricubicNodes);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      for (int k = 0; k < 4; ++k)
        for (int a = 0; a < 4; ++a)
          for (int b = 0; b < 4; ++b)
            for (int g = 0; g < 4; ++g)
              N(i * 16 + j * 4 + k, a * 16 + b * 4 + g) = B[i][a] * B[j][b] * B[k][g];
  return N;
}

Eigen::MatrixXd linearShapeTable(bool pyramid) {
  const QuadratureRule rule2 = gaussLegendre(2);
  const QuadratureRule ruleW = pyramid ? collapsedPyramidRule() : rule2;
  Eigen::MatrixXd N(kLinearGaussPoints, kLinearNodes);
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j)
      for (int k = 0; k < 2; ++k) {
        double values[8], gradients[8][3];
        trilinearShape({rule2.points[i], rule2.points[j], ruleW.points[k]}, values, gradients);
        for (int a = 0; a < 8; ++a) N(i * 4 + j * 2 + k, a) = values[a];
      }
  return N;
}

}  // namespace

SparseMatrix assembleNodeMatrix(const FemMesh& mesh, MassField field) {
  const Eigen::MatrixXd tricubicN = tricubicShapeTable();
  const Eigen::MatrixXd hexN = linearShapeTable(false);
  const Eigen::MatrixXd pyramidN = linearShapeTable(true);

  // Element matrices N^T diag(field * V) N, scattered as triplets per element (the duplicates of
  // repeated pyramid apices and shared nodes are summed by setFromTriplets).
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(size_t(mesh.numTricubic()) * 64 * 64 + size_t(mesh.numLinear()) * 64);
  Eigen::VectorXd weights;
  for (uint32_t e = 0; e < mesh.numElements(); ++e) {
    const uint32_t g0 = mesh.gaussBegin(e), count = mesh.gaussCount(e);
    weights.resize(count);
    for (uint32_t q = 0; q < count; ++q) {
      const Material& m = mesh.gaussMaterial[g0 + q];
      weights[q] = (field == MassField::Density ? m.density : m.damping) * mesh.gaussVolume[g0 + q];
    }
    if (weights.isZero(0.0)) continue;
    const Eigen::MatrixXd& N = e < mesh.numTricubic()
                                   ? tricubicN
                                   : (mesh.elementType[e] == ElementType::Pyramid ? pyramidN : hexN);
    const Eigen::MatrixXd Me = N.transpose() * weights.asDiagonal() * N;
    const uint32_t* ids = e < mesh.numTricubic()
                              ? mesh.tricubicNodes[e].data()
                              : mesh.linearNodes[e - mesh.numTricubic()].data();
    for (Eigen::Index a = 0; a < Me.rows(); ++a)
      for (Eigen::Index b = 0; b < Me.cols(); ++b)
        triplets.emplace_back(int(ids[a]), int(ids[b]), Me(a, b));
  }
  SparseMatrix M(mesh.numNodes(), mesh.numNodes());
  M.setFromTriplets(triplets.begin(), triplets.end());
  return M;
}

SparseMatrix stencilMatrix(const StencilTable& stencils) {
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(stencils.numEntries());
  for (uint32_t r = 0; r < stencils.numRows(); ++r)
    for (uint32_t k = stencils.offsets()[r]; k < stencils.offsets()[r + 1]; ++k)
      triplets.emplace_back(int(r), int(stencils.indices()[k]), stencils.weights()[k]);
  SparseMatrix A(stencils.numRows(), stencils.numColumns());
  A.setFromTriplets(triplets.begin(), triplets.end());
  return A;
}

SparseMatrix reduceToControlPoints(const SparseMatrix& A, const SparseMatrix& nodeMatrix) {
  SparseMatrix MA = nodeMatrix * A;
  SparseMatrix reduced = SparseMatrix(A.transpose()) * MA;
  reduced.prune(0.0);
  return reduced;
}

}  // namespace sculpt
