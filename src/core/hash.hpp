// Counter-based randomness: every random number is a pure function of (seed, stream, index), so
// results never depend on thread count or scheduling (STYLE.md, "Randomness").
#pragma once

#include <cstdint>

namespace dfvn {

// The finaliser of SplitMix64 (Steele, Lea and Flood 2014): a bijection on 64-bit words with full
// avalanche, so consecutive counters give statistically independent outputs.
constexpr std::uint64_t mix64(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

// Golden-ratio increment of SplitMix64; used to separate streams and counters before mixing.
inline constexpr std::uint64_t kGoldenGamma = 0x9E3779B97F4A7C15ULL;

constexpr std::uint64_t hash_combine(std::uint64_t h, std::uint64_t value) {
  return mix64(h ^ (value + kGoldenGamma + (h << 6) + (h >> 2)));
}

// Named streams keep the generators of different methods apart even with the same seed.
enum class Stream : std::uint64_t {
  noise = 1,
  jitter = 2,
  random_points = 3,
  poisson_disk = 4,
  sobol_scramble = 5,
  rdf_queries = 6,
  turning_bands = 7,
  field_diagnosis = 8,
  gradient_noise = 9,
  halton_scramble = 10,
  latin_hypercube = 11,
  genz = 12,
  sphere_points = 13,
  test = 99,
};

// The key of (seed, stream); loops that draw many numbers of one stream hash it once.
constexpr std::uint64_t stream_key(std::uint64_t seed, Stream stream) {
  return hash_combine(mix64(seed), static_cast<std::uint64_t>(stream));
}

// A 64-bit random word for (seed, stream, index, lane):
// hash_combine(hash_combine(stream_key(seed, stream), index), lane).
constexpr std::uint64_t random_bits(std::uint64_t seed, Stream stream, std::uint64_t index,
                                    std::uint64_t lane = 0) {
  return hash_combine(hash_combine(stream_key(seed, stream), index), lane);
}

// Uniform double in [0, 1) with 53 random bits.
constexpr double bits_to_unit(std::uint64_t bits) {
  return static_cast<double>(bits >> 11) * 0x1.0p-53;
}

constexpr double random_unit(std::uint64_t seed, Stream stream, std::uint64_t index,
                             std::uint64_t lane = 0) {
  return bits_to_unit(random_bits(seed, stream, index, lane));
}

}  // namespace dfvn
