#pragma once
// Shape functions of the 8-node trilinear hexahedron on [0,1]^3, VTK node order: 0 (0,0,0),
// 1 (1,0,0), 2 (1,1,0), 3 (0,1,0), then 4-7 the same corners at w = 1.

#include <Eigen/Core>

namespace sculpt {

inline constexpr int kTrilinearCorner[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                               {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};

/// Values N (8) and parametric gradients dN (8 by 3) at xi.
inline void trilinearShape(const Eigen::Vector3d& xi, double N[8], double dN[8][3]) {
  for (int a = 0; a < 8; ++a) {
    double f[3], df[3];
    for (int d = 0; d < 3; ++d) {
      f[d] = kTrilinearCorner[a][d] ? xi[d] : 1.0 - xi[d];
      df[d] = kTrilinearCorner[a][d] ? 1.0 : -1.0;
    }
    N[a] = f[0] * f[1] * f[2];
    dN[a][0] = df[0] * f[1] * f[2];
    dN[a][1] = f[0] * df[1] * f[2];
    dN[a][2] = f[0] * f[1] * df[2];
  }
}

}  // namespace sculpt
