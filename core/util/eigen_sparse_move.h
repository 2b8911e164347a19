// Part of the body of Eigen::SparseMatrix, included there through EIGEN_SPARSEMATRIX_PLUGIN (set
// for every target in the top CMakeLists.txt); hence no include guard.
//
// Eigen 3.4.0's SparseMatrix declares a copy constructor and copy assignment but no moves, so
// std::move, std::future::get and returns without copy elision copy every array: block10's
// stiffness stand-in (12 MB) was copied seven times on its way to the first factor
// (docs/memory.md). These take the other matrix's arrays instead; the matrix moved from is left
// empty (a move constructor) or with this one's old contents (a move assignment).
SparseMatrix(SparseMatrix&& other) noexcept : SparseMatrix() { swap(other); }
SparseMatrix& operator=(SparseMatrix&& other) noexcept {
  swap(other);
  return *this;
}
