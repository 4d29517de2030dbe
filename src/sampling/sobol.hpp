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

// The dimensions of Joe and Kuo's table new-joe-kuo-6.21201 (data/joe_kuo_directions.md), compiled in.
inline constexpr int kSobolMaxDimensions = 21201;

// One row of the table: dimension d's primitive polynomial x^s + a_1 x^(s-1) + ... + a_(s-1) x + 1 (its
// degree s; its inner coefficients as the bits of `coefficients`, a_1 the highest) and the initial
// direction numbers m_1..m_s (m_k odd and below 2^k; the rest 0). Dimension 1 (van der Corput) has
// degree 0 and no m.
struct JoeKuoRow {
  int degree = 0;
  std::uint32_t coefficients = 0;
  std::array<std::uint32_t, 18> initial{};
};
// The rows of dimensions 1..dimensions, decoded from the compiled-in table; throws std::invalid_argument
// outside 1..kSobolMaxDimensions.
std::vector<JoeKuoRow> joe_kuo_rows(int dimensions);

class SobolSequence {
 public:
  static constexpr int kBits = 32;
  // The first `dimensions` dimensions of new-joe-kuo-6.21201 (data/). Throws std::invalid_argument
  // outside 1..kSobolMaxDimensions.
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
// The same points written to `out` (count x dimension doubles, row-major), memory the caller owns: the
// Python module writes into a NumPy array, whose allocator reuses freed memory where fresh pages would
// have to be faulted in and zeroed by the kernel (core/bulk_memory.hpp).
void sobol_points_into(int dimension, std::uint64_t first, std::uint64_t count, const Box& domain, Scramble scramble,
                       std::uint64_t seed, int threads, double* out, Simd simd = Simd::best);

// The same sequence carried to 64 digits (SciPy's Sobol(bits=33..64)): up to 2^64 points, the direction
// numbers of the same table over 64 bits. Points first .. first + count - 1; throws std::invalid_argument
// if that passes point 2^64 - 1. With Scramble::none a coordinate is its top 53
// digits / 2^53 (below 1; the 32-digit sequence's points, for index < 2^32); with Scramble::owen the 64
// digits are Owen-scrambled by owen_scramble_64 and the top 53 kept. Deterministic per seed, independent
// of the thread count.
PointSet sobol_points_64(int dimension, std::uint64_t first, std::uint64_t count, const Box& domain, Scramble scramble,
                         std::uint64_t seed, int threads);
// Nested scrambling of 64 digits, as owen_scramble's on 64 bits with its own keys per dimension.
std::uint64_t owen_scramble_64(std::uint64_t digits, std::uint64_t seed, int dim);

}  // namespace dfvn
