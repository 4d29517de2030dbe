#include "dfvn/stats/spectrum.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "dfvn/sampling/jitter.hpp"
#include "dfvn/sampling/lattice.hpp"

namespace dfvn {
namespace {

// Uniform random points: E[P(k)] = 1 for every k != 0 (the cross terms average to 0), so the mean over
// 8 realizations and a shell of many frequencies is 1 within a few per cent. Seeds 1..8.
TEST(PowerSpectrum, UniformRandomPointsAreFlatAtOne) {
  for (int dimension : {2, 3}) {
    std::vector<PointSet> sets;
    for (std::uint64_t seed = 1; seed <= 8; ++seed)
      sets.push_back(uniform_random_points(dimension, 500, Box{0.0, 1.0}, seed, 0));
    const int max_frequency = dimension == 2 ? 24 : 8;
    const PowerSpectrum s = power_spectrum(sets, max_frequency, 0);
    const int zero[3] = {0, 0, 0};
    EXPECT_NEAR(s.at(zero), 500.0, 1e-9);  // DC term: n
    double mean = 0.0;
    int count = 0;
    for (std::size_t r = 1; r < s.radial_mean.size(); ++r) {
      mean += s.radial_mean[r] * s.shell_counts[r];
      count += s.shell_counts[r];
      if (s.shell_counts[r] >= 100) {
        EXPECT_NEAR(s.radial_mean[r], 1.0, 0.25) << dimension << "D shell " << r;
      }
    }
    EXPECT_NEAR(mean / count, 1.0, 0.05) << dimension << "D";
    // Isotropic: about 0 dB minus the averaging over 8 realizations (var / mean^2 = 1/8: -9 dB).
    ASSERT_TRUE(s.anisotropy_db[max_frequency / 2].has_value());
    EXPECT_NEAR(*s.anisotropy_db[max_frequency / 2], -9.0, 2.0) << dimension << "D";
  }
}

// A jittered K x K lattice keeps Bragg peaks at the multiples of K along the axes (damped by the
// jitter's characteristic function, sinc^2(pi k h / ... ) = 4/pi^2 at k = K for cell-wide jitter),
// far above the flat level of random points; between them the spectrum is low.
TEST(PowerSpectrum, JitteredLatticeShowsBraggPeaks) {
  constexpr int kGrid = 16;
  LatticeSpec lattice{2, kGrid, Protocol::fair};
  std::vector<PointSet> sets;
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    PointSet s = jittered_lattice(lattice, seed, 0);
    // Half the cell-wide jitter, so the peak stays strong: x = c + (x - c) / 2.
    for (std::size_t i = 0; i < s.size(); ++i)
      for (int a = 0; a < 2; ++a) {
        double& x = s.coordinates[i * 2 + a];
        const double centre = (std::floor(x * kGrid) + 0.5) / kGrid;
        x = centre + 0.5 * (x - centre);
      }
    sets.push_back(std::move(s));
  }
  const PowerSpectrum s = power_spectrum(sets, 2 * kGrid, 0);
  const int peak[2] = {kGrid, 0}, off_peak[2] = {kGrid / 2, 0}, diagonal_peak[2] = {kGrid, kGrid};
  EXPECT_GT(s.at(peak), 50.0);  // n |sinc(pi/2)|^2 = 256 * 0.405 = 104 expected
  EXPECT_GT(s.at(diagonal_peak), 20.0);
  EXPECT_LT(s.at(off_peak), 2.0);
}

TEST(PowerSpectrum, SameForAnyThreadCount) {
  const std::vector<PointSet> sets = {uniform_random_points(3, 200, Box{0.0, 1.0}, 3, 0)};
  EXPECT_EQ(power_spectrum(sets, 4, 1).power, power_spectrum(sets, 4, 3).power);
  EXPECT_THROW(power_spectrum({uniform_random_points(4, 10, Box{0.0, 1.0}, 3, 0)}, 4, 1), std::invalid_argument);
}

// Issue 23: three identical points have the same power n at every frequency: zero variance over every
// shell, whose anisotropy (-Inf dB) was written as -inf. It is undefined there, and written empty.
TEST(PowerSpectrum, AnisotropyOfAConstantSpectrumIsNotDefined) {
  for (int dimension : {2, 3}) {
    PointSet identical{dimension, {}, Box{0.0, 1.0}};
    for (int i = 0; i < 3; ++i)
      for (int a = 0; a < dimension; ++a) identical.coordinates.push_back(0.3 + 0.1 * a);
    const PowerSpectrum s = power_spectrum({identical}, 6, 2);
    for (std::size_t r = 1; r < s.radial_mean.size(); ++r) {
      EXPECT_NEAR(s.radial_mean[r], 3.0, 1e-12) << dimension << "D shell " << r;
      EXPECT_FALSE(s.anisotropy_db[r].has_value()) << dimension << "D shell " << r << ": " << *s.anisotropy_db[r];
    }
    // Two points half the domain apart along x0: P = 0 at odd k0, 2 at even: variance, defined anisotropy.
    const PointSet pair{dimension, dimension == 2 ? Coordinates{0.1, 0.2, 0.6, 0.2} : Coordinates{0.1, 0.2, 0.3, 0.6, 0.2, 0.3}, Box{0.0, 1.0}};
    const PowerSpectrum p = power_spectrum({pair}, 6, 2);
    for (std::size_t r = 1; r < p.radial_mean.size(); ++r) {
      ASSERT_TRUE(p.anisotropy_db[r].has_value()) << dimension << "D shell " << r;
      EXPECT_TRUE(std::isfinite(*p.anisotropy_db[r]));
    }
  }
}

}  // namespace
}  // namespace dfvn
