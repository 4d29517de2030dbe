// Quintic gradient noise: analytic gradient, C2 continuity across cell faces, lattice values, and the
// closed-form moments (k_eff, RMS |c| = 1) measured over space, in every dimension 2..8.
#include "dfvn/noise/gradient_noise.hpp"

#include <cmath>

#include "dfvn/field/dfvn_field.hpp"
#include "test_support.hpp"

namespace dfvn {
namespace {

using testing::AllDimensions;

template <typename D>
class GradientNoiseTest : public ::testing::Test {};
TYPED_TEST_SUITE(GradientNoiseTest, AllDimensions);

constexpr std::uint64_t kSeed = 20251121;

TYPED_TEST(GradientNoiseTest, AnalyticGradientMatchesCentralDifferences) {
  constexpr int N = TypeParam::value;
  const QuinticGradientNoise<N> noise(kSeed);
  const double h = 1e-6;
  double worst = 0.0;
  const std::uint64_t points = N <= 6 ? 200 : 50;  // an 8D evaluation visits 7 x 256 corners
  for (std::uint64_t i = 0; i < points; ++i) {
    const Vec<N> x = testing::random_point<N>(kSeed, i);
    const auto s = noise.evaluate(x);
    for (int m = 0; m < N - 1; ++m) {
      const double scale = std::max(s.gradient[m].norm(), 1e-3);
      for (int j = 0; j < N; ++j) {
        Vec<N> xp = x, xm = x;
        xp[j] += h;
        xm[j] -= h;
        const double fd = (noise.evaluate(xp).value[m] - noise.evaluate(xm).value[m]) / (2 * h);
        worst = std::max(worst, std::abs(fd - s.gradient[m][j]) / scale);
      }
    }
  }
  std::printf("%dD: max relative error %.2e (seed %llu)\n", N, worst, static_cast<unsigned long long>(kSeed));
  EXPECT_LT(worst, 1e-5) << "seed " << kSeed;
}

// Walk finely along random segments that cross many cell faces (see the simplex test for the bounds):
// for a C1 function the trapezoid rule predicts the value change to O(h^3 |n'''|) and the gradient
// changes by O(h |n''|) per step; a kink or jump at a face breaks both by orders of magnitude.
TYPED_TEST(GradientNoiseTest, ValueAndGradientAreContinuousAcrossCellFaces) {
  constexpr int N = TypeParam::value;
  const QuinticGradientNoise<N> noise(kSeed);
  const double h = 2e-4;
  const int steps = N <= 6 ? 10000 : 3000;  // segment length 2 (0.6): dozens of face crossings in all
  double worst_value = 0.0, worst_gradient = 0.0;
  for (std::uint64_t segment = 0; segment < 3; ++segment) {
    Vec<N> x = testing::random_point<N>(kSeed + 1, segment);
    const Vec<N> u = testing::random_direction<N>(kSeed + 1, segment);
    auto previous = noise.evaluate(x);
    for (int k = 0; k < steps; ++k) {
      x += h * u;
      const auto current = noise.evaluate(x);
      for (int m = 0; m < N - 1; ++m) {
        const double predicted = 0.5 * h * (previous.gradient[m] + current.gradient[m]).dot(u);
        worst_value = std::max(worst_value, std::abs(current.value[m] - previous.value[m] - predicted));
        worst_gradient = std::max(worst_gradient, (current.gradient[m] - previous.gradient[m]).norm());
      }
      previous = current;
    }
  }
  std::printf("%dD: worst value defect %.2e, worst gradient step %.2e\n", N, worst_value, worst_gradient);
  // The noise's second derivatives grow with the 2^N corners but stay below ~10 N here, its third below
  // ~100 N: value defect ~h^3 100 N < 1e-8, gradient step ~h 10 N < 2e-2. A gradient jump at a face
  // would be O(1), a value jump O(0.1).
  EXPECT_LT(worst_value, 1e-8);
  EXPECT_LT(worst_gradient, 2e-2);
}

TYPED_TEST(GradientNoiseTest, VanishesAtLatticePointsWithTheHashedGradient) {
  constexpr int N = TypeParam::value;
  const QuinticGradientNoise<N> noise(kSeed);
  // Function 0 is axis-aligned: its lattice point k sits at x = k - o_0, where n_0 = 0 and
  // grad n_0 = g_0k. Rounding may put y = x + o_0 just below k (u ~ 1 in the cell before), so compare
  // with a tolerance well above rounding and far below the O(1) size of a gradient.
  for (std::uint64_t i = 0; i < 50; ++i) {
    std::array<std::int64_t, N> lattice;
    const Vec<N> p = testing::random_point<N>(kSeed + 2, i);
    for (int d = 0; d < N; ++d) lattice[d] = static_cast<std::int64_t>(std::floor(p[d]));
    Vec<N> x;
    for (int d = 0; d < N; ++d) x[d] = static_cast<double>(lattice[d]) - noise.offset(0)[d];
    const auto s = noise.evaluate(x);
    const Vec<N> g = noise.lattice_gradient(0, lattice);
    EXPECT_NEAR(s.value[0], 0.0, 1e-12) << "lattice point " << i;
    EXPECT_LT((s.gradient[0] - g).norm(), 1e-10) << "lattice point " << i;
    EXPECT_LE(g.cwiseAbs().maxCoeff(), 1.0);
  }
}

// The closed-form moments against space averages over random points spread across ~40 cells per axis.
TYPED_TEST(GradientNoiseTest, MeasuredWavenumberMatchesTheClosedForm) {
  constexpr int N = TypeParam::value;
  const QuinticGradientNoise<N> noise(kSeed);
  const int samples = N <= 5 ? 40000 : 10000;
  double value2 = 0.0, gradient2 = 0.0;
  for (int i = 0; i < samples; ++i) {
    const auto s = noise.evaluate(testing::random_point<N>(kSeed + 3, static_cast<std::uint64_t>(i)));
    for (int m = 0; m < N - 1; ++m) {
      value2 += s.value[m] * s.value[m];
      gradient2 += s.gradient[m].squaredNorm();
    }
  }
  const GradientNoiseMoments exact = quintic_gradient_noise_moments(N);
  const double functions = samples * (N - 1.0);
  std::printf("%dD: E n^2 %.5f (closed form %.5f), E|grad n|^2 %.4f (%.4f), k_eff %.4f (%.4f)\n", N,
              value2 / functions, exact.value2, gradient2 / functions, exact.gradient2,
              std::sqrt(gradient2 / value2), noise.wavenumber());
  // Monte Carlo with >= 10^4 samples of quantities with a relative spread of ~1: a few percent.
  EXPECT_NEAR(value2 / functions / exact.value2, 1.0, 0.05);
  EXPECT_NEAR(gradient2 / functions / exact.gradient2, 1.0, 0.03);
  EXPECT_NEAR(std::sqrt(gradient2 / value2) / noise.wavenumber(), 1.0, 0.03);
}

TYPED_TEST(GradientNoiseTest, FieldHasUnitRmsSpeed) {
  constexpr int N = TypeParam::value;
  const DfvnField<N> field(kSeed, FieldOptions{NoiseBasis::quintic_gradient, 0.5});
  const int samples = N <= 5 ? 40000 : 10000;
  double speed2 = 0.0;
  for (int i = 0; i < samples; ++i)
    speed2 += field.velocity(testing::random_point<N>(kSeed + 4, static_cast<std::uint64_t>(i))).squaredNorm();
  const double rms = std::sqrt(speed2 / samples);
  std::printf("%dD: RMS |c| = %.4f over %d points (seed %llu)\n", N, rms, samples, static_cast<unsigned long long>(kSeed));
  EXPECT_NEAR(rms, 1.0, 0.05);
}

TEST(GradientNoise, TwoDimensionalMomentsHaveTheirExactValues) {
  // E n^2 = (2/3) (2A) (2B) and E|grad n|^2 = (2/3) [(2A)(2B') + (2A')(2B)] with A = 181/462,
  // A' = 10/7, B = 535/18018, B' = 30/77 (exact rational integrals, checked with Python fractions).
  // The code expands the polynomials in doubles: cancellation costs a few units of 1e-14.
  const double a = 181.0 / 462, da = 10.0 / 7, b = 535.0 / 18018, db = 30.0 / 77;
  const GradientNoiseMoments m = quintic_gradient_noise_moments(2);
  EXPECT_NEAR(m.value2 / ((2.0 / 3) * (2 * a) * (2 * b)), 1.0, 1e-12);
  EXPECT_NEAR(m.gradient2 / ((2.0 / 3) * ((2 * a) * (2 * db) + (2 * da) * (2 * b))), 1.0, 1e-12);
}

}  // namespace
}  // namespace dfvn
