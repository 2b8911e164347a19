#include "subdiv/tricubic_patch.h"

#include <algorithm>

namespace sculpt {

void cubicBSplineBasis(double t, double basis[4], double derivative[4]) {
  const double s = 1.0 - t, t2 = t * t, t3 = t2 * t;
  basis[0] = s * s * s / 6.0;
  basis[1] = (3.0 * t3 - 6.0 * t2 + 4.0) / 6.0;
  basis[2] = (-3.0 * t3 + 3.0 * t2 + 3.0 * t + 1.0) / 6.0;
  basis[3] = t3 / 6.0;
  if (derivative) {
    derivative[0] = -0.5 * s * s;
    derivative[1] = (9.0 * t2 - 12.0 * t) / 6.0;
    derivative[2] = (-9.0 * t2 + 6.0 * t + 3.0) / 6.0;
    derivative[3] = 0.5 * t2;
  }
}

Eigen::Vector3d evaluateTricubic(const Points& positions, const ControlBlock& block, double u,
                                 double v, double w) {
  double bu[4], bv[4], bw[4];
  cubicBSplineBasis(u, bu);
  cubicBSplineBasis(v, bv);
  cubicBSplineBasis(w, bw);
  Eigen::Vector3d x = Eigen::Vector3d::Zero();
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b)
      for (int g = 0; g < 4; ++g)
        x += bu[a] * bv[b] * bw[g] * positions.row(block[size_t(a * 16 + b * 4 + g)]).transpose();
  return x;
}

Eigen::Vector3d regularVertexLimit(const Topology& t, const Points& positions, uint32_t v) {
  // The 27 vertices of the 8 cells around v, classified by what they share with v.
  std::vector<uint32_t> neighbourhood;
  for (uint32_t c : t.vertexCells.row(v))
    for (uint32_t u : t.cellVertices.row(c)) neighbourhood.push_back(u);
  std::sort(neighbourhood.begin(), neighbourhood.end());
  neighbourhood.erase(std::unique(neighbourhood.begin(), neighbourhood.end()), neighbourhood.end());
  auto sharesFace = [&](uint32_t u) {
    for (uint32_t f : t.vertexFaces.row(v)) {
      auto loop = t.faceVertices.row(f);
      if (std::find(loop.begin(), loop.end(), u) != loop.end()) return true;
    }
    return false;
  };
  Eigen::Vector3d x = Eigen::Vector3d::Zero();
  for (uint32_t u : neighbourhood) {
    double w;
    if (u == v) w = 8.0 / 27.0;
    else if (t.findEdge(v, u) >= 0) w = 2.0 / 27.0;
    else if (sharesFace(u)) w = 1.0 / 54.0;
    else w = 1.0 / 216.0;
    x += w * positions.row(u).transpose();
  }
  return x;
}

}  // namespace sculpt
