#include "sim/node_block_rows.h"

#include <utility>

#include "util/dense_accumulator.h"
#include "util/reserve_from_mean.h"

namespace sculpt {

namespace {

// Ends the current row of `rows` with the accumulator's sums.
void endRow(NodeBlockRows& rows, DenseAccumulator<Eigen::Matrix3d>& sum) {
  sum.drain([&](uint32_t j, const Eigen::Matrix3d& block) {
    rows.column.push_back(j);
    rows.block.push_back(block);
  });
  rows.begin.push_back(uint32_t(rows.column.size()));
}

}  // namespace

SparseMatrix reduceSymmetricNodeBlocks(const SymmetricNodeBlocks& nodes, const SparseMatrix& A) {
  // K = V + V^T, V being K's blocks above the diagonal and half of each diagonal block, so
  // S = A^T K A = W + W^T with W = A^T V A. W takes two sparse passes over V with a dense row
  // accumulator, T = V A row by row, then W = A^T T; S adds W's transpose. Reducing K whole
  // (its lower blocks mirrored first) took 1.6x as long and twice K's memory; as scalar sparse
  // products, 4x longer still (docs/BENCHMARKS.md).
  const NodeBlockRows& K = nodes.K;
  const uint32_t numNodes = K.numNodes();
  const uint32_t numControl = uint32_t(A.cols());
  DenseAccumulator<Eigen::Matrix3d> sum(numControl, Eigen::Matrix3d::Zero());

  // T = V A: per node n, the blocks T_nj = sum_m V_nm A_mj (row n of K starts with n itself).
  using RowSparseMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;
  const RowSparseMatrix rowsOfA = A;
  NodeBlockRows T;
  T.begin.reserve(size_t(numNodes) + 1);
  // T had 1.8-1.9x V's blocks for the stand-in (the bunny, block10 and block12 at K = 1) and
  // 0.7x for the elements' own stiffness (the bunny). Reserved, not touched: pages never written
  // cost nothing, and growing by copies cost a first step 200-400 ms of page faults and copying
  // where faults are dear (docs/memory.md). Reserving from the rows' mean (as W does) made
  // BM_StandInStiffness and BM_RestStiffness 1.3x slower: T's rows grow denser along the node
  // order, and each new estimate copied T again.
  T.column.reserve(5 * K.column.size() / 2);
  T.block.reserve(5 * K.column.size() / 2);
  for (uint32_t n = 0; n < numNodes; ++n) {
    for (uint32_t k = K.begin[n]; k < K.begin[n + 1]; ++k) {
      const double weight = k == K.begin[n] ? 0.5 : 1.0;
      for (RowSparseMatrix::InnerIterator it(rowsOfA, K.column[k]); it; ++it)
        sum.add(uint32_t(it.col()), (weight * it.value()) * K.block[k]);
    }
    endRow(T, sum);
  }

  // W = A^T T: control row i gathers A_ni T_n over the nodes n of A's column i.
  NodeBlockRows W;
  W.begin.reserve(size_t(numControl) + 1);
  for (uint32_t i = 0; i < numControl; ++i) {
    for (SparseMatrix::InnerIterator it(A, i); it; ++it) {
      const size_t n = size_t(it.row());
      for (size_t k = T.begin[n]; k < T.begin[n + 1]; ++k)
        sum.add(T.column[k], it.value() * T.block[k]);
    }
    endRow(W, sum);
    reserveFromMean(i + 1, numControl, W.column, W.block);
  }
  T = {};

  // W's columns: for control point j, the places k of the blocks W_ij (i increasing).
  std::vector<size_t> columnBegin(size_t(numControl) + 1, 0);
  for (uint32_t j : W.column) ++columnBegin[j + 1];
  for (uint32_t j = 0; j < numControl; ++j) columnBegin[j + 1] += columnBegin[j];
  std::vector<size_t> inColumn(W.column.size());
  std::vector<uint32_t> rowOf(W.column.size());
  {
    std::vector<size_t> next(columnBegin.begin(), columnBegin.end() - 1);
    for (uint32_t i = 0; i < numControl; ++i)
      for (size_t k = W.begin[i]; k < W.begin[i + 1]; ++k) {
        const size_t place = next[W.column[k]]++;
        inColumn[place] = k;
        rowOf[place] = i;
      }
  }

  // S = W + W^T, row i: W_ij and W_ji^T. S is symmetric, so row i's blocks, transposed, are
  // column i's: column 3i + c holds S_ij(c, r) at row 3j + r.
  // Its blocks, counted first: reserving a guess and growing past it cost the first step a
  // second copy of S in memory touched for the first time (docs/memory.md).
  Eigen::Index entries = 0;
  {
    std::vector<uint32_t> seenIn(numControl, numControl);  // the last row j was counted in
    for (uint32_t i = 0; i < numControl; ++i) {
      const auto count = [&](uint32_t j) {
        if (seenIn[j] != i) entries += 9;
        seenIn[j] = i;
      };
      for (size_t k = W.begin[i]; k < W.begin[i + 1]; ++k) count(W.column[k]);
      for (size_t p = columnBegin[i]; p < columnBegin[i + 1]; ++p) count(rowOf[p]);
    }
  }
  SparseMatrix S(3 * Eigen::Index(numControl), 3 * Eigen::Index(numControl));
  S.reserve(entries);
  std::vector<std::pair<uint32_t, Eigen::Matrix3d>> rowBlocks;
  for (uint32_t i = 0; i < numControl; ++i) {
    for (size_t k = W.begin[i]; k < W.begin[i + 1]; ++k) sum.add(W.column[k], W.block[k]);
    for (size_t p = columnBegin[i]; p < columnBegin[i + 1]; ++p)
      sum.add(rowOf[p], W.block[inColumn[p]].transpose());
    sum.sortTouched();
    rowBlocks.clear();
    sum.drain([&](uint32_t j, const Eigen::Matrix3d& block) { rowBlocks.emplace_back(j, block); });
    for (int c = 0; c < 3; ++c) {
      S.startVec(3 * Eigen::Index(i) + c);
      for (const auto& [j, block] : rowBlocks)
        for (int r = 0; r < 3; ++r)
          S.insertBack(3 * Eigen::Index(j) + r, 3 * Eigen::Index(i) + c) = block(c, r);
    }
  }
  S.finalize();
  return S;
}

}  // namespace sculpt
