#pragma once
// Uniform tricubic B-spline evaluation of a regular cell, and limit positions of regular vertices.

#include <Eigen/Core>

#include "mesh/cell_complex.h"
#include "mesh/topology.h"
#include "subdiv/regularity.h"

namespace sculpt {

/// Uniform cubic B-spline basis B_0..B_3 at t in [0,1], and optionally its derivative.
void cubicBSplineBasis(double t, double basis[4], double derivative[4] = nullptr);

/// x(u,v,w) = sum B_a(u) B_b(v) B_g(w) P[a][b][g] over the control block.
Eigen::Vector3d evaluateTricubic(const Points& positions, const ControlBlock& block, double u,
                                 double v, double w);

/// Limit position of a regular vertex (isRegularVertex): (1,4,1)/6 in each direction on its
/// 3x3x3 neighbourhood, found combinatorially (edge neighbours 2/27, face diagonals 1/54,
/// cell diagonals 1/216, the vertex 8/27).
Eigen::Vector3d regularVertexLimit(const Topology& topology, const Points& positions, uint32_t v);

}  // namespace sculpt
