#include "dfvn/stats/radial_distribution.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "dfvn/core/hash.hpp"
#include "dfvn/sampling/jitter.hpp"
#include "dfvn/sampling/lattice.hpp"
#include "test_support.hpp"

namespace dfvn {
namespace {

TEST(UnitBall, KnownVolumes) {
  EXPECT_NEAR(unit_ball_volume(2), std::numbers::pi, 1e-14);
  EXPECT_NEAR(unit_ball_volume(3), 4.0 / 3.0 * std::numbers::pi, 1e-14);
  EXPECT_NEAR(unit_ball_volume(4), std::numbers::pi * std::numbers::pi / 2.0, 1e-14);
}

// The lens |B intersect (B + d)| of two balls: the closed forms in 2D (2R^2 acos(d/2R) - (d/2) sqrt(4R^2 -
// d^2)) and 3D (pi (4R + d) (2R - d)^2 / 12), the whole ball at d = 0 and nothing at d = 2R, in every
// dimension; and a Monte Carlo estimate in 5D (seeded).
TEST(BallOverlap, IsTheLensOfTwoBalls) {
  const double R = 0.7;
  for (double d : {0.0, 0.1, 0.5, 1.0, 1.3, 1.4}) {
    EXPECT_NEAR(ball_overlap_volume(2, R, d), 2 * R * R * std::acos(d / (2 * R)) - 0.5 * d * std::sqrt(4 * R * R - d * d), 1e-12);
    EXPECT_NEAR(ball_overlap_volume(3, R, d), std::numbers::pi * (4 * R + d) * (2 * R - d) * (2 * R - d) / 12.0, 1e-12);
  }
  for (int n = 2; n <= 8; ++n) {
    EXPECT_NEAR(ball_overlap_volume(n, R, 0.0), unit_ball_volume(n) * std::pow(R, n), 1e-12) << n;
    EXPECT_NEAR(ball_overlap_volume(n, R, 2 * R), 0.0, 1e-14) << n;
  }
  int inside = 0;
  const int count = 400000;
  for (int i = 0; i < count; ++i) {
    double x[5], a2 = 0.0, b2 = 0.0;
    for (int j = 0; j < 5; ++j) x[j] = R * (2.0 * random_unit(3, Stream::test, static_cast<std::uint64_t>(i), static_cast<std::uint64_t>(j)) - 1.0);
    for (int j = 0; j < 5; ++j) a2 += x[j] * x[j], b2 += (x[j] - (j == 0 ? 0.6 : 0.0)) * (x[j] - (j == 0 ? 0.6 : 0.0));
    inside += a2 <= R * R && b2 <= R * R;
  }
  const double p = ball_overlap_volume(5, R, 0.6) / std::pow(2 * R, 5);
  EXPECT_NEAR(static_cast<double>(inside) / count, p, 5.0 * std::sqrt(p * (1 - p) / count));
}

// Uniform random points in the ball: g(r) -> 1 with the lens as the edge correction, up to the radius.
TEST(RadialDistribution, UniformPointsInTheBallGiveOne) {
  for (int dimension : {2, 3, 5}) {
    const std::uint64_t wanted = testing::sanitizer_scaled(20000, 4);
    const PointSet cube = uniform_random_points(dimension, 8 * wanted, Box{0.0, 1.0}, 5 + dimension, 2);
    PointSet ball{dimension, {}, Domain::unit(DomainKind::ball)};
    for (std::size_t i = 0; i < cube.size() && ball.size() < wanted; ++i)
      if (ball.domain.contains(cube.point(i), dimension))
        ball.coordinates.insert(ball.coordinates.end(), cube.point(i), cube.point(i) + dimension);
    ASSERT_EQ(ball.size(), wanted);
    RdfOptions o;
    o.bins = 10;
    o.r_max = 0.45;
    o.max_queries = 0;
    const RdfCurve c = radial_distribution(ball, o, 1, 2);
    const double n = static_cast<double>(ball.size()), volume = ball.domain.measure(dimension);
    for (int k = 2; k < o.bins; ++k) {
      const double lo = k * o.r_max / o.bins, hi = (k + 1) * o.r_max / o.bins;
      // Pairs in the bin: n^2 / (2V) times the shell volume, thinned by the lens (at most 1).
      const double expected_pairs = 0.5 * n * (n - 1) / volume * unit_ball_volume(dimension) *
                                    (std::pow(hi, dimension) - std::pow(lo, dimension)) *
                                    ball_overlap_volume(dimension, 0.5, hi) / volume;
      EXPECT_NEAR(c.g[k], 1.0, 5.0 / std::sqrt(expected_pairs) + 0.01) << dimension << "D bin " << k;
    }
  }
}

// Bins so narrow that their shell volume underflows are refused before computing (--rdf-max 1e-300
// gave NaN); every accepted configuration gives finite g.
TEST(RadialDistribution, TooNarrowBinsAreRefusedAndAcceptedOnesAreFinite) {
  for (int dimension : {2, 5, 8}) {
    EXPECT_THROW(check_rdf_resolution(dimension, 1.0, 1e-300, 50), std::invalid_argument);
    EXPECT_THROW(check_rdf_resolution(dimension, 1.0, 0.0, 50), std::invalid_argument);
    EXPECT_NO_THROW(check_rdf_resolution(dimension, 1.0, 1e-6, 3));
    const PointSet p = uniform_random_points(dimension, 500, Box{0.0, 1.0}, 5, 1);
    RdfOptions options;
    options.r_max = 1e-300;
    EXPECT_THROW(radial_distribution(p, options, 1, 1), std::invalid_argument);
    options.r_max = 1e-6;
    options.bins = 3;
    for (double g : radial_distribution(p, options, 1, 1).g) EXPECT_TRUE(std::isfinite(g));
  }
}

// Uniform random points: g(r) -> 1 at every r, including r comparable to the box (the edge
// correction). Each bin is compared with its Poisson standard error (pairs counted twice).
TEST(RadialDistribution, UniformRandomPointsGiveOne) {
  for (int dimension : {2, 3, 5, 7}) {
    const std::uint64_t n = testing::sanitizer_scaled(dimension <= 3 ? 20000 : 60000, 4);
    const PointSet p = uniform_random_points(dimension, n, Box{0.0, 1.0}, 77 + dimension, 2);
    RdfOptions o;
    o.bins = 20;
    o.r_max = dimension <= 3 ? 0.25 : 0.5;  // up to half the box: most pairs there need the correction
    o.max_queries = 0;
    const RdfCurve c = radial_distribution(p, o, 1, 2);
    int outside = 0;
    for (int k = 2; k < o.bins; ++k) {  // the first bins hold few pairs
      const double lo = k * o.r_max / o.bins, hi = (k + 1) * o.r_max / o.bins;
      const double expected_pairs = 0.5 * static_cast<double>(n) * static_cast<double>(n - 1) * unit_ball_volume(dimension) *
                                    (std::pow(hi, dimension) - std::pow(lo, dimension));
      const double standard_error = 1.0 / std::sqrt(std::max(expected_pairs, 1.0));
      if (std::abs(c.g[k] - 1.0) > 5.0 * standard_error + 0.01) {
        ++outside;
        ADD_FAILURE() << dimension << "D bin " << k << " r=" << c.r[k] << " g=" << c.g[k] << " (se " << standard_error << ")";
      }
    }
    EXPECT_EQ(outside, 0);
  }
}

// The paper's estimator (no factor 2, no edge correction) tends to 0.5 and sags: ours must not.
TEST(RadialDistribution, LatticeHasNoPairsBelowItsSpacing) {
  const LatticeSpec l{3, 10, Protocol::fair};
  PointSet p{3, Coordinates(3000, 0.0), Box{0.0, 1.0}};
  for (std::uint64_t i = 0; i < 1000; ++i) l.point(i, p.coordinates.data() + 3 * i);
  RdfOptions o;
  o.r_max = 0.2;
  o.bins = 20;
  const RdfCurve c = radial_distribution(p, o, 1, 1);
  for (int k = 0; k < 9; ++k) EXPECT_EQ(c.g[k], 0.0);  // r < 0.09
  // The 6 neighbours at exactly 0.1 (bin 9 or 10 by rounding) against 1.3 expected for uniform points.
  EXPECT_GT(c.g[9] + c.g[10], 3.0);
}

TEST(RadialDistribution, QuerySubsetIsUnbiasedAndThreadIndependent) {
  const PointSet p = uniform_random_points(4, 50000, Box{0.0, 1.0}, 5, 2);
  RdfOptions o;
  o.bins = 10;
  o.r_max = 0.3;
  o.max_queries = 5000;
  const RdfCurve a = radial_distribution(p, o, 3, 1), b = radial_distribution(p, o, 3, 2);
  EXPECT_EQ(a.g, b.g);
  EXPECT_NEAR(static_cast<double>(a.queries), 5000.0, 300.0);
  for (int k = 3; k < o.bins; ++k) EXPECT_NEAR(a.g[k], 1.0, 0.05);
}

}  // namespace
}  // namespace dfvn
