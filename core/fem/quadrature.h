#pragma once
// One-dimensional quadrature rules on [0, 1], combined as tensor products by the elements.

#include <vector>

namespace sculpt {

struct QuadratureRule {
  std::vector<double> points;   ///< abscissae in [0, 1]
  std::vector<double> weights;  ///< sum to 1 (the length of [0, 1])
  int size() const { return static_cast<int>(points.size()); }
};

/// Gauss-Legendre rule with n points (1 <= n <= 5): exact for polynomials of degree 2n - 1.
QuadratureRule gaussLegendre(int n);

/// Two-point rule for the collapsing direction w of a pyramid written as a degenerate hexahedron
/// (the top face w = 1 shrinks to the apex). It is the Gauss-Jacobi rule for the weight
/// (1 - w)^2 with that weight divided back out, so f(w) = (1 - w)^2 g(w) is integrated exactly
/// for cubic g: the volume factor of the collapsed map is (1 - w)^2, and this "conical product"
/// rule puts no point where the map degenerates.
QuadratureRule collapsedPyramidRule();

}  // namespace sculpt
