#include "dfvn/sampling/annulus.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "dfvn/core/dimension.hpp"

namespace dfvn {
namespace {

// Kolmogorov-Smirnov distance between the samples' empirical CDF and `cdf` (sorts the samples).
template <class Cdf>
double ks_distance(std::vector<double>& samples, const Cdf& cdf) {
  std::sort(samples.begin(), samples.end());
  const double n = static_cast<double>(samples.size());
  double d = 0.0;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const double f = cdf(samples[i]);
    d = std::max({d, f - static_cast<double>(i) / n, static_cast<double>(i + 1) / n - f});
  }
  return d;
}

// The K-S distance that a correct sampler exceeds with probability 0.1% (1.95 / sqrt(n)).
double ks_bound(std::size_t n) { return 1.95 / std::sqrt(static_cast<double>(n)); }

TEST(NormalZiggurat, TailStartsWhereMarsagliaAndTsangPutIt) {
  // Their table for 256 strips: r = 3.6541528853610088 (derived here by bisection).
  EXPECT_NEAR(NormalZiggurat::instance().tail_start(), 3.6541528853610088, 1e-12);
}

TEST(NormalZiggurat, DrawsTheStandardNormalDistribution) {
  const NormalZiggurat& normal = NormalZiggurat::instance();
  const std::size_t n = 1000000;
  std::vector<double> x(n);
  RandomWords words{hash_combine(stream_key(42, Stream::test), 1)};
  double sum = 0.0, sum2 = 0.0;
  std::size_t beyond_tail = 0;
  for (double& v : x) {
    v = normal(words);
    sum += v;
    sum2 += v * v;
    beyond_tail += std::abs(v) > normal.tail_start();
  }
  const double mean = sum / n, variance = sum2 / n - mean * mean;
  EXPECT_LT(std::abs(mean), 5.0 / std::sqrt(n));
  EXPECT_LT(std::abs(variance - 1.0), 5.0 * std::sqrt(2.0 / n));
  // The tail's own sampler: P(|x| > r) = erfc(r / sqrt 2) = 2.58e-4, ~258 of 10^6 (Poisson sd 16).
  const double expected = n * std::erfc(normal.tail_start() / std::sqrt(2.0));
  EXPECT_NEAR(static_cast<double>(beyond_tail), expected, 5.0 * std::sqrt(expected));
  const double d = ks_distance(x, [](double v) { return 0.5 * std::erfc(-v / std::sqrt(2.0)); });
  std::printf("K-S distance to the normal CDF %.5f (0.1%% bound %.5f); %zu beyond the tail start, %.0f expected\n", d,
              ks_bound(n), beyond_tail, expected);
  EXPECT_LT(d, ks_bound(n));
}

// Uniform in the volume of r <= |d| <= 2r, 2D-8D: |d|^N is uniform in [r^N, (2r)^N], and d / |d| has
// the moments of a uniform direction (E u_j = 0, E u_j^2 = 1/N, E u_j u_k = 0 for j != k).
TEST(UniformInAnnulus, IsUniformInTheAnnulusVolume) {
  for (int dimension = 2; dimension <= 8; ++dimension) {
    dispatch_dimension(dimension, [&]<int N>() {
      const double r = 0.3;
      const std::size_t n = 40000;
      const NormalZiggurat& normal = NormalZiggurat::instance();
      std::vector<double> volume_fraction(n);
      double mean[N] = {}, square[N] = {}, cross = 0.0;
      for (std::size_t i = 0; i < n; ++i) {
        RandomWords words{hash_combine(stream_key(7, Stream::test), i)};
        double d[N];
        uniform_in_annulus<N>(words, normal, r, d);
        double length2 = 0.0;
        for (int j = 0; j < N; ++j) length2 += d[j] * d[j];
        const double length = std::sqrt(length2);
        ASSERT_GE(length, r * (1.0 - 1e-12));
        ASSERT_LE(length, 2.0 * r * (1.0 + 1e-12));
        volume_fraction[i] = (std::pow(length, N) - std::pow(r, N)) / (std::pow(2.0 * r, N) - std::pow(r, N));
        for (int j = 0; j < N; ++j) {
          mean[j] += d[j] / length / n;
          square[j] += d[j] * d[j] / length2 / n;
        }
        cross += d[0] * d[1] / length2 / n;
      }
      // Standard deviations of the sample means: Var u_j = 1/N, Var u_j^2 = 3/(N(N+2)) - 1/N^2,
      // Var u_0 u_1 = 1/(N(N+2)).
      const double sd_mean = std::sqrt(1.0 / N / n), sd_square = std::sqrt((3.0 / (N * (N + 2.0)) - 1.0 / (N * N)) / n),
                   sd_cross = std::sqrt(1.0 / (N * (N + 2.0)) / n);
      for (int j = 0; j < N; ++j) {
        EXPECT_LT(std::abs(mean[j]), 5.0 * sd_mean) << N << "D axis " << j;
        EXPECT_LT(std::abs(square[j] - 1.0 / N), 5.0 * sd_square) << N << "D axis " << j;
      }
      EXPECT_LT(std::abs(cross), 5.0 * sd_cross) << N << "D";
      const double ks = ks_distance(volume_fraction, [](double u) { return u; });
      std::printf("%dD: K-S distance of the volume fraction to uniform %.5f (0.1%% bound %.5f)\n", N, ks, ks_bound(n));
      EXPECT_LT(ks, ks_bound(n)) << N << "D";
    });
  }
}

}  // namespace
}  // namespace dfvn
