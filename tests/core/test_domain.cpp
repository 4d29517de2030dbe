#include "dfvn/core/domain.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>

namespace dfvn {
namespace {

TEST(Domain, NamesRoundTripAndUnknownOnesAreRefused) {
  for (DomainKind kind : kAllDomainKinds) EXPECT_EQ(parse_domain_kind(to_string(kind)), kind);
  EXPECT_EQ(domain_kind_names(), "torus, cube, ball, sphere");
  EXPECT_THROW(parse_domain_kind("box"), std::invalid_argument);
  EXPECT_THROW(parse_domain_kind(""), std::invalid_argument);
}

// Volumes in closed form: the unit cube and torus 1, the inscribed disc pi/4, the 3D ball pi/6, the
// unit circle's length 2 pi and the 2-sphere's area 4 pi; a side of 2 scales them by 2^N (2^(N-1)).
TEST(Domain, MeasuresAreTheClosedForms) {
  for (int n = 2; n <= 8; ++n) {
    EXPECT_DOUBLE_EQ(Domain::unit(DomainKind::torus).measure(n), 1.0);
    EXPECT_DOUBLE_EQ(Domain::unit(DomainKind::cube).measure(n), 1.0);
    EXPECT_NEAR(Domain(DomainKind::cube, 0.0, 2.0).measure(n), std::pow(2.0, n), 1e-12);
  }
  EXPECT_NEAR(Domain::unit(DomainKind::ball).measure(2), std::numbers::pi / 4, 1e-15);
  EXPECT_NEAR(Domain::unit(DomainKind::ball).measure(3), std::numbers::pi / 6, 1e-15);
  EXPECT_NEAR(Domain::unit(DomainKind::sphere).measure(2), 2 * std::numbers::pi, 1e-14);
  EXPECT_NEAR(Domain::unit(DomainKind::sphere).measure(3), 4 * std::numbers::pi, 1e-14);
  EXPECT_EQ(Domain::unit(DomainKind::sphere).manifold_dimension(5), 4);
  EXPECT_EQ(Domain::unit(DomainKind::ball).manifold_dimension(5), 5);
}

// The ball's volume against the fraction of uniform points of its cube that it holds (seeded; 2e5 points).
TEST(Domain, BallHoldsItsVolumeFractionOfTheCube) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const Domain ball = Domain::unit(DomainKind::ball);
  for (int n : {2, 4, 6}) {
    int inside = 0;
    const int count = 200000;
    double x[8];
    for (int i = 0; i < count; ++i) {
      for (int j = 0; j < n; ++j) x[j] = u(rng);
      inside += ball.contains(x, n);
    }
    const double p = ball.measure(n);
    EXPECT_NEAR(static_cast<double>(inside) / count, p, 5.0 * std::sqrt(p * (1 - p) / count)) << n << "D";
  }
}

TEST(Domain, ContainsFollowsTheKind) {
  const double inside[3] = {0.5, 0.5, 0.5}, corner[3] = {0.99, 0.99, 0.99}, face[3] = {1.0, 0.2, 0.3},
               outside[3] = {1.01, 0.5, 0.5};
  for (DomainKind kind : {DomainKind::torus, DomainKind::cube}) {
    EXPECT_TRUE(Domain::unit(kind).contains(inside, 3));
    EXPECT_TRUE(Domain::unit(kind).contains(corner, 3));
    EXPECT_TRUE(Domain::unit(kind).contains(face, 3));  // a file may hold the torus' upper face
    EXPECT_FALSE(Domain::unit(kind).contains(outside, 3));
  }
  EXPECT_TRUE(Domain::unit(DomainKind::ball).contains(inside, 3));
  EXPECT_FALSE(Domain::unit(DomainKind::ball).contains(corner, 3));
  const double on_sphere[3] = {0.6, 0.8, 0.0}, off_sphere[3] = {0.6, 0.8, 0.01};
  EXPECT_TRUE(Domain::unit(DomainKind::sphere).contains(on_sphere, 3));
  EXPECT_FALSE(Domain::unit(DomainKind::sphere).contains(off_sphere, 3));
}

// Minimum image on the torus: the smallest distance over the 3^N images, checked by brute force on
// seeded random pairs in a box that is not the unit one; the cube's is the straight line.
TEST(Domain, TorusDistanceIsTheMinimumOverImages) {
  std::mt19937_64 rng(11);
  const Domain torus{DomainKind::torus, -2.0, 3.0}, cube{DomainKind::cube, -2.0, 3.0};
  std::uniform_real_distribution<double> u(-2.0, 1.0);
  for (int trial = 0; trial < 2000; ++trial) {
    double a[3], b[3];
    for (int j = 0; j < 3; ++j) a[j] = u(rng), b[j] = u(rng);
    double best = INFINITY, straight = 0.0;
    for (int image = 0; image < 27; ++image) {
      double d2 = 0.0;
      for (int j = 0, code = image; j < 3; ++j, code /= 3) {
        const double d = a[j] - (b[j] + 3.0 * (code % 3 - 1));
        d2 += d * d;
      }
      best = std::min(best, d2);
    }
    for (int j = 0; j < 3; ++j) straight += (a[j] - b[j]) * (a[j] - b[j]);
    EXPECT_NEAR(torus.distance2(a, b, 3), best, 1e-12);
    EXPECT_DOUBLE_EQ(cube.distance2(a, b, 3), straight);
  }
}

TEST(Domain, WrapIsModuloTheSideOnTheTorusOnly) {
  const Domain torus{DomainKind::torus, -1.0, 2.0};
  double x[4] = {-1.5, 1.0, 3.25, -1.0};
  torus.wrap(x, 4);
  EXPECT_DOUBLE_EQ(x[0], 0.5);
  EXPECT_DOUBLE_EQ(x[1], -1.0);  // the upper face is the lower one
  EXPECT_DOUBLE_EQ(x[2], -0.75);
  EXPECT_DOUBLE_EQ(x[3], -1.0);
  double y[2] = {1.5, -3.0};
  Domain::unit(DomainKind::cube).wrap(y, 2);
  EXPECT_EQ(y[0], 1.5);
  EXPECT_EQ(y[1], -3.0);
  double tiny[1] = {-1e-18};  // just below 0: its image rounds to 1, which is 0
  Domain::unit(DomainKind::torus).wrap(tiny, 1);
  EXPECT_EQ(tiny[0], 0.0);
}

TEST(Domain, DescribesItself) {
  EXPECT_EQ(Domain::unit(DomainKind::torus).describe(7), "the torus [0, 1)^7");
  EXPECT_EQ(Domain(DomainKind::cube, 0.0, 0.6).describe(7), "the cube [0, 0.6]^7");
  EXPECT_EQ(Domain::unit(DomainKind::sphere).describe(4), "the unit sphere S^3");
  EXPECT_EQ(Domain(Box{0.0, 2.0}), Domain(DomainKind::cube, 0.0, 2.0));  // a box is its cube
}

}  // namespace
}  // namespace dfvn
