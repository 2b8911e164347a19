#include "fem/mass_matrix.h"

#include <Eigen/Core>
#include <algorithm>
#include <cstdint>
#include <span>
#include <vector>

#include "fem/quadrature.h"
#include "fem/trilinear_shape.h"
#include "subdiv/tricubic_patch.h"

namespace sculpt {
namespace {

// The tricubic element matrix sum_q w_q N_a(q) N_b(q) by sum factorisation: with nodes and
// Gauss points both 4x4x4 tensor grids, N_(a1 a2 a3)(q1 q2 q3) = B_a1(q1) B_a2(q2) B_a3(q3), so the
// sum is taken one axis at a time (about 21 k multiply-adds instead of 64^3 = 262 k).
class TricubicMassKernel {
 public:
  TricubicMassKernel() {
    const QuadratureRule rule = gaussLegendre(4);
    for (int q = 0; q < 4; ++q) {
      double B[4];
      cubicBSplineBasis(rule.points[q], B);
      for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b) pair_[a * 4 + b][q] = B[a] * B[b];
    }
  }

  // Me(a, b) for node ids a = a1*16 + a2*4 + a3 from weights w[q1*16 + q2*4 + q3].
  void elementMatrix(const double* w, Eigen::MatrixXd& Me) const {
    double t1[16][4][4];  // [a1 b1][q2][q3]
    for (int p = 0; p < 16; ++p)
      for (int q2 = 0; q2 < 4; ++q2)
        for (int q3 = 0; q3 < 4; ++q3) {
          double sum = 0;
          for (int q1 = 0; q1 < 4; ++q1) sum += w[q1 * 16 + q2 * 4 + q3] * pair_[p][q1];
          t1[p][q2][q3] = sum;
        }
    double t2[16][16][4];  // [a1 b1][a2 b2][q3]
    for (int p = 0; p < 16; ++p)
      for (int r = 0; r < 16; ++r)
        for (int q3 = 0; q3 < 4; ++q3) {
          double sum = 0;
          for (int q2 = 0; q2 < 4; ++q2) sum += t1[p][q2][q3] * pair_[r][q2];
          t2[p][r][q3] = sum;
        }
    Me.resize(kTricubicNodes, kTricubicNodes);
    for (int a1 = 0; a1 < 4; ++a1)
      for (int b1 = 0; b1 < 4; ++b1)
        for (int a2 = 0; a2 < 4; ++a2)
          for (int b2 = 0; b2 < 4; ++b2) {
            const double* t = t2[a1 * 4 + b1][a2 * 4 + b2];
            for (int a3 = 0; a3 < 4; ++a3)
              for (int b3 = 0; b3 < 4; ++b3) {
                const double* p3 = pair_[a3 * 4 + b3];
                Me(a1 * 16 + a2 * 4 + a3, b1 * 16 + b2 * 4 + b3) =
                    t[0] * p3[0] + t[1] * p3[1] + t[2] * p3[2] + t[3] * p3[3];
              }
          }
  }

 private:
  double pair_[16][4];  // [a b][q]: B_a(q) B_b(q) of one axis
};

// Shape function values at the Gauss points of a linear element kind: N(q, a).
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
  const TricubicMassKernel tricubic;
  const Eigen::MatrixXd hexN = linearShapeTable(false);
  const Eigen::MatrixXd pyramidN = linearShapeTable(true);
  const uint32_t numElements = mesh.numElements();
  const auto elementNodes = [&](uint32_t e) -> std::span<const uint32_t> {
    if (e < mesh.numTricubic()) return mesh.tricubicNodes[e];
    return mesh.linearNodes[e - mesh.numTricubic()];
  };

