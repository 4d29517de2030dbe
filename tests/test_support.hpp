// Shared helpers for the typed dimension sweeps.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <type_traits>

#include "dfvn/core/dimension.hpp"
#include "dfvn/core/hash.hpp"
#include "dfvn/core/point_set.hpp"
#include "dfvn/noise/noise_functions.hpp"
#include "dfvn/sampling/lattice.hpp"

namespace dfvn::testing {

// The ASan + UBSan build (scripts/build --sanitize) runs every test, the heaviest statistical sweeps on
// fewer points: the sanitizers look for memory errors and undefined behaviour in the same code paths,
// which run 8-10x slower there, and the Release pass keeps the full sizes and the same thresholds.
#ifdef DFVN_SANITIZED_TESTS
inline constexpr bool kSanitized = true;
#else
inline constexpr bool kSanitized = false;
#endif
// n in the Release build, n / divisor (at least 1) in the sanitizer build.
constexpr std::uint64_t sanitizer_scaled(std::uint64_t n, std::uint64_t divisor) {
  return kSanitized ? std::max<std::uint64_t>(1, n / divisor) : n;
}

template <int N>
using Dim = std::integral_constant<int, N>;
using AllDimensions = ::testing::Types<Dim<2>, Dim<3>, Dim<4>, Dim<5>, Dim<6>, Dim<7>, Dim<8>>;

// A (noise basis, dimension) pair for sweeps over every basis and dimension.
template <NoiseBasis B, int N>
struct BasisDim {
  static constexpr NoiseBasis basis = B;
  static constexpr int dimension = N;
};
#define DFVN_BASIS_DIMENSIONS(B) \
  BasisDim<B, 2>, BasisDim<B, 3>, BasisDim<B, 4>, BasisDim<B, 5>, BasisDim<B, 6>, BasisDim<B, 7>, BasisDim<B, 8>
using AllBasesAndDimensions =
    ::testing::Types<DFVN_BASIS_DIMENSIONS(NoiseBasis::simplex), DFVN_BASIS_DIMENSIONS(NoiseBasis::turning_bands),
                     DFVN_BASIS_DIMENSIONS(NoiseBasis::simplex_separate)>;
// The bases meant to be healthy in every dimension (not the paper's simplex construction, fused or separate).
using HealthyBasesAndDimensions = ::testing::Types<DFVN_BASIS_DIMENSIONS(NoiseBasis::turning_bands)>;

// Names the typed tests "turning-bands_7D" rather than by an index.
struct BasisDimName {
  template <typename T>
  static std::string GetName(int) {
    return std::string(to_string(T::basis)) + "_" + std::to_string(T::dimension) + "D";
  }
};

// The fair protocol's cell-centred lattice of side^dimension sites, scaled into `box` (box.lo + box.side x:
// exact ties on most axes), with box as its domain.
inline PointSet fair_lattice_in(int dimension, int side, const Box& box) {
  const LatticeSpec l{dimension, side, Protocol::fair};
  PointSet lattice{dimension, Coordinates(l.point_count() * static_cast<std::size_t>(dimension)), box};
  for (std::uint64_t i = 0; i < l.point_count(); ++i) l.point(i, lattice.coordinates.data() + static_cast<std::size_t>(dimension) * i);
  for (double& x : lattice.coordinates) x = box.lo + box.side * x;
  return lattice;
}

// A reproducible point in [lo, hi]^N: randomness is keyed by (seed, index), never by time.
template <int N>
Vec<N> random_point(std::uint64_t seed, std::uint64_t index, double lo = -20.0, double hi = 20.0) {
  Vec<N> x;
  for (int j = 0; j < N; ++j)
    x[j] = lo + (hi - lo) * random_unit(seed, Stream::test, index, static_cast<std::uint64_t>(j));
  return x;
}

// A direction uniformly distributed on the unit sphere (normalised Gaussian by Box-Muller).
template <int N>
Vec<N> random_direction(std::uint64_t seed, std::uint64_t index) {
  Vec<N> v;
  for (int j = 0; j < N; ++j) {
    const double u1 = 1.0 - random_unit(seed, Stream::test, index, 2 * j + 1000);
    const double u2 = random_unit(seed, Stream::test, index, 2 * j + 1001);
    v[j] = std::sqrt(-2.0 * std::log(u1)) * std::cos(6.283185307179586 * u2);
  }
  return v.normalized();
}

}  // namespace dfvn::testing
