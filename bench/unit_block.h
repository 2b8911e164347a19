#pragma once
// An n x n x n block of unit hexahedra (n = 3 is assets/block3.json), for the benchmarks.
#include "mesh/cell_complex.h"
#include "mesh/standard_cell.h"

namespace sculpt::bench {

inline CellComplex unitBlock(int n) {
  CellComplex mesh;
  const int m = n + 1;
  auto id = [m](int i, int j, int k) { return uint32_t((k * m + j) * m + i); };
  mesh.positions.resize(m * m * m, 3);
  for (int k = 0; k < m; ++k)
    for (int j = 0; j < m; ++j)
      for (int i = 0; i < m; ++i) mesh.positions.row(id(i, j, k)) << i, j, k;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const uint32_t v[8] = {id(i, j, k),         id(i + 1, j, k),     id(i + 1, j + 1, k),
                               id(i, j + 1, k),     id(i, j, k + 1),     id(i + 1, j, k + 1),
                               id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)};
        mesh.addCell(standardCellFaces(StandardCell::Hexahedron, v));
      }
  return mesh;
}

}  // namespace sculpt::bench
