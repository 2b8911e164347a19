#pragma once
// A sparse matrix's entries on chosen coordinates: the system on the free coordinates, and the
// blocks that extend a factor to coordinates released from a pin.

#include <Eigen/SparseCore>
#include <vector>

namespace sculpt {

/// The entries S(rows[i], columns[j]) as a rows.size() x columns.size() matrix. Both lists are
/// increasing, so every kept column keeps its rows in order and is copied as it is.
Eigen::SparseMatrix<double> restrictedMatrix(const Eigen::SparseMatrix<double>& S,
                                             const std::vector<int>& rows,
                                             const std::vector<int>& columns);

}  // namespace sculpt
