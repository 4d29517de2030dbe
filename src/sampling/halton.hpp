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

// The radical inverse of `index` in `base`: its base-b digits mirrored about the radix point,
// sum_j d_j b^-(j+1) for index = sum_j d_j b^j.
double radical_inverse(std::uint64_t index, int base);

// The k-th prime (k = 0: 2); k < 16.
int halton_base(int axis);
// The scrambling of axis `axis` (base `base`): one permutation of {0..base-1} per digit position that
// still changes a double (floor(53 / log2 base) of them), drawn by Fisher-Yates from (seed, axis,
// position). Exposed so that a point i > 0 can be scrambled alone (the Python engines' fast_forward).
std::vector<std::vector<int>> halton_digit_permutations(int base, int axis, std::uint64_t seed);

// `count` Halton points (point 0 first) scaled to `domain`; dimension 1..16. Deterministic per seed,
// independent of the thread count; with scramble = false the seed is not used.
PointSet halton_points(int dimension, std::uint64_t count, const Box& domain, bool scramble, std::uint64_t seed,
                       int threads);

}  // namespace dfvn
