#pragma once
// A sparse symmetric positive definite test matrix shaped like the solver's systems.

#include <Eigen/SparseCore>
#include <vector>

namespace sculpt::test {

// The 7-point Laplacian of an n^3 grid plus `shift` times the identity: symmetric positive
// definite, and its nested-dissection factor has large dense supernodes like the solver's.
inline Eigen::SparseMatrix<double> gridLaplacian(int n, double shift) {
  std::vector<Eigen::Triplet<double>> entries;
  auto id = [n](int i, int j, int k) { return (i * n + j) * n + k; };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        const int row = id(i, j, k);
        entries.emplace_back(row, row, 6.0 + shift);
        const int next[3][3] = {{i + 1, j, k}, {i, j + 1, k}, {i, j, k + 1}};
        for (const auto& c : next) {
          if (c[0] >= n || c[1] >= n || c[2] >= n) continue;
          entries.emplace_back(row, id(c[0], c[1], c[2]), -1.0);
          entries.emplace_back(id(c[0], c[1], c[2]), row, -1.0);
        }
      }
  Eigen::SparseMatrix<double> S(n * n * n, n * n * n);
  S.setFromTriplets(entries.begin(), entries.end());
  return S;
}

}  // namespace sculpt::test
