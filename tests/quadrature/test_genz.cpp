#include "dfvn/quadrature/genz.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace dfvn {
namespace {

// Gauss-Legendre rule of `order` nodes on [-1, 1], by Newton's method on P_order from the Chebyshev
// guesses cos(pi (k - 1/4) / (order + 1/2)) (Numerical Recipes' gauleg).
void gauss_legendre(int order, std::vector<double>& nodes, std::vector<double>& weights) {
  nodes.assign(order, 0.0);
  weights.assign(order, 0.0);
  for (int k = 0; k < order; ++k) {
    double x = std::cos(std::numbers::pi * (k + 0.75) / (order + 0.5));
    double derivative = 0.0;
    for (int iteration = 0; iteration < 100; ++iteration) {
      double p0 = 1.0, p1 = x;  // P_0, P_1, then the three-term recurrence up to P_order
      for (int j = 2; j <= order; ++j) {
        const double p2 = ((2.0 * j - 1.0) * x * p1 - (j - 1.0) * p0) / j;
        p0 = p1;
        p1 = p2;
      }
      derivative = order * (x * p1 - p0) / (x * x - 1.0);
      const double step = p1 / derivative;
      x -= step;
      if (std::abs(step) < 1e-16) break;
    }
    nodes[k] = x;
    weights[k] = 2.0 / ((1.0 - x * x) * derivative * derivative);
  }
}

// A composite 1D rule on [0,1]: panels split at the integrand's kinks and jumps (the shifts u_i), each
// cut into `panels` pieces with a `order`-node Gauss-Legendre rule.
void composite_rule(double kink, int panels, int order, std::vector<double>& x, std::vector<double>& w) {
  std::vector<double> nodes, weights;
  gauss_legendre(order, nodes, weights);
  x.clear();
  w.clear();
  for (auto [lo, hi] : {std::pair{0.0, kink}, std::pair{kink, 1.0}}) {
    const double h = (hi - lo) / panels;
    for (int p = 0; p < panels; ++p)
      for (int k = 0; k < order; ++k) {
        x.push_back(lo + h * (p + 0.5 * (nodes[k] + 1.0)));
        w.push_back(0.5 * h * weights[k]);
      }
  }
}

double tensor_quadrature(const GenzIntegrand& f, int panels, int order) {
  const int n = f.dimension();
  std::vector<std::vector<double>> x(n), w(n);
  for (int i = 0; i < n; ++i) composite_rule(f.u[i], panels, order, x[i], w[i]);
  const std::size_t m = x[0].size();
  std::vector<std::size_t> index(n, 0);
  double sum = 0.0;
  std::vector<double> point(n);
  while (true) {
    double weight = 1.0;
    for (int i = 0; i < n; ++i) {
      point[i] = x[i][index[i]];
      weight *= w[i][index[i]];
    }
    sum += weight * f(point.data());
    int i = 0;
    while (i < n && ++index[i] == m) index[i++] = 0;
    if (i == n) break;
  }
  return sum;
}

// The closed forms of genz.cpp against a tensor Gauss-Legendre rule (2 x 16 panels of 20 nodes per
// axis, split at the shifts) in 2D: at most 1e-12 relative for every family and several seeds.
TEST(Genz, ExactIntegralsEqualHighOrderQuadratureIn2D) {
  for (GenzFamily family : kGenzFamilies) {
    for (std::uint64_t seed : {1u, 2u, 3u, 4u, 5u}) {
      const GenzIntegrand f = random_genz_integrand(family, 2, seed);
      const double exact = f.exact_integral();
      const double quadrature = tensor_quadrature(f, 16, 20);
      EXPECT_NEAR(exact, quadrature, 1e-12 * std::abs(quadrature)) << to_string(family) << " seed " << seed;
    }
  }
}

// In 3D as well, more coarsely (2 x 6 panels of 12 nodes), for the inclusion-exclusion sum of the
// corner peak and the products of the others.
TEST(Genz, ExactIntegralsEqualQuadratureIn3D) {
  for (GenzFamily family : kGenzFamilies) {
    const GenzIntegrand f = random_genz_integrand(family, 3, 11);
    const double quadrature = tensor_quadrature(f, 6, 12);
    EXPECT_NEAR(f.exact_integral(), quadrature, 1e-9 * std::abs(quadrature)) << to_string(family);
  }
}

TEST(Genz, ParametersFollowTheDifficultyAndTheSeed) {
  for (GenzFamily family : kGenzFamilies) {
    const GenzIntegrand f = random_genz_integrand(family, 7, 3);
    double sum = 0.0;
    for (int i = 0; i < 7; ++i) {
      EXPECT_GT(f.a[i], 0.0);
      EXPECT_TRUE(f.u[i] >= 0.0 && f.u[i] < 1.0);
      sum += f.a[i];
    }
    EXPECT_NEAR(sum, genz_difficulty(family), 1e-12);
    EXPECT_NE(f.u, random_genz_integrand(family, 7, 4).u);
    EXPECT_EQ(f.u, random_genz_integrand(family, 7, 3).u);
  }
}

}  // namespace
}  // namespace dfvn
