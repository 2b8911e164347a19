#include "fem/mass_matrix.h"

#include <Eigen/Core>
#include <algorithm>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "fem/node_slots.h"
#include "fem/quadrature.h"
#include "fem/trilinear_shape.h"
#include "subdiv/tricubic_patch.h"
#include "util/dense_accumulator.h"
#include "util/parallel_for.h"
#include "util/reserve_from_mean.h"

namespace sculpt {
namespace {

// Columns of the tricubic element matrix sum_q w_q N_a(q) N_b(q) by sum factorisation: with
// nodes and Gauss points both 4x4x4 tensor grids, N_(a1 a2 a3)(q1 q2 q3) = B_a1(q1) B_a2(q2)
// B_a3(q3), so the sum is taken one axis at a time, four rows a3 at once (192 four-wide
// multiply-adds per column instead of 64 x 64).
class TricubicMassColumns {
 public:
  TricubicMassColumns() {
    const QuadratureRule rule = gaussLegendre(4);
    for (int q = 0; q < 4; ++q) {
      double B[4];
      cubicBSplineBasis(rule.points[q], B);
      for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b) pair_[a * 4 + b][q] = B[a] * B[b];
    }
    for (int b = 0; b < 4; ++b)
      for (int q = 0; q < 4; ++q)
        pairRows_[b][q] = V4(pair_[b][q], pair_[4 + b][q], pair_[8 + b][q], pair_[12 + b][q]);
  }

  // Column b = b1*16 + b2*4 + b3 of the element matrix, Me(a, b) for a = a1*16 + a2*4 + a3, from
  // the weights w[q1*16 + q2*4 + q3].
  void column(const double* w, int b, double* out) const {
    const int b1 = b / 16, b2 = (b / 4) % 4, b3 = b % 4;
    V4 t1[4][4];  // [q1][q2], lanes a3
    for (int q1 = 0; q1 < 4; ++q1)
      for (int q2 = 0; q2 < 4; ++q2) {
        const double* wq = w + q1 * 16 + q2 * 4;
        t1[q1][q2] = wq[0] * pairRows_[b3][0] + wq[1] * pairRows_[b3][1] +
                     wq[2] * pairRows_[b3][2] + wq[3] * pairRows_[b3][3];
      }
    V4 t2[4][4];  // [q1][a2]
    for (int q1 = 0; q1 < 4; ++q1)
      for (int a2 = 0; a2 < 4; ++a2) {
        const double* p = pair_[a2 * 4 + b2];
        t2[q1][a2] = p[0] * t1[q1][0] + p[1] * t1[q1][1] + p[2] * t1[q1][2] + p[3] * t1[q1][3];
      }
    for (int a1 = 0; a1 < 4; ++a1) {
      const double* p = pair_[a1 * 4 + b1];
      for (int a2 = 0; a2 < 4; ++a2)
        Eigen::Map<V4>(out + a1 * 16 + a2 * 4) =
            p[0] * t2[0][a2] + p[1] * t2[1][a2] + p[2] * t2[2][a2] + p[3] * t2[3][a2];
    }
  }

 private:
  using V4 = Eigen::Array4d;
  double pair_[16][4];   // [a b][q]: B_a(q) B_b(q) of one axis
  V4 pairRows_[4][4];    // [b][q]: pair_[a*4 + b][q] for a = 0..3
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

// A sparse matrix column by column, each column's rows in no particular order.
struct Columns {
  std::vector<int64_t> begin{0};
  std::vector<int> rows;
  std::vector<double> values;
};

// Columns made in contiguous chunks, one per worker, and kept as made: part k holds columns
// [first[k], first[k + 1]). Merging the parts into one copy doubled a node matrix's memory
// (block10 at K = 1: 38 MB more, touched for the first time: docs/memory.md).
struct ColumnChunks {
  std::vector<Columns> parts;
  std::vector<uint32_t> first{0};

