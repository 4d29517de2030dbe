#include "dfvn/stats/lattice_displacement.hpp"

#include <cmath>
#include <numbers>

#include "dfvn/sampling/jitter.hpp"
#include "dfvn/sampling/lattice.hpp"
#include "test_support.hpp"

namespace dfvn {
namespace {

TEST(LatticeDisplacement, RigidTranslationKeepsTheLatticeAndHasNoDisorder) {
  const int n = 3, k = 6;
  std::vector<double> u(216 * n);
  for (std::size_t i = 0; i < 216; ++i) u[i * n] = 0.3, u[i * n + 1] = -0.1, u[i * n + 2] = 0.0;
  const auto s = summarize_lattice_displacements(n, k, 0.5, u);
  EXPECT_NEAR(s.rms, std::sqrt(0.1), 1e-12);
  EXPECT_NEAR(s.median, std::sqrt(0.1), 1e-12);
  EXPECT_EQ(s.fraction_unmoved, 0.0);
  EXPECT_NEAR(s.neighbour_disorder, 0.0, 1e-12);
  EXPECT_NEAR(s.lattice_order, 1.0, 1e-12);
}

// Uniform jitter of half-width h spacings: neighbour disorder sqrt(2N/3) h and lattice order
// (sin(2 pi h) / (2 pi h))^2, up to sampling error (and the 1/n bias of the order).
TEST(LatticeDisplacement, UniformJitterMatchesItsClosedForms) {
  const LatticeSpec lattice{4, 12, Protocol::unit};
  const PointSet points = jittered_lattice(lattice, 5, 0);  // unit protocol: h = 1/2 spacing
  const double a = lattice.spacing();
  const auto s = summarize_lattice_displacements(4, 12, a, lattice_displacements(lattice, points));
  const double h = jitter_half_width(lattice) / a;
  EXPECT_NEAR(s.neighbour_disorder, std::sqrt(2.0 * 4 / 3.0) * h, 0.01);
  const double sinc = std::sin(2 * std::numbers::pi * h) / (2 * std::numbers::pi * h);
  EXPECT_NEAR(s.lattice_order, sinc * sinc, 5.0 / 20736.0);
  EXPECT_NEAR(s.rms, std::sqrt(4.0 / 3.0) * h * a, 0.01 * a);
  EXPECT_EQ(s.fraction_unmoved, 0.0);
}

TEST(LatticeDisplacement, UnmovedPointsAreCountedAndMaskedPointsLeftOut) {
  std::vector<double> u(2 * 4, 0.0);  // K = 2, N = 2: 4 points
  u[0] = 0.5;                           // point 0 moved half a spacing
  const auto all = summarize_lattice_displacements(2, 2, 1.0, u);
  EXPECT_DOUBLE_EQ(all.fraction_unmoved, 0.75);
  const auto masked = summarize_lattice_displacements(2, 2, 1.0, u, {1, 0, 0, 1});
  EXPECT_DOUBLE_EQ(masked.fraction_unmoved, 0.5);
  EXPECT_THROW(summarize_lattice_displacements(2, 3, 1.0, u), std::invalid_argument);
}

}  // namespace
}  // namespace dfvn
