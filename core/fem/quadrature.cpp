#include "fem/quadrature.h"

#include <cmath>
#include <stdexcept>

namespace sculpt {

QuadratureRule gaussLegendre(int n) {
  // Abscissae and weights on [-1, 1], mapped to [0, 1] below.
  static const double kPoints[5][5] = {
      {0.0},
      {-0.5773502691896257645, 0.5773502691896257645},
      {-0.7745966692414833770, 0.0, 0.7745966692414833770},
      {-0.8611363115940525752, -0.3399810435848562648, 0.3399810435848562648,
       0.8611363115940525752},
      {-0.9061798459386639928, -0.5384693101056830910, 0.0, 0.5384693101056830910,
       0.9061798459386639928}};
  static const double kWeights[5][5] = {
      {2.0},
      {1.0, 1.0},
      {0.5555555555555555556, 0.8888888888888888889, 0.5555555555555555556},
      {0.3478548451374538574, 0.6521451548625461426, 0.6521451548625461426,
       0.3478548451374538574},
      {0.2369268850561890875, 0.4786286704993664680, 0.5688888888888888889,
       0.4786286704993664680, 0.2369268850561890875}};
  if (n < 1 || n > 5) throw std::invalid_argument("gaussLegendre: n must be in 1..5");
  QuadratureRule rule;
  for (int i = 0; i < n; ++i) {
    rule.points.push_back(0.5 * (kPoints[n - 1][i] + 1.0));
    rule.weights.push_back(0.5 * kWeights[n - 1][i]);
  }
  return rule;
}

QuadratureRule collapsedPyramidRule() {
  // Orthogonal polynomial of degree 2 for the weight (1 - w)^2 on [0, 1]: w^2 - 2/3 w + 1/15
  // (from the moments 1/3, 1/12, 1/30, 1/60). Its roots are the nodes; the weights reproduce
  // the moments 1/3 and 1/12, and dividing by (1 - w)^2 turns them into weights for f itself.
  const double r = std::sqrt(2.0 / 45.0);
  const double w0 = 1.0 / 3.0 - r, w1 = 1.0 / 3.0 + r;
  // a0 + a1 = 1/3, a0 w0 + a1 w1 = 1/12.
  const double a1 = (1.0 / 12.0 - w0 / 3.0) / (w1 - w0);
  const double a0 = 1.0 / 3.0 - a1;
  QuadratureRule rule;
  rule.points = {w0, w1};
  rule.weights = {a0 / ((1 - w0) * (1 - w0)), a1 / ((1 - w1) * (1 - w1))};
  return rule;
}

}  // namespace sculpt
