#include "dfvn/stats/lattice_displacement.hpp"

#include <algorithm>
#include <cmath>
#include <vector>
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
  const LatticeSpec lattice{4, 12, Protocol::fair};
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

// The axes' sums and the lengths' pass run side by side from 2^20 coordinates on: the same bits on 1, 2
// and 4 threads, with and without a mask, and the median that of the sorted lengths (even and odd counts).
TEST(LatticeDisplacement, TheSameBitsOnAnyThreadCount) {
  const int n = 4, k = 23;  // 279,841 points, 1,119,364 coordinates
  const std::size_t rows = 279841;
  std::vector<double> u(rows * n);
  for (std::size_t i = 0; i < u.size(); ++i) u[i] = 0.01 * std::sin(0.37 * static_cast<double>(i)) * std::cos(1e-3 * static_cast<double>(i));
  std::vector<unsigned char> mask(rows);
  for (std::size_t i = 0; i < rows; ++i) mask[i] = (i % 3) != 1 && i != 0;
  for (const bool masked : {false, true}) {
    const std::vector<unsigned char> include = masked ? mask : std::vector<unsigned char>{};
    const auto one = summarize_lattice_displacements(n, k, 0.04, u, include, 1);
    for (const int threads : {2, 4}) {
      const auto many = summarize_lattice_displacements(n, k, 0.04, u, include, threads);
      EXPECT_EQ(many.rms, one.rms) << threads;
      EXPECT_EQ(many.median, one.median) << threads;
      EXPECT_EQ(many.fraction_unmoved, one.fraction_unmoved) << threads;
      EXPECT_EQ(many.neighbour_disorder, one.neighbour_disorder) << threads;
      EXPECT_EQ(many.lattice_order, one.lattice_order) << threads;
    }
    std::vector<double> lengths;
    for (std::size_t i = 0; i < rows; ++i) {
      if (masked && !mask[i]) continue;
      double r2 = 0.0;
      for (int a = 0; a < n; ++a) r2 += u[i * n + static_cast<std::size_t>(a)] * u[i * n + static_cast<std::size_t>(a)];
      lengths.push_back(std::sqrt(r2));
    }
    std::sort(lengths.begin(), lengths.end());
    const std::size_t m = lengths.size();
    EXPECT_EQ(m % 2, masked ? 0u : 1u);  // both parities of the median
    EXPECT_EQ(one.median, m % 2 ? lengths[m / 2] : 0.5 * (lengths[m / 2 - 1] + lengths[m / 2]));
  }
}

}  // namespace
}  // namespace dfvn
