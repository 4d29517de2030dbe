#include "dfvn/sampling/halton.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

#include "dfvn/core/hash.hpp"
#include "dfvn/core/parallel.hpp"

namespace dfvn {

namespace {

// Digit positions that still change a double in [0, 1): b^-m >= 2^-53, m = floor(53 / log2 b).
int significant_digits(int base) { return static_cast<int>(std::floor(53.0 / std::log2(static_cast<double>(base)))); }

// The permutations of a group of axes are held at once (each point then visits its coordinates in
// order); the group ends where they would pass this many ints (64 MiB), so that a high dimension,
// whose bases reach 10^5 and more, never holds every axis' permutations.
constexpr std::size_t kPermutationIntsPerGroup = std::size_t{16} << 20;

}  // namespace

std::vector<int> halton_bases(int dimension) {
  if (dimension < 1 || dimension > kHaltonMaxDimensions)
    throw std::invalid_argument("Halton points are available in 1.." + std::to_string(kHaltonMaxDimensions) +
                                " dimensions, asked for " + std::to_string(dimension));
  // The n-th prime is below n (ln n + ln ln n) for n >= 6 (Rosser 1941); 15 covers n < 6 (the 5th prime is 11).
  const double n = dimension;
  const auto bound = dimension < 6 ? std::size_t{15} : static_cast<std::size_t>(n * (std::log(n) + std::log(std::log(n)))) + 1;
  std::vector<bool> composite(bound + 1, false);
  std::vector<int> primes;
  primes.reserve(static_cast<std::size_t>(dimension));
  for (std::size_t p = 2; p <= bound && primes.size() < static_cast<std::size_t>(dimension); ++p) {
    if (composite[p]) continue;
    primes.push_back(static_cast<int>(p));
    for (std::size_t multiple = p * p; multiple <= bound; multiple += p) composite[multiple] = true;
  }
  return primes;
}

int halton_base(int axis) {
  if (axis < 0) throw std::invalid_argument("Halton axes are numbered from 0, got " + std::to_string(axis));
  return halton_bases(axis + 1).back();
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
  return halton_points_range(dimension, 0, count, domain, scramble, seed, threads);
}

PointSet halton_points_range(int dimension, std::uint64_t first, std::uint64_t count, const Box& domain, bool scramble,
                             std::uint64_t seed, int threads) {
  const std::vector<int> bases = halton_bases(dimension);
  const auto dims = static_cast<std::uint64_t>(dimension);
  PointSet out{dimension, Coordinates(count * dims), domain};
  for (int group_begin = 0; group_begin < dimension;) {
    // Axes group_begin .. group_end - 1 and their permutations (none unscrambled).
    std::vector<std::vector<std::vector<int>>> permutations;
    std::size_t ints = 0;
    int group_end = group_begin;
    do {
      const int base = bases[static_cast<std::size_t>(group_end)];
      permutations.push_back(scramble ? halton_digit_permutations(base, group_end, seed) : std::vector<std::vector<int>>{});
      ints += scramble ? static_cast<std::size_t>(significant_digits(base)) * static_cast<std::size_t>(base) : 0;
      ++group_end;
    } while (group_end < dimension && ints < kPermutationIntsPerGroup);
#pragma omp parallel for schedule(static) num_threads(resolve_threads(threads)) if (worth_threads(out.coordinates.size()))
    for (std::int64_t at = 0; at < static_cast<std::int64_t>(count); ++at) {
      const std::uint64_t i = first + static_cast<std::uint64_t>(at);
      for (int k = group_begin; k < group_end; ++k) {
        const int base = bases[static_cast<std::size_t>(k)];
        double unit;
        if (!scramble) {
          unit = radical_inverse(i, base);
        } else {
          // Every significant position is permuted, so the zeros above the index's last digit become
          // random digits too (otherwise all points would share a zero tail and a bias towards 0).
          const double inverse_base = 1.0 / base;
          std::uint64_t index = i;
          double scale = inverse_base;
          unit = 0.0;
          for (const auto& permutation : permutations[static_cast<std::size_t>(k - group_begin)]) {
            unit += permutation[index % static_cast<std::uint64_t>(base)] * scale;
            index /= static_cast<std::uint64_t>(base);
            scale *= inverse_base;
          }
        }
        out.coordinates[static_cast<std::uint64_t>(at) * dims + static_cast<std::uint64_t>(k)] = domain.lo + domain.side * unit;
      }
    }
    group_begin = group_end;
  }
  return out;
}

}  // namespace dfvn
