#include "sim/node_block_rows.h"

#include <utility>

#include "util/dense_accumulator.h"

namespace sculpt {

NodeBlockRows& mirrorUpperBlocks(SymmetricNodeBlocks& nodes) {
  // Row m's blocks below its diagonal are those of the rows n < m that reach m, in increasing n.
  NodeBlockRows& K = nodes.K;
  std::vector<uint32_t> next(K.begin.begin(), K.begin.end() - 1);
  for (uint32_t n = 0; n < K.numNodes(); ++n)
    for (uint32_t k = nodes.diagonal[n] + 1; k < K.begin[n + 1]; ++k)
      K.block[next[K.column[k]]++] = K.block[k].transpose();
  return K;
}

SparseMatrix reduceNodeBlocks(const NodeBlockRows& K, const SparseMatrix& A) {
  // S_ij = sum_nm A_ni K_nm A_mj on 3x3 blocks, in two sparse passes with dense row
  // accumulators: T = K A row by row, then S = A^T T. As scalar sparse products it took 4x
  // longer, most of a first step (block10 at K = 1: 260 ms).
  const uint32_t numNodes = K.numNodes();
  const Eigen::Index numControl = A.cols();
  // A dense accumulator over the control points.
  DenseAccumulator<Eigen::Matrix3d> sum(size_t(numControl), Eigen::Matrix3d::Zero());

  // T = K A: per node n, the blocks T_nj = sum_m K_nm A_mj.
  using RowSparseMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;
  const RowSparseMatrix rowsOfA = A;
  std::vector<size_t> tBegin(size_t(numNodes) + 1, 0);
  std::vector<uint32_t> tColumn;
  std::vector<Eigen::Matrix3d> tBlock;
  // T had 1.4x K's blocks for the stand-in and 0.45x for the elements' own stiffness (the
  // bunny at K = 1). Reserved, not touched: pages never written cost nothing, and growing by
  // copies cost a first step 200-400 ms of page faults and copying on a machine where faults
  // are dear (docs/BENCHMARKS.md).
  tColumn.reserve(2 * K.column.size());
  tBlock.reserve(2 * K.column.size());
  for (uint32_t n = 0; n < numNodes; ++n) {
    for (uint32_t k = K.begin[n]; k < K.begin[n + 1]; ++k)
      for (RowSparseMatrix::InnerIterator it(rowsOfA, K.column[k]); it; ++it)
        sum.add(uint32_t(it.col()), it.value() * K.block[k]);
    sum.drain([&](uint32_t j, const Eigen::Matrix3d& block) {
      tColumn.push_back(j);
      tBlock.push_back(block);
    });
    tBegin[n + 1] = tColumn.size();
  }

  // S = A^T T: control row i gathers A_ni T_n over the nodes n of A's column i. S is symmetric,
  // so row i's blocks, transposed, are column i's: column 3i + c holds S_ij(c, r) at row 3j + r.
  SparseMatrix S(3 * numControl, 3 * numControl);
  S.reserve(Eigen::Index(tColumn.size()) * 9);  // a guess; the matrix grows as needed
  std::vector<std::pair<uint32_t, Eigen::Matrix3d>> rowBlocks;
  for (Eigen::Index i = 0; i < numControl; ++i) {
    for (SparseMatrix::InnerIterator it(A, i); it; ++it) {
      const size_t n = size_t(it.row());
      for (size_t k = tBegin[n]; k < tBegin[n + 1]; ++k)
        sum.add(tColumn[k], it.value() * tBlock[k]);
    }
    sum.sortTouched();
    rowBlocks.clear();
    sum.drain([&](uint32_t j, const Eigen::Matrix3d& block) { rowBlocks.emplace_back(j, block); });
    for (int c = 0; c < 3; ++c) {
      S.startVec(3 * i + c);
      for (const auto& [j, block] : rowBlocks)
        for (int r = 0; r < 3; ++r) S.insertBack(3 * Eigen::Index(j) + r, 3 * i + c) = block(c, r);
    }
  }
  S.finalize();
  return S;
}

}  // namespace sculpt
