#include "dfvn/sampling/halton.hpp"

#include <array>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <vector>

#include "dfvn/core/hash.hpp"
#include "dfvn/core/parallel.hpp"

namespace dfvn {

namespace {

constexpr std::array<int, 16> kPrimes = {2, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37, 41, 43, 47, 53};

// Digit positions that still change a double in [0, 1): b^-m >= 2^-53, m = floor(53 / log2 b).
int significant_digits(int base) { return static_cast<int>(std::floor(53.0 / std::log2(static_cast<double>(base)))); }

}  // namespace

int halton_base(int axis) {
  if (axis < 0 || axis >= static_cast<int>(kPrimes.size()))
    throw std::invalid_argument("Halton points are available in 1.." + std::to_string(kPrimes.size()) + " dimensions");
  return kPrimes[static_cast<std::size_t>(axis)];
}

std::vector<std::vector<int>> halton_digit_permutations(int base, int axis, std::uint64_t seed) {
  std::vector<std::vector<int>> permutations(static_cast<std::size_t>(significant_digits(base)));
  for (std::size_t position = 0; position < permutations.size(); ++position) {
    auto& p = permutations[position];
    p.resize(static_cast<std::size_t>(base));
    std::iota(p.begin(), p.end(), 0);
    const std::uint64_t stream_index = static_cast<std::uint64_t>(axis) * 1024 + position;
    for (int k = base - 1; k > 0; --k) {
      const auto pick = static_cast<int>(random_bits(seed, Stream::halton_scramble, stream_index, static_cast<std::uint64_t>(k)) %
                                         static_cast<std::uint64_t>(k + 1));
      std::swap(p[static_cast<std::size_t>(k)], p[static_cast<std::size_t>(pick)]);
    }
  }
  return permutations;
}

double radical_inverse(std::uint64_t index, int base) {
  const double inverse_base = 1.0 / base;
  double value = 0.0, scale = inverse_base;
  for (; index > 0; index /= static_cast<std::uint64_t>(base), scale *= inverse_base)
    value += static_cast<double>(index % static_cast<std::uint64_t>(base)) * scale;
  return value;
}

PointSet halton_points(int dimension, std::uint64_t count, const Box& domain, bool scramble, std::uint64_t seed,
                       int threads) {
  std::vector<std::vector<std::vector<int>>> permutations;
  for (int k = 0; k < dimension; ++k)
    permutations.push_back(scramble ? halton_digit_permutations(halton_base(k), k, seed) : std::vector<std::vector<int>>{});
  PointSet out{dimension, Coordinates(count * static_cast<std::uint64_t>(dimension)), domain};
#pragma omp parallel for schedule(static) num_threads(resolve_threads(threads)) if (worth_threads(out.coordinates.size()))
  for (std::int64_t i = 0; i < static_cast<std::int64_t>(count); ++i) {
    for (int k = 0; k < dimension; ++k) {
      const int base = halton_base(k);
      double unit;
      if (!scramble) {
        unit = radical_inverse(static_cast<std::uint64_t>(i), base);
      } else {
        // Every significant position is permuted, so the zeros above the index's last digit become
        // random digits too (otherwise all points would share a zero tail and a bias towards 0).
        const double inverse_base = 1.0 / base;
        auto index = static_cast<std::uint64_t>(i);
        double scale = inverse_base;
        unit = 0.0;
        for (const auto& permutation : permutations[static_cast<std::size_t>(k)]) {
          unit += permutation[index % static_cast<std::uint64_t>(base)] * scale;
          index /= static_cast<std::uint64_t>(base);
          scale *= inverse_base;
        }
      }
      out.coordinates[static_cast<std::size_t>(i) * dimension + k] = domain.lo + domain.side * unit;
    }
  }
  return out;
}

}  // namespace dfvn
