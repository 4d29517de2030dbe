// Sobol points (Joe-Kuo direction numbers) with optional hash-based Owen scrambling.
#pragma once

#include <array>
#include <cstdint>
#include <string_view>
#include <vector>

#include "dfvn/core/simd.hpp"
#include "dfvn/core/point_set.hpp"

namespace dfvn {

enum class Scramble { owen, none };
Scramble parse_scramble(std::string_view name);  // "owen" | "none"
std::string_view to_string(Scramble scramble);

class SobolSequence {
 public:
  static constexpr int kBits = 32;
  // The first `dimensions` dimensions of new-joe-kuo-6.21201 (data/). Throws std::invalid_argument
  // above the 15 dimensions the table holds.
  explicit SobolSequence(int dimensions);

  int dimensions() const { return static_cast<int>(directions_.size()); }
  // The 32-bit digits of point `index` in dimension `dim` (index < 2^32); point 0 is the origin.
  // Points come in Gray-code order (point i uses the direction numbers of the bits of i ^ (i >> 1)),
  // the order of Joe and Kuo's generator and of SciPy; any 2^m first points form the same net.
  std::uint32_t digits(std::uint32_t index, int dim) const;
  // Direction number v_bit of dimension `dim`: digits(i + 1, dim) = digits(i, dim) ^ direction(dim, ctz(i + 1)),
  // since the Gray codes of i and i + 1 differ in bit ctz(i + 1) only.
  std::uint32_t direction(int dim, int bit) const { return directions_[static_cast<std::size_t>(dim)][static_cast<std::size_t>(bit)]; }

 private:
  std::vector<std::array<std::uint32_t, kBits>> directions_;
};

// Nested (Owen 1995) scrambling of 32 digits, hash-based (Burley 2020): every digit is flipped by a
// function of the seed, the dimension and the digits above it, so points that share a prefix get the
// same flips and every (0, m, s)-net stays a net.
std::uint32_t owen_scramble(std::uint32_t digits, std::uint64_t seed, int dim);

// `count` Sobol points scaled to `domain`. With Scramble::none the coordinates are digits / 2^32
// exactly; with Scramble::owen the 32 digits are scrambled and the 20 bits below them (down to 2^-52)
// are hashed uniform bits. Deterministic per seed; independent of the thread count and of `simd` (the
// scramble runs on AVX2 where the CPU has it).
PointSet sobol_points(int dimension, std::uint64_t count, const Box& domain, Scramble scramble, std::uint64_t seed,
                      int threads, Simd simd = Simd::best);
// Points first .. first + count - 1 of that set, the same bits as its rows (a streamed run's slabs).
PointSet sobol_points_range(int dimension, std::uint64_t first, std::uint64_t count, const Box& domain, Scramble scramble,
                            std::uint64_t seed, int threads, Simd simd = Simd::best);

}  // namespace dfvn
