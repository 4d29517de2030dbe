#include "dfvn/noise/simplex_noise.hpp"

#include <cmath>

#include "test_support.hpp"

namespace dfvn {
namespace {

using testing::AllDimensions;

template <typename D>
class SimplexNoiseTest : public ::testing::Test {};
TYPED_TEST_SUITE(SimplexNoiseTest, AllDimensions);

constexpr std::uint64_t kSeed = 20251215;

TYPED_TEST(SimplexNoiseTest, AnalyticGradientMatchesCentralDifferences) {
  constexpr int N = TypeParam::value;
  const SimplexNoise<N> noise(kSeed);
  const double h = 1e-6;
  double worst = 0.0;
  int active = 0;
  for (std::uint64_t i = 0; i < 400; ++i) {
    const Vec<N> x = testing::random_point<N>(kSeed, i);
    const auto s = noise.evaluate_all(x);
    for (int m = 0; m < N - 1; ++m) {
      double scale = s.gradient[m].norm();
      if (scale < 1e-6) continue;  // outside every kernel: both sides are ~0
      ++active;
      for (int j = 0; j < N; ++j) {
        Vec<N> xp = x, xm = x;
        xp[j] += h;
        xm[j] -= h;
        const double fd = (noise.evaluate_all(xp).value[m] - noise.evaluate_all(xm).value[m]) / (2 * h);
        worst = std::max(worst, std::abs(fd - s.gradient[m][j]) / scale);
      }
    }
  }
  this->RecordProperty("max_relative_error", std::to_string(worst));
  EXPECT_GT(active, 50) << "too few points inside a kernel to test anything";
  EXPECT_LT(worst, 1e-5) << "seed " << kSeed;
}

// Walk finely along random segments that cross many simplex faces. A C^1 function obeys
// |f(x + h u) - f(x) - h grad f(x).u| <= (h^2 / 2) max |f''| and |grad f(x + h u) - grad f(x)| <= h max |f''|;
// a jump across a face (the defect of a kernel radius above 1/sqrt(2)) breaks both by orders of magnitude.
TYPED_TEST(SimplexNoiseTest, ValueAndGradientAreContinuousAcrossSimplexFaces) {
  constexpr int N = TypeParam::value;
  const SimplexNoise<N> noise(kSeed);
  const double h = 1e-4;
  const int steps = 30000;  // segment length 3: crosses O(10) faces per segment
  double worst_value = 0.0, worst_gradient = 0.0;
  for (std::uint64_t segment = 0; segment < 6; ++segment) {
    Vec<N> x = testing::random_point<N>(kSeed + 1, segment);
    const Vec<N> u = testing::random_direction<N>(kSeed + 1, segment);
    auto previous = noise.evaluate_all(x);
    for (int k = 0; k < steps; ++k) {
      x += h * u;
      const auto current = noise.evaluate_all(x);
      for (int m = 0; m < N - 1; ++m) {
        const double predicted = 0.5 * h * (previous.gradient[m] + current.gradient[m]).dot(u);
        worst_value = std::max(worst_value, std::abs(current.value[m] - previous.value[m] - predicted));
        worst_gradient = std::max(worst_gradient, (current.gradient[m] - previous.gradient[m]).norm());
      }
      previous = current;
    }
  }
  // The raw noise has |f''| below ~10 and |f'''| below ~100, so the trapezoid value error is
  // O(h^3 |f'''|) ~ 1e-10 and the gradient change O(h |f''|) ~ 1e-3.
  EXPECT_LT(worst_value, 1e-9);
  EXPECT_LT(worst_gradient, 5e-3);
}

TYPED_TEST(SimplexNoiseTest, FusedTraversalEqualsSeparateTraversals) {
  constexpr int N = TypeParam::value;
  const SimplexNoise<N> noise(kSeed);
  for (std::uint64_t i = 0; i < 200; ++i) {
    const Vec<N> x = testing::random_point<N>(kSeed + 2, i);
    const auto fused = noise.evaluate_all(x);
    for (int m = 0; m < N - 1; ++m) {
      const auto single = noise.template evaluate<1>(x, m);
      EXPECT_EQ(single.value[0], fused.value[m]);
      EXPECT_EQ(single.gradient[0], fused.gradient[m]);
    }
  }
}

TYPED_TEST(SimplexNoiseTest, SeedDeterminesTheFunctions) {
  constexpr int N = TypeParam::value;
  const SimplexNoise<N> a(kSeed), b(kSeed), c(kSeed + 1);
  int differ = 0;
  for (std::uint64_t i = 0; i < 100; ++i) {
    const Vec<N> x = testing::random_point<N>(kSeed + 3, i);
    EXPECT_EQ(a.evaluate_all(x).value, b.evaluate_all(x).value);
    differ += a.evaluate_all(x).value[0] != c.evaluate_all(x).value[0];
  }
  EXPECT_GT(differ, 50);
}

// The N-1 functions of one traversal must be statistically independent: sample correlation ~ 0.
// The values are heavy-tailed in high dimensions (mostly ~0 with rare bumps), so each covariance is
// compared with its own standard error under independence, sqrt(mean(a^2 b^2) / n), not 1/sqrt(n).
TYPED_TEST(SimplexNoiseTest, FunctionsAreUncorrelated) {
  constexpr int N = TypeParam::value;
  if constexpr (N >= 3) {
    const SimplexNoise<N> noise(kSeed);
    const int samples = 60000;
    std::vector<std::array<double, N - 1>> values(samples);
    std::array<double, N - 1> mean{};
    for (int i = 0; i < samples; ++i) {
      values[i] = noise.evaluate_all(testing::random_point<N>(kSeed + 4, static_cast<std::uint64_t>(i), 0.0, 1000.0)).value;
      for (int a = 0; a < N - 1; ++a) mean[a] += values[i][a] / samples;
    }
    double worst_z = 0.0, worst_correlation = 0.0;
    for (int a = 0; a < N - 1; ++a)
      for (int b = 0; b < a; ++b) {
        double cov = 0.0, cov2 = 0.0, va = 0.0, vb = 0.0;
        for (const auto& v : values) {
          const double da = v[a] - mean[a], db = v[b] - mean[b];
          cov += da * db;
          cov2 += da * da * db * db;
          va += da * da;
          vb += db * db;
        }
        worst_z = std::max(worst_z, std::abs(cov) / std::sqrt(cov2));
        worst_correlation = std::max(worst_correlation, std::abs(cov) / std::sqrt(va * vb));
      }
    this->RecordProperty("max_abs_correlation", std::to_string(worst_correlation));
    std::printf("N=%d max |correlation| %.4f, max z %.2f\n", N, worst_correlation, worst_z);
    // With up to 21 pairs, 4.5 standard errors is a false-alarm rate below 1e-4.
    EXPECT_LT(worst_z, 4.5) << "seed " << kSeed;
    EXPECT_LT(worst_correlation, 0.1);
  }
}

}  // namespace
}  // namespace dfvn
