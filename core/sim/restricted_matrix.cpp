#include "sim/restricted_matrix.h"

namespace sculpt {

Eigen::SparseMatrix<double> restrictedMatrix(const Eigen::SparseMatrix<double>& S,
                                             const std::vector<int>& rows,
                                             const std::vector<int>& columns) {
  std::vector<int> rowIndex(size_t(S.rows()), -1);
  for (size_t k = 0; k < rows.size(); ++k) rowIndex[size_t(rows[k])] = int(k);
  const int n = int(columns.size());
  Eigen::SparseMatrix<double> restricted(Eigen::Index(rows.size()), n);
  Eigen::Index entries = 0;
  for (const int column : columns) entries += S.col(column).nonZeros();
  restricted.reserve(entries);
  for (int k = 0; k < n; ++k) {
    restricted.startVec(k);
    for (Eigen::SparseMatrix<double>::InnerIterator it(S, columns[size_t(k)]); it; ++it) {
      const int r = rowIndex[size_t(it.row())];
      if (r >= 0) restricted.insertBack(r, k) = it.value();
    }
  }
  restricted.finalize();
  return restricted;
}

}  // namespace sculpt
