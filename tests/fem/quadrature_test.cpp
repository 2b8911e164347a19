// One-dimensional quadrature rules (core/fem/quadrature.h) against exact integrals on [0, 1].

#include "fem/quadrature.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace sculpt {
namespace {

double integrate(const QuadratureRule& rule, auto f) {
  double s = 0;
  for (int i = 0; i < rule.size(); ++i) s += rule.weights[size_t(i)] * f(rule.points[size_t(i)]);
  return s;
}

TEST(Quadrature, GaussLegendreIsExactUpToDegree2nMinus1) {
  for (int n = 1; n <= 5; ++n) {
    const QuadratureRule rule = gaussLegendre(n);
    ASSERT_EQ(rule.size(), n);
    double worst = 0;
    for (int k = 0; k <= 2 * n - 1; ++k) {
      const double exact = 1.0 / (k + 1);  // integral of x^k on [0, 1]
      const double got = integrate(rule, [k](double x) { return std::pow(x, k); });
      worst = std::max(worst, std::abs(got - exact));
      EXPECT_NEAR(got, exact, 1e-15) << "n = " << n << ", k = " << k;
    }
    // Degree 2n is not integrated exactly: the test is sensitive to the rule.
    const double exact2n = 1.0 / (2 * n + 1);
    const double got2n = integrate(rule, [n](double x) { return std::pow(x, 2 * n); });
    EXPECT_GT(std::abs(got2n - exact2n), 1e-6) << "n = " << n;
    for (double p : rule.points) {
      EXPECT_GT(p, 0.0);
      EXPECT_LT(p, 1.0);
    }
    std::printf("gaussLegendre(%d): worst error on x^0..x^%d = %.3g, error on x^%d = %.3g\n", n,
                2 * n - 1, worst, 2 * n, std::abs(got2n - exact2n));
  }
}

TEST(Quadrature, GaussLegendreRejectsUnsupportedSizes) {
  EXPECT_THROW(gaussLegendre(0), std::invalid_argument);
  EXPECT_THROW(gaussLegendre(6), std::invalid_argument);
}

TEST(Quadrature, CollapsedPyramidRuleIntegratesWeightedCubicsExactly) {
  const QuadratureRule rule = collapsedPyramidRule();
  ASSERT_EQ(rule.size(), 2);
  for (double p : rule.points) {
    EXPECT_GT(p, 0.0);
    EXPECT_LT(p, 1.0);  // no point on the apex, where the map degenerates
  }
  for (double w : rule.weights) EXPECT_GT(w, 0.0);
  double worst = 0;
  for (int k = 0; k <= 3; ++k) {
    // integral_0^1 (1 - w)^2 w^k dw = B(k + 1, 3) = 2 / ((k + 1)(k + 2)(k + 3))
    const double exact = 2.0 / ((k + 1.0) * (k + 2.0) * (k + 3.0));
    const double got =
        integrate(rule, [k](double w) { return (1 - w) * (1 - w) * std::pow(w, k); });
    worst = std::max(worst, std::abs(got - exact) / exact);
    EXPECT_NEAR(got, exact, 1e-15) << "k = " << k;
  }
  // Degree 4 times the weight is beyond a 2-point Gauss-Jacobi rule.
  const double exact4 = 2.0 / (5.0 * 6.0 * 7.0);
  const double got4 = integrate(rule, [](double w) { return (1 - w) * (1 - w) * std::pow(w, 4); });
  EXPECT_GT(std::abs(got4 - exact4), 1e-5);
  // Independent nodes: roots of the degree-2 orthogonal polynomial for the weight (1 - w)^2,
  // w^2 - 2/3 w + 1/15 (from the moments 1/3, 1/12, 1/30, 1/60).
  for (double p : rule.points) EXPECT_NEAR(p * p - 2.0 / 3.0 * p + 1.0 / 15.0, 0.0, 1e-15);
  std::printf(
      "collapsedPyramidRule: points %.17g %.17g, weights %.17g %.17g, worst rel. error "
      "%.3g, degree-4 error %.3g\n",
      rule.points[0], rule.points[1], rule.weights[0], rule.weights[1], worst,
      std::abs(got4 - exact4));
}

}  // namespace
}  // namespace sculpt