  // The sparsity pattern first (node j couples with every node of every element around it), so
  // that element matrices are added in place: triplets would hold 4096 entries per tricubic
  // element (hundreds of MB for a few thousand elements) only to be sorted and summed.
  std::vector<uint32_t> elementsBegin(mesh.numNodes() + 1, 0), elementsOfNode;
  for (uint32_t e = 0; e < numElements; ++e)
    for (uint32_t j : elementNodes(e)) ++elementsBegin[j + 1];
  for (uint32_t j = 0; j < mesh.numNodes(); ++j) elementsBegin[j + 1] += elementsBegin[j];
  elementsOfNode.resize(elementsBegin.back());
  {
    std::vector<uint32_t> cursor(elementsBegin.begin(), elementsBegin.end() - 1);
    for (uint32_t e = 0; e < numElements; ++e)
      for (uint32_t j : elementNodes(e)) elementsOfNode[cursor[j]++] = e;
  }
  SparseMatrix M(mesh.numNodes(), mesh.numNodes());
  {
    // Column j: the distinct nodes of the elements around j (a marker array dedupes them, so only
    // the few hundred distinct rows of each column are sorted), written straight into the
    // compressed arrays (inserting entry by entry took as long as the element matrices).
    std::vector<uint32_t> marker(mesh.numNodes(), UINT32_MAX);
    std::vector<int> outerIndex(size_t(mesh.numNodes()) + 1, 0), innerIndex;
    for (uint32_t j = 0; j < mesh.numNodes(); ++j) {
      const size_t first = innerIndex.size();
      for (uint32_t k = elementsBegin[j]; k < elementsBegin[j + 1]; ++k)
        for (uint32_t i : elementNodes(elementsOfNode[k]))
          if (marker[i] != j) {
            marker[i] = j;
            innerIndex.push_back(static_cast<int>(i));
          }
      std::sort(innerIndex.begin() + std::ptrdiff_t(first), innerIndex.end());
      outerIndex[j + 1] = static_cast<int>(innerIndex.size());
    }
    M.resizeNonZeros(static_cast<Eigen::Index>(innerIndex.size()));
    std::copy(outerIndex.begin(), outerIndex.end(), M.outerIndexPtr());
    std::copy(innerIndex.begin(), innerIndex.end(), M.innerIndexPtr());
    std::fill(M.valuePtr(), M.valuePtr() + innerIndex.size(), 0.0);
  }
  const int* outer = M.outerIndexPtr();
  const int* inner = M.innerIndexPtr();
  double* values = M.valuePtr();
  // Where each column's diagonal entry is: the element matrices go into the lower triangle only
  // (half the walk along each column), and the upper one is its mirror image.
  std::vector<int> diagonal(mesh.numNodes());
  for (uint32_t j = 0; j < mesh.numNodes(); ++j)
    diagonal[j] = int(std::lower_bound(inner + outer[j], inner + outer[j + 1], int(j)) - inner);

  // Element matrices N^T diag(field * V) N, added in place (repeated nodes of pyramid apices
  // add up like any shared node).
  Eigen::VectorXd weights;
  Eigen::MatrixXd Me;
  std::vector<uint32_t> order;
  for (uint32_t e = 0; e < numElements; ++e) {
    const uint32_t g0 = mesh.gaussBegin(e), count = mesh.gaussCount(e);
    weights.resize(count);
    for (uint32_t q = 0; q < count; ++q) {
      const Material& m = mesh.gaussMaterial[g0 + q];
      weights[q] = (field == MassField::Density ? m.density : m.damping) * mesh.gaussVolume[g0 + q];
    }
    if (weights.isZero(0.0)) continue;
    if (e < mesh.numTricubic()) {
      tricubic.elementMatrix(weights.data(), Me);
    } else {
      const Eigen::MatrixXd& N = mesh.elementType[e] == ElementType::Pyramid ? pyramidN : hexN;
      Me.noalias() = N.transpose() * weights.asDiagonal() * N;
    }
    // The element's nodes in increasing id order, so that each column's entries are found by
    // one merge-like walk down the column from its diagonal instead of a search per entry.
    const std::span<const uint32_t> ids = elementNodes(e);
    order.resize(ids.size());
    for (size_t a = 0; a < ids.size(); ++a) order[a] = static_cast<uint32_t>(a);
    std::sort(order.begin(), order.end(), [&](uint32_t x, uint32_t y) { return ids[x] < ids[y]; });
    for (size_t ob = 0; ob < order.size(); ++ob) {
      const uint32_t b = order[ob];
      const int* at = inner + diagonal[ids[b]];
      for (size_t oa = ob; oa < order.size(); ++oa) {
        const uint32_t a = order[oa];
        while (*at < static_cast<int>(ids[a])) ++at;  // the pattern holds every element node
        // A node repeated in the element (a pyramid's apex) meets itself twice in the full
        // matrix, (a, b) and (b, a), on the diagonal.
        values[at - inner] += oa > ob && ids[a] == ids[b] ? 2.0 * Me(a, b) : Me(a, b);
      }
    }
  }
  // The upper triangle: column i's rows above its diagonal are, in order, the columns j < i
  // whose lower part holds row i.
  std::vector<int> upper(outer, outer + mesh.numNodes());
  for (uint32_t j = 0; j < mesh.numNodes(); ++j)
    for (int k = diagonal[j] + 1; k < outer[j + 1]; ++k) values[upper[size_t(inner[k])]++] = values[k];
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
