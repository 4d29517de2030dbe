// Halton points (Halton 1960): coordinate k of point i is the radical inverse of i in the k-th prime
// base. Scrambled by random digit permutations (Braaten and Weller 1979; the scheme of SciPy's
// qmc.Halton(scramble=True)): digit position j of base b_k is mapped through its own permutation of
// {0..b_k-1}, drawn from (seed, axis, position), for every position down to double precision, the
// leading zeros included.
#pragma once

#include <cstdint>
#include <vector>

#include "dfvn/core/point_set.hpp"

namespace dfvn {

// The dimensions Halton points are offered in: the primes stay below 2^31 and a sieve up to them below 2 GB.
inline constexpr int kHaltonMaxDimensions = 10'000'000;

// The radical inverse of `index` in `base`: its base-b digits mirrored about the radix point,
// sum_j d_j b^-(j+1) for index = sum_j d_j b^j.
double radical_inverse(std::uint64_t index, int base);

// The first `dimension` primes (2, 3, 5, ...), the bases of axes 0..dimension-1, by a sieve of
// Eratosthenes; throws std::invalid_argument outside 1..kHaltonMaxDimensions.
std::vector<int> halton_bases(int dimension);
// The base of one axis (axis 0: 2), halton_bases(axis + 1)'s last.
int halton_base(int axis);
// The scrambling of axis `axis` (base `base`): one permutation of {0..base-1} per digit position that
// still changes a double (floor(53 / log2 base) of them), drawn by Fisher-Yates from (seed, axis,
// position). Exposed so that a point i > 0 can be scrambled alone.
std::vector<std::vector<int>> halton_digit_permutations(int base, int axis, std::uint64_t seed);

// `count` Halton points (point 0 first) scaled to `domain`; dimension 1..kHaltonMaxDimensions.
// Deterministic per seed, independent of the thread count; with scramble = false the seed is not used.
PointSet halton_points(int dimension, std::uint64_t count, const Box& domain, bool scramble, std::uint64_t seed,
                       int threads);
// Points first .. first + count - 1 of that sequence, the same bits as its rows.
PointSet halton_points_range(int dimension, std::uint64_t first, std::uint64_t count, const Box& domain, bool scramble,
                             std::uint64_t seed, int threads);

}  // namespace dfvn
