// Derives the per-dimension amplitudes A_N of src/noise/simplex_normalisation.hpp.
//
// Procedure: for each N, evaluate the raw field (A = 1, frequency 1) at `samples` points drawn
// uniformly from [0, 1000]^N (far more simplex cells than samples, so the points see independent
// lattice neighbourhoods), for each of `seeds` seeds, and take rms = sqrt(mean |c|^2). The field is a
// product of N-1 gradients, each scaled by A, so |c| scales by A^(N-1) and A_N = rms^(-1/(N-1)) makes
// the RMS of |c| exactly 1 on this sample. The relative standard error of the mean of |c|^2 is printed
// too; tests/field/test_normalisation.cpp re-checks RMS |c| = 1 on fresh seeds and points.
//
// Usage: derive_normalisation [samples per seed = 200000] [seeds = 8] [fused | separate]
// fused (the default): the simplex basis (kFieldAmplitudes); separate: the simplex-separate basis, one
// traversal per function at its offset (kSeparateFieldAmplitudes, noise/simplex_separate.hpp).
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "dfvn/core/dimension.hpp"
#include "dfvn/core/hash.hpp"
#include "dfvn/field/cross_product.hpp"
#include "dfvn/noise/simplex_noise.hpp"
#include "dfvn/noise/simplex_separate.hpp"

int main(int argc, char** argv) {
  const long samples = argc > 1 ? std::atol(argv[1]) : 200000;
  const int seeds = argc > 2 ? std::atoi(argv[2]) : 8;
  const bool separate = argc > 3 && std::strcmp(argv[3], "separate") == 0;
  if (samples < 100 || seeds < 1 || (argc > 3 && !separate && std::strcmp(argv[3], "fused") != 0)) {
    std::fprintf(stderr, "usage: derive_normalisation [samples>=100] [seeds>=1] [fused|separate]\n");
    return 2;
  }
  std::printf("// dim, amplitude A_N, relative standard error of mean |c|^2 (raw)\n");
  for (int n = dfvn::kMinDimension; n <= dfvn::kMaxDimension; ++n) {
    dfvn::dispatch_dimension(n, [&]<int N>() {
      double sum = 0.0, sum2 = 0.0;
      const double total = static_cast<double>(samples) * seeds;
      for (int s = 0; s < seeds; ++s) {
        const dfvn::SimplexNoise<N> noise(1000 + static_cast<std::uint64_t>(s));
        const dfvn::SimplexSeparateNoiseFunctions<N> separate_noise(1000 + static_cast<std::uint64_t>(s));
        for (long i = 0; i < samples; ++i) {
          dfvn::Vec<N> x;
          for (int j = 0; j < N; ++j)
            x[j] = 1000.0 * dfvn::random_unit(static_cast<std::uint64_t>(s), dfvn::Stream::test,
                                              static_cast<std::uint64_t>(i), static_cast<std::uint64_t>(j));
          const double c2 =
              dfvn::cross<N>(separate ? separate_noise.evaluate(x).gradient : noise.evaluate_all(x).gradient).squaredNorm();
          sum += c2;
          sum2 += c2 * c2;
        }
      }
      const double mean = sum / total;
      const double variance = sum2 / total - mean * mean;
      const double relative_error = std::sqrt(variance / total) / mean;
      const double amplitude = std::pow(std::sqrt(mean), -1.0 / (N - 1));
      std::printf("{%d, %.6g, %.2g},\n", N, amplitude, relative_error);
      return 0;
    });
  }
  return 0;
}
