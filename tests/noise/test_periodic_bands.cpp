// The periodic form of turning-bands noise (noise/turning_bands.hpp), the torus's basis: period 1 along
// every axis, analytic gradients, the realised frequency near the asked one, swept over 2D-8D.
#include <cmath>
#include <cstdio>
#include <numbers>

#include "dfvn/core/simd.hpp"
#include "dfvn/noise/noise_functions.hpp"
#include "dfvn/noise/turning_bands.hpp"
#include "test_support.hpp"

namespace dfvn {
namespace {

template <typename T>
class PeriodicBandsTest : public ::testing::Test {};
TYPED_TEST_SUITE(PeriodicBandsTest, testing::AllDimensions);

constexpr std::uint64_t kSeed = 11;

// f(x + e_j) = f(x) and grad f(x + e_j) = grad f(x) to 1e-12, for random x in [-3, 3]^N, every axis and
// shifts of one and of several periods.
TYPED_TEST(PeriodicBandsTest, RepeatsWithPeriodOneAlongEveryAxis) {
  constexpr int N = TypeParam::value;
  for (const double frequency : {0.3, 1.2, 4.0, 17.0}) {
    const TurningBandsNoise<N> noise(kSeed, typename TurningBandsNoise<N>::Periodic{frequency});
    double worst = 0.0, size = 0.0;
    for (std::uint64_t i = 0; i < 200; ++i) {
      const Vec<N> x = testing::random_point<N>(kSeed, i, -3.0, 3.0);
      const auto a = noise.evaluate(x);
      for (int j = 0; j < N; ++j)
        for (const double shift : {1.0, -1.0, 5.0}) {
          Vec<N> y = x;
          y[j] += shift;
          const auto b = noise.evaluate(y);
          for (int f = 0; f < N - 1; ++f) {
            worst = std::max(worst, std::abs(a.value[f] - b.value[f]));
            worst = std::max(worst, (a.gradient[f] - b.gradient[f]).cwiseAbs().maxCoeff());
            size = std::max(size, a.gradient[f].cwiseAbs().maxCoeff());
          }
        }
    }
    EXPECT_LT(worst, 1e-12 * std::max(1.0, size)) << N << "D, frequency " << frequency;
    EXPECT_GT(size, 0.1);  // not periodic by being constant
  }
}

template <int N>
double central_difference_error(const TurningBandsNoise<N>& noise, const Vec<N>& x, double h) {
  const auto s = noise.evaluate(x);
  double worst = 0.0;
  for (int f = 0; f < N - 1; ++f) {
    Vec<N> numeric;
    for (int j = 0; j < N; ++j) {
      Vec<N> xp = x, xm = x;
      xp[j] += h;
      xm[j] -= h;
      numeric[j] = (noise.evaluate(xp).value[f] - noise.evaluate(xm).value[f]) / (2.0 * h);
    }
    worst = std::max(worst, (numeric - s.gradient[f]).norm() / std::max(1.0, s.gradient[f].norm()));
  }
  return worst;
}

TYPED_TEST(PeriodicBandsTest, GradientMatchesCentralDifferences) {
  constexpr int N = TypeParam::value;
  const TurningBandsNoise<N> noise(kSeed, typename TurningBandsNoise<N>::Periodic{2.5});
  double worst = 0.0;
  for (std::uint64_t i = 0; i < 100; ++i)
    worst = std::max(worst, central_difference_error<N>(noise, testing::random_point<N>(kSeed, i, 0.0, 1.0), 1e-6));
  EXPECT_LT(worst, 1e-6);
}

// Every knot vector has even integer entries (so that neighbouring knots keep independent slopes) and
// the realised frequency, wavenumber / 2 pi, is within 10% of the asked one from about 1.2 cycles per
// unit length on; below, the lowest periodic frequency (knot vectors 2 e_j) is what there is.
TYPED_TEST(PeriodicBandsTest, KnotVectorsAreEvenIntegersAndTheFrequencyFollows) {
  constexpr int N = TypeParam::value;
  for (const double frequency : {0.2, 1.2, 2.0, 6.0, 30.0}) {
    const TurningBandsNoise<N> noise(kSeed, typename TurningBandsNoise<N>::Periodic{frequency});
    EXPECT_TRUE(noise.periodic());
    const auto v = noise.directions();
    for (int b = 0; b < v.rows(); ++b) {
      EXPECT_FALSE(v.row(b).isZero());
      for (int j = 0; j < N; ++j) EXPECT_EQ(std::fmod(v(b, j), 2.0), 0.0) << v.row(b);
    }
    const double realised = noise.wavenumber() / (2.0 * std::numbers::pi);
    std::printf("N=%d asked %.2f cycles per unit length, realised %.3f\n", N, frequency, realised);
    if (frequency >= 1.2)
      EXPECT_NEAR(realised / frequency, 1.0, 0.1);
    else
      EXPECT_GE(realised, frequency);
  }
}

// The aperiodic form is untouched: its directions are unit frame rows and it is not periodic.
TEST(PeriodicBands, AperiodicFormKeepsItsFrames) {
  const TurningBandsNoise<4> noise(kSeed);
  EXPECT_FALSE(noise.periodic());
  EXPECT_NEAR(noise.directions().rowwise().norm().minCoeff(), 1.0, 1e-12);
}

TEST(PeriodicBands, SimdBuildsGiveTheSameBits) {
  if (!cpu_has_avx2()) GTEST_SKIP() << "this CPU has neither AVX2 nor AVX-512: one build only";
  const TurningBandsNoise<7> best(kSeed, TurningBandsNoise<7>::Periodic{1.2}, Simd::best);
  const TurningBandsNoise<7> baseline(kSeed, TurningBandsNoise<7>::Periodic{1.2}, Simd::baseline);
  for (std::uint64_t i = 0; i < 500; ++i) {
    const Vec<7> x = testing::random_point<7>(kSeed, i, -1e3, 1e3);
    const auto a = best.evaluate(x), b = baseline.evaluate(x);
    for (int f = 0; f < 6; ++f) {
      ASSERT_EQ(a.value[f], b.value[f]);
      ASSERT_EQ(a.gradient[f], b.gradient[f]);
    }
  }
}

TEST(PeriodicBands, OnlyTurningBandsHasAPeriodicForm) {
  EXPECT_NO_THROW(make_periodic_noise_functions<3>(NoiseBasis::turning_bands, kSeed, 2.0));
  EXPECT_THROW(make_periodic_noise_functions<3>(NoiseBasis::simplex, kSeed, 2.0), std::invalid_argument);
  EXPECT_THROW(make_periodic_noise_functions<3>(NoiseBasis::quintic_gradient, kSeed, 2.0), std::invalid_argument);
  for (const double bad : {0.0, -1.0, std::nan(""), 1e7})
    EXPECT_THROW(make_periodic_noise_functions<3>(NoiseBasis::turning_bands, kSeed, bad), std::invalid_argument) << bad;
}

}  // namespace
}  // namespace dfvn