  uint32_t numColumns() const { return first.back(); }
  size_t numEntries() const {
    size_t entries = 0;
    for (const Columns& part : parts) entries += part.rows.size();
    return entries;
  }
  // f(row, value) for the entries of column j.
  template <class F>
  void forColumn(uint32_t j, const F& f) const {
    const size_t k = size_t(std::upper_bound(first.begin(), first.end(), j) - first.begin()) - 1;
    const Columns& part = parts[k];
    const size_t local = j - first[k];
    for (int64_t e = part.begin[local]; e < part.begin[local + 1]; ++e)
      f(uint32_t(part.rows[size_t(e)]), part.values[size_t(e)]);
  }
};

using Accumulator = DenseAccumulator<double>;

// Appends the accumulated column to `out` (rows sorted when asked, exact zeros kept when asked).
void flush(Accumulator& column, Columns& out, bool sorted, bool keepZeros) {
  if (sorted) column.sortTouched();
  column.drain([&](uint32_t row, double value) {
    if (value == 0.0 && !keepZeros) return;
    out.rows.push_back(int(row));
    out.values.push_back(value);
  });
  out.begin.push_back(int64_t(out.rows.size()));
}

// Columns [0, n) computed in parallel chunks by column(j, accumulator). Chunk k is worker k's
// and the chunks follow each other in k (parallel_for.h), so the parts are in column order.
template <class ColumnBody>
ColumnChunks columnsInParallel(uint32_t n, size_t rows, bool sorted, bool keepZeros,
                               const ColumnBody& column) {
  std::vector<Columns> parts(workerCount());
  parallelChunks(n, 64, [&](uint32_t begin, uint32_t end, unsigned worker) {
    Accumulator accumulator(rows, 0.0);
    Columns& part = parts[worker];
    part.begin.reserve(size_t(end - begin) + 1);
    for (uint32_t j = begin; j < end; ++j) {
      column(j, accumulator, worker);
      flush(accumulator, part, sorted, keepZeros);
      reserveFromMean(j + 1 - begin, end - begin, part.rows, part.values);
    }
  });
  ColumnChunks chunks;
  for (Columns& part : parts) {
    if (part.begin.size() == 1) continue;  // a worker without a chunk
    chunks.first.push_back(chunks.first.back() + uint32_t(part.begin.size() - 1));
    chunks.parts.push_back(std::move(part));
  }
  return chunks;
}

// The node matrix of the Gauss-point weights `weights` (a field times the Gauss volume) over the
// elements marked in `included` (all when empty), each node's column gathered from the elements
// around the node: a dense accumulator per column instead of a search for every element entry in
// the pattern.
ColumnChunks nodeMatrixColumns(const FemMesh& mesh, std::span<const double> weights,
                               std::span<const uint8_t> included, bool sorted) {
  const TricubicMassColumns tricubic;
  const Eigen::MatrixXd hexN = linearShapeTable(false);
  const Eigen::MatrixXd pyramidN = linearShapeTable(true);
  const uint32_t numElements = mesh.numElements(), numNodes = mesh.numNodes();
  // An element left out, or where the weights vanish, adds nothing.
  std::vector<uint8_t> empty(numElements, 1);
  for (uint32_t e = 0; e < numElements; ++e) {
    if (!included.empty() && !included[e]) continue;
    for (uint32_t q = mesh.gaussBegin(e); q < mesh.gaussBegin(e) + mesh.gaussCount(e); ++q)
      if (weights[q] != 0.0) empty[e] = 0;
  }
  // A node repeated in an element (a pyramid's apex) has a slot for each of its places there,
  // and the element's columns for both add up.
  const NodeSlots around = nodeSlots(mesh, empty);
  const auto nodeColumn = [&](uint32_t j, Accumulator& acc, unsigned) {
    alignas(32) double column[kTricubicNodes];
    for (uint32_t s = around.begin[j]; s < around.begin[j + 1]; ++s) {
      const auto [e, b] = around.slots[s];
      const double* w = weights.data() + mesh.gaussBegin(e);
      const std::span<const uint32_t> ids = mesh.elementNodes(e);
      if (e < mesh.numTricubic()) {
        tricubic.column(w, int(b), column);
      } else {
        const Eigen::MatrixXd& N = mesh.elementType[e] == ElementType::Pyramid ? pyramidN : hexN;
        for (int a = 0; a < kLinearNodes; ++a) {
          column[a] = 0.0;
          for (int q = 0; q < kLinearGaussPoints; ++q) column[a] += N(q, a) * w[q] * N(q, b);
        }
      }
      for (size_t a = 0; a < ids.size(); ++a) acc.add(ids[a], column[a]);
    }
  };
  return columnsInParallel(numNodes, numNodes, sorted, true, nodeColumn);
}

SparseMatrix toSparse(const ColumnChunks& columns, Eigen::Index rows) {
  SparseMatrix matrix(rows, Eigen::Index(columns.numColumns()));
  matrix.resizeNonZeros(Eigen::Index(columns.numEntries()));
  Eigen::Index j = 0, entries = 0;
  for (const Columns& part : columns.parts) {
    for (size_t k = 0; k + 1 < part.begin.size(); ++k)
      matrix.outerIndexPtr()[j++] = int(entries + part.begin[k]);
    std::copy(part.rows.begin(), part.rows.end(), matrix.innerIndexPtr() + entries);
    std::copy(part.values.begin(), part.values.end(), matrix.valuePtr() + entries);
    entries += Eigen::Index(part.rows.size());
  }
  matrix.outerIndexPtr()[j] = int(entries);
  return matrix;
}

}  // namespace

std::vector<double> fieldWeights(const FemMesh& mesh, MassField field) {
  std::vector<double> weights(mesh.numGaussPoints());
  for (uint32_t q = 0; q < mesh.numGaussPoints(); ++q) {
    const Material& m = mesh.gaussMaterial[q];
    weights[q] = (field == MassField::Density ? m.density : m.damping) * mesh.gaussVolume[q];
  }
  return weights;
}

SparseMatrix assembleNodeMatrix(const FemMesh& mesh, MassField field) {
  return toSparse(nodeMatrixColumns(mesh, fieldWeights(mesh, field), {}, true), mesh.numNodes());
}

SparseMatrix reducedNodeMatrix(const FemMesh& mesh, const SparseMatrix& A, MassField field) {
  return reducedWeightedMatrix(mesh, A, fieldWeights(mesh, field));
}

SparseMatrix reducedWeightedMatrix(const FemMesh& mesh, const SparseMatrix& A,
                                   std::span<const double> weights,
                                   std::span<const uint8_t> included) {
  // Column c of A^T M A is A^T (M a_c), a_c column c of A: M's columns for the nodes of a_c
  // summed into one dense accumulator over the nodes, then those nodes' rows of A into one over
  // the control points. M's columns need no order.
  const ColumnChunks M = nodeMatrixColumns(mesh, weights, included, false);
  const SparseMatrix At = A.transpose();  // column n: the control points of node n's row of A
  const uint32_t numControl = uint32_t(A.cols());
  std::vector<Accumulator> nodeSums(workerCount(), Accumulator(size_t(A.rows()), 0.0));
  const ColumnChunks reduced = columnsInParallel(
      numControl, numControl, true, false, [&](uint32_t c, Accumulator& sum, unsigned worker) {
        Accumulator& nodes = nodeSums[worker];
        for (SparseMatrix::InnerIterator a(A, Eigen::Index(c)); a; ++a)
          M.forColumn(uint32_t(a.row()), [&, weight = a.value()](uint32_t node, double value) {
            nodes.add(node, weight * value);
          });
        nodes.drain([&](uint32_t node, double value) {
          for (SparseMatrix::InnerIterator r(At, Eigen::Index(node)); r; ++r)
            sum.add(uint32_t(r.row()), r.value() * value);
        });
      });
  return toSparse(reduced, A.cols());
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

}  // namespace sculpt
