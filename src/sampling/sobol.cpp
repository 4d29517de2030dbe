#include "dfvn/sampling/sobol.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cstring>
#include <stdexcept>
#include <string>
#include <utility>

#if defined(__x86_64__)
#include <immintrin.h>
#endif

#include "dfvn/core/hash.hpp"
#include "dfvn/core/message_text.hpp"
#include "dfvn/core/parallel.hpp"
#include "joe_kuo_table.hpp"

namespace dfvn {

Scramble parse_scramble(std::string_view name) {
  if (name == "owen") return Scramble::owen;
  if (name == "none") return Scramble::none;
  throw std::invalid_argument("unknown scramble " + quote_for_message(name) + " (allowed: owen, none)");
}

std::string_view to_string(Scramble scramble) { return scramble == Scramble::owen ? "owen" : "none"; }

namespace {

// Reads the packed table (data/joe_kuo_directions.md): a little-endian bit stream, given as hexadecimal
// digits, read in fields of up to 24 bits.
class PackedBits {
 public:
  explicit PackedBits(const char* hex) : hex_(hex) {}
  std::uint32_t read(int width) {
    while (held_ < width) {
      buffer_ |= static_cast<std::uint64_t>(next_byte()) << held_;
      held_ += 8;
    }
    const auto value = static_cast<std::uint32_t>(buffer_ & ((std::uint64_t{1} << width) - 1));
    buffer_ >>= width;
    held_ -= width;
    return value;
  }

 private:
  static int nibble(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    throw std::logic_error("the compiled-in Joe-Kuo table is damaged (a non-hexadecimal digit or its end)");
  }
  std::uint32_t next_byte() {
    const int high = nibble(hex_[0]);
    const int low = nibble(hex_[1]);
    hex_ += 2;
    return static_cast<std::uint32_t>(high << 4 | low);
  }
  const char* hex_;
  std::uint64_t buffer_ = 0;
  int held_ = 0;
};

constexpr int kDegreeBits = 5;  // the table's degrees are 1..18

// The direction numbers v_0..v_(B-1) of one row over B-bit words, v_k = m_(k+1) 2^(B-1-k) for k < s, then
// the recurrence of the primitive polynomial (Joe & Kuo 2008, Eq. 2):
// v_k = a_1 v_(k-1) ^ ... ^ a_(s-1) v_(k-s+1) ^ v_(k-s) ^ (v_(k-s) >> s).
// Dimension 1 (degree 0) is van der Corput, v_k = 2^(B-1-k).
template <class Word>
std::array<Word, 8 * sizeof(Word)> direction_numbers(const JoeKuoRow& row) {
  constexpr int kWordBits = 8 * sizeof(Word);
  std::array<Word, kWordBits> v{};
  const int s = row.degree;
  if (s == 0) {
    for (int k = 0; k < kWordBits; ++k) v[k] = Word{1} << (kWordBits - 1 - k);
    return v;
  }
  for (int k = 0; k < s; ++k) v[k] = static_cast<Word>(row.initial[k]) << (kWordBits - 1 - k);
  for (int k = s; k < kWordBits; ++k) {
    Word value = v[k - s] ^ (v[k - s] >> s);
    for (int i = 1; i < s; ++i)
      if ((row.coefficients >> (s - 1 - i)) & 1U) value ^= v[k - i];
    v[k] = value;
  }
  return v;
}

}  // namespace

std::vector<JoeKuoRow> joe_kuo_rows(int dimensions) {
  if (dimensions < 1 || dimensions > kSobolMaxDimensions)
    throw std::invalid_argument("Sobol direction numbers are available for 1.." + std::to_string(kSobolMaxDimensions) +
                                " dimensions, asked for " + std::to_string(dimensions));
  std::vector<JoeKuoRow> rows(static_cast<std::size_t>(dimensions));  // row 0: van der Corput, degree 0
  PackedBits table(kJoeKuoPackedHex);
  for (std::size_t d = 1; d < rows.size(); ++d) {
    JoeKuoRow& row = rows[d];
    row.degree = static_cast<int>(table.read(kDegreeBits));
    if (row.degree < 1 || row.degree > static_cast<int>(row.initial.size()))
      throw std::logic_error("the compiled-in Joe-Kuo table is damaged (degree " + std::to_string(row.degree) + ")");
    row.coefficients = table.read(row.degree - 1);
    // m_k is odd and below 2^k: the table holds (m_k - 1) / 2 in k - 1 bits.
    for (int k = 1; k <= row.degree; ++k) row.initial[static_cast<std::size_t>(k - 1)] = 2 * table.read(k - 1) + 1;
  }
  return rows;
}

SobolSequence::SobolSequence(int dimensions) {
  if (dimensions < 1) throw std::invalid_argument("Sobol needs at least one dimension");
  for (const JoeKuoRow& row : joe_kuo_rows(dimensions)) directions_.push_back(direction_numbers<std::uint32_t>(row));
}

std::uint32_t SobolSequence::digits(std::uint32_t index, int dim) const {
  const auto& v = directions_[static_cast<std::size_t>(dim)];
  std::uint32_t gray = index ^ (index >> 1);
  std::uint32_t x = 0;
  for (int k = 0; gray != 0; ++k, gray >>= 1)
    if (gray & 1U) x ^= v[k];
  return x;
}

namespace {

// U: std::uint32_t or a vector of them. The vector helpers are always inlined, so that they take the
// instruction set of their caller (fill_block_avx2 or fill_block); GCC's -Wpsabi note about passing
// 32-byte vectors without AVX concerns calls that never happen: GCC fails the build if it cannot
// inline an always_inline call. (The note is issued where templates are instantiated, at the end of
// the file, so a push/pop around the kernels would not silence it.)
#pragma GCC diagnostic ignored "-Wpsabi"

template <typename U>
[[gnu::always_inline]] inline U reverse_bits(U x) {
  x = ((x >> 1) & 0x55555555U) | ((x & 0x55555555U) << 1);
  x = ((x >> 2) & 0x33333333U) | ((x & 0x33333333U) << 2);
  x = ((x >> 4) & 0x0F0F0F0FU) | ((x & 0x0F0F0F0FU) << 4);
  x = ((x >> 8) & 0x00FF00FFU) | ((x & 0x00FF00FFU) << 8);
  return (x >> 16) | (x << 16);
}

// The key of dimension `dim`'s scramble: one hash per (seed, dimension), hoisted out of point loops.
std::uint32_t owen_key(std::uint64_t seed, int dim) {
  return static_cast<std::uint32_t>(random_bits(seed, Stream::sobol_scramble, static_cast<std::uint64_t>(dim)) >> 32);
}

// Burley 2020, "Practical Hash-based Owen Scrambling" (JCGT 9(4)): with the digits bit-reversed, a
// Laine-Karras permutation (adding the key, then x ^= x * even constant) changes each bit only according
// to the bits below it, i.e. each original digit according to the digits above it: a nested (Owen)
// scramble keyed by the seed and the dimension, in a handful of operations. Takes the digits already
// reversed and returns the scrambled digits in their natural order.
template <typename U>
[[gnu::always_inline]] inline U laine_karras_permutation(U reversed_digits, U key) {
  U x = reversed_digits + key;
  x ^= x * 0x6c50b47cU;
  x ^= x * 0xb82f1e52U;
  x ^= x * 0xc7afe638U;
  x ^= x * 0x8d22f6e6U;
  return x;
}
template <typename U>
[[gnu::always_inline]] inline U owen_scramble_reversed(U reversed_digits, U key) {
  return reverse_bits(laine_karras_permutation(reversed_digits, key));
}

// What every block of points needs. With Owen scrambling the digits are kept bit-reversed all along:
// reversal commutes with XOR, so the Gray-code walk XORs reversed direction numbers and feeds the
// Laine-Karras permutation directly; only its result is reversed back.
struct SobolBlocks {
  // Row length of `walk`: the dimension rounded up to 8 lanes, so that rows load as whole vectors.
  static constexpr std::size_t stride(std::size_t dims) { return (dims + 7) / 8 * 8; }
  const SobolSequence& sequence;
  std::vector<std::uint32_t> walk;  // row `bit`: direction `bit` of every dimension (reversed for Owen)
  std::vector<std::uint32_t> keys;  // Owen: one key per dimension, lane 0 of (seed, stream, dimension)
  std::uint64_t stream = 0;         // Owen: stream_key(seed, sobol_scramble)
  double lo = 0.0, side = 1.0;
  double* out = nullptr;   // point `first`'s row
  std::uint64_t first = 0;
  std::size_t dims = 0;    // the dimension (fill_block_any reads it; the other kernels have it as D)
  // Owen on AVX2 (fill_block_points_in_lanes_avx2): row j, lane p: dimension j's digits of Gray code
  // p ^ (p >> 1), p = 0..7, reversed; the offsets of points 8k + p from point 8k.
  std::vector<std::uint32_t> lane_offsets{};
};

// A GCC/Clang vector of `bytes` bytes of T (the attribute cannot be written on a dependent alias).
template <typename T, std::size_t bytes>
struct Vector {
  typedef T type __attribute__((vector_size(bytes)));
};

// Lanes first, first + 1, ... (one per L) of the random bits below the digits: coordinate j's 20 bits, at the top
// of its 32-bit lane (where fill_block_with's mantissa expects them), are bits 20 (j % 3) up of word
// j / 3; lanes past the dimension are 0.
template <std::size_t D, typename U32, std::size_t kWords, std::size_t... L>
[[gnu::always_inline]] inline U32 below_lanes(const std::array<std::uint64_t, kWords>& words, std::size_t first,
                                              std::index_sequence<L...>) {
  return U32{(first + L < D ? static_cast<std::uint32_t>(words[(first + L) / 3] >> (20 * ((first + L) % 3))) << 12 : 0U)...};
}

// Points [begin, end) of one block: start from digits() of `begin`, then walk the Gray code, one XOR
// per coordinate. D is the dimension, known at compile time so the loops over coordinates unroll; W
// is the number of 32-bit lanes of a vector. Digits, keys and the random bits below the digits stay in
// vectors (writing lanes one by one and reading them back as a vector stalls store forwarding).
template <std::size_t D, std::size_t W, Scramble S>
[[gnu::always_inline]] inline void fill_block_with(const SobolBlocks& b, std::uint64_t begin, std::uint64_t end) {
  using U32 = typename Vector<std::uint32_t, 4 * W>::type;
  using U64 = typename Vector<std::uint64_t, 4 * W>::type;
  using F64 = typename Vector<double, 4 * W>::type;
  constexpr std::size_t kVectors = (D + W - 1) / W;
  constexpr std::size_t kBelowWords = (D + 2) / 3;  // 64-bit hashes per point, 20 bits per coordinate
  static_assert(kVectors * W <= SobolBlocks::stride(D));
  std::array<U32, kVectors> digits{}, keys{};
  for (std::size_t j = 0; j < D; ++j) {
    const std::uint32_t d = b.sequence.digits(static_cast<std::uint32_t>(begin), static_cast<int>(j));
    digits[j / W][j % W] = S == Scramble::owen ? reverse_bits(d) : d;
    keys[j / W][j % W] = S == Scramble::owen ? b.keys[j] : 0;
  }
  constexpr std::uint64_t kOneBits = 0x3ff0000000000000;  // the bits of 1.0
  for (std::uint64_t i = begin; i < end; ++i) {
    double* x = b.out + (i - b.first) * D;
    if constexpr (S == Scramble::owen) {
      // 20 random bits below the 32 digits per coordinate: coordinate j takes bits 20 (j % 3) up of
      // random_bits(seed, stream, point, 1 + j / 3), so they depend on the point and the coordinate
      // only (not on D), and lane 0, the dimension keys' lane, is never used. Digits and random bits
      // make the 52-bit mantissa of a double in [1, 2): building it from its bits and subtracting 1 is
      // exact and, unlike an integer conversion, vectorises.
      const std::uint64_t point_key = hash_combine(b.stream, i);
      std::array<std::uint64_t, kBelowWords> words;
      for (std::size_t w = 0; w < kBelowWords; ++w) words[w] = hash_combine(point_key, 1 + w);
      for (std::size_t v = 0; v < kVectors; ++v) {
        const U32 high = owen_scramble_reversed(digits[v], keys[v]);
        const U32 low = below_lanes<D, U32>(words, v * W, std::make_index_sequence<W>{});
        // Interleave into 64-bit lanes: the random bits in the low half, the digits in the high half.
        U64 halves[2];
        if constexpr (W == 4) {
          halves[0] = reinterpret_cast<U64>(__builtin_shuffle(low, high, U32{0, 4, 1, 5}));
          halves[1] = reinterpret_cast<U64>(__builtin_shuffle(low, high, U32{2, 6, 3, 7}));
        } else {
          static_assert(W == 8);
          halves[0] = reinterpret_cast<U64>(__builtin_shuffle(low, high, U32{0, 8, 1, 9, 2, 10, 3, 11}));
          halves[1] = reinterpret_cast<U64>(__builtin_shuffle(low, high, U32{4, 12, 5, 13, 6, 14, 7, 15}));
        }
        for (std::size_t h = 0; h < 2; ++h) {
          const std::size_t first = v * W + h * W / 2;
          if (first >= D) break;
          const F64 unit = reinterpret_cast<F64>((halves[h] >> 12) | kOneBits) - 1.0;
          const F64 scaled = b.lo + b.side * unit;
          std::memcpy(x + first, &scaled, std::min(W / 2, D - first) * sizeof(double));
        }
      }
    } else {
      for (std::size_t j = 0; j < D; ++j) x[j] = b.lo + b.side * (static_cast<double>(digits[j / W][j % W]) * 0x1.0p-32);
    }
    if (i + 1 < end) {
      const std::uint32_t* row = b.walk.data() + static_cast<std::size_t>(std::countr_zero(i + 1)) * SobolBlocks::stride(D);
      for (std::size_t v = 0; v < kVectors; ++v) {
        U32 direction;
        std::memcpy(&direction, row + v * W, sizeof direction);
        digits[v] ^= direction;
      }
    }
  }
}

// Owen-scrambled points in batches of kBatch, for any D: a batch's coordinates sit in arrays laid out
// as the output (point-major), so the scramble, the hashes of the random bits below the digits and the
// conversion to doubles are plain loops over kBatch * D lanes that the compiler vectorises, whatever D
// is (fill_block_with vectorises over one point's coordinates, which leaves most lanes idle in 2D-3D,
// and hashes one point at a time). Same bits as fill_block_with: the same digits, keys, hashes and
// arithmetic, lane by lane; points past the last whole batch take the per-point formulas.
template <std::size_t D>
[[gnu::always_inline]] inline void fill_block_batched_with(const SobolBlocks& b, std::uint64_t begin, std::uint64_t end) {
  constexpr std::size_t kBatch = 8;
  constexpr std::size_t kLanes = kBatch * D;
  constexpr std::size_t kBelowWords = (D + 2) / 3;  // 64-bit hashes per point, 20 bits per coordinate
  constexpr std::uint64_t kOneBits = 0x3ff0000000000000;  // the bits of 1.0
  std::array<std::uint32_t, D> current;
  for (std::size_t j = 0; j < D; ++j)
    current[j] = reverse_bits(b.sequence.digits(static_cast<std::uint32_t>(begin), static_cast<int>(j)));
  alignas(64) std::array<std::uint32_t, kLanes> keys, high, low;
  alignas(64) std::array<std::uint64_t, kBatch> point_keys;
  alignas(64) std::array<std::uint64_t, kBatch * kBelowWords> words;
  for (std::size_t k = 0; k < kLanes; ++k) keys[k] = b.keys[k % D];
  const double lo = b.lo, side = b.side;  // locals: the stores below cannot alias them
  const auto step = [&](std::uint64_t i) {  // the Gray-code walk from point i to point i + 1
    if (i + 1 >= end) return;
    const std::uint32_t* row = b.walk.data() + static_cast<std::size_t>(std::countr_zero(i + 1)) * SobolBlocks::stride(D);
    for (std::size_t j = 0; j < D; ++j) current[j] ^= row[j];
  };
  const auto to_double = [&](std::uint32_t digits, std::uint32_t below) {
    const std::uint64_t bits = (((std::uint64_t{digits} << 32) | below) >> 12) | kOneBits;
    double unit;
    std::memcpy(&unit, &bits, sizeof unit);
    return lo + side * (unit - 1.0);
  };
  std::uint64_t i = begin;
  for (; i + kBatch <= end; i += kBatch) {
    for (std::size_t p = 0; p < kBatch; ++p) {
      for (std::size_t j = 0; j < D; ++j) high[p * D + j] = current[j];
      step(i + p);
    }
    for (std::size_t k = 0; k < kLanes; ++k) high[k] = owen_scramble_reversed(high[k], keys[k]);
    for (std::size_t p = 0; p < kBatch; ++p) point_keys[p] = hash_combine(b.stream, i + p);
    for (std::size_t p = 0; p < kBatch; ++p)
      for (std::size_t w = 0; w < kBelowWords; ++w) words[p * kBelowWords + w] = hash_combine(point_keys[p], 1 + w);
    for (std::size_t p = 0; p < kBatch; ++p)
      for (std::size_t j = 0; j < D; ++j)
        low[p * D + j] = static_cast<std::uint32_t>(words[p * kBelowWords + j / 3] >> (20 * (j % 3))) << 12;
    double* x = b.out + (i - b.first) * D;
    for (std::size_t k = 0; k < kLanes; ++k) x[k] = to_double(high[k], low[k]);
  }
  for (; i < end; ++i) {
    const std::uint64_t point_key = hash_combine(b.stream, i);
    double* x = b.out + (i - b.first) * D;
    for (std::size_t j = 0; j < D; ++j) {
      const std::uint64_t word = hash_combine(point_key, 1 + j / 3);
      x[j] = to_double(owen_scramble_reversed(current[j], b.keys[j]), static_cast<std::uint32_t>(word >> (20 * (j % 3))) << 12);
    }
    step(i);
  }
}

// Any dimension, for those above the unrolled kernels (kUnrolledDimensions): one point at a time, each
// step a loop over the D coordinates that the compiler vectorises (at least 16 lanes here). Same bits
// as fill_block_with: the same digits, keys, hashes and arithmetic, coordinate by coordinate, so a
// coordinate's value never depends on the dimension (tests/sampling/test_sobol.cpp).
template <Scramble S>
[[gnu::always_inline]] inline void fill_block_any_with(const SobolBlocks& b, std::uint64_t begin, std::uint64_t end) {
  constexpr std::uint64_t kOneBits = 0x3ff0000000000000;  // the bits of 1.0
  const std::size_t dims = b.dims;
  const std::size_t words_per_point = (dims + 2) / 3;    // 64-bit hashes per point, 20 bits per coordinate
  std::vector<std::uint32_t> current(dims), high(dims), low(3 * words_per_point);
  std::vector<std::uint64_t> words(words_per_point);
  for (std::size_t j = 0; j < dims; ++j) {
    const std::uint32_t d = b.sequence.digits(static_cast<std::uint32_t>(begin), static_cast<int>(j));
    current[j] = S == Scramble::owen ? reverse_bits(d) : d;
  }
  const std::uint32_t* keys = b.keys.data();
  const double lo = b.lo, side = b.side;  // locals: the stores below cannot alias them
  for (std::uint64_t i = begin; i < end; ++i) {
    double* x = b.out + (i - b.first) * dims;
    if constexpr (S == Scramble::owen) {
      const std::uint64_t point_key = hash_combine(b.stream, i);
      for (std::size_t w = 0; w < words_per_point; ++w) words[w] = hash_combine(point_key, 1 + w);
      for (std::size_t w = 0; w < words_per_point; ++w)
        for (std::size_t part = 0; part < 3; ++part)
          low[3 * w + part] = static_cast<std::uint32_t>(words[w] >> (20 * part)) << 12;
      for (std::size_t j = 0; j < dims; ++j) high[j] = owen_scramble_reversed(current[j], keys[j]);
      for (std::size_t j = 0; j < dims; ++j) {
        const std::uint64_t bits = (((std::uint64_t{high[j]} << 32) | low[j]) >> 12) | kOneBits;
        double unit;
        std::memcpy(&unit, &bits, sizeof unit);
        x[j] = lo + side * (unit - 1.0);
      }
    } else {
      for (std::size_t j = 0; j < dims; ++j) x[j] = lo + side * (static_cast<double>(current[j]) * 0x1.0p-32);
    }
    if (i + 1 < end) {
      const std::uint32_t* row = b.walk.data() + static_cast<std::size_t>(std::countr_zero(i + 1)) * SobolBlocks::stride(dims);
      for (std::size_t j = 0; j < dims; ++j) current[j] ^= row[j];
    }
  }
}

// SSE2's Owen kernels (AVX2 takes fill_block_points_in_lanes_avx2 in every dimension).
// The batches pay in 1D-3D, where one point fills few lanes: 2^21 2D points in 37-40 ms against 55-68
// per point, 3D 43-46 against 66-79 (one thread, fresh memory, load 9-13); in 4D-7D the two were within
// the noise, so those keep the per-point kernel.
template <std::size_t D>
constexpr bool kBatched = D <= 3;

// Two builds of the same code: 4 lanes (SSE2, every x86-64; the only build elsewhere) and, on x86-64,
// 8 lanes with AVX2, chosen at run time. They give the same bits: integer operations, a double built
// from its bits minus 1 (exact), then one multiply and one add, rounded alike because this file is
// compiled (as every file) with -ffp-contract=off (CMakeLists.txt).
template <std::size_t D, Scramble S>
void fill_block(const SobolBlocks& b, std::uint64_t begin, std::uint64_t end) {
  if constexpr (S == Scramble::owen && kBatched<D>) fill_block_batched_with<D>(b, begin, end);
  else fill_block_with<D, 4, S>(b, begin, end);
}

#if defined(__x86_64__)
template <std::size_t D, Scramble S>
[[gnu::target("avx2")]] void fill_block_avx2(const SobolBlocks& b, std::uint64_t begin, std::uint64_t end) {
  if constexpr (S == Scramble::owen && kBatched<D>) fill_block_batched_with<D>(b, begin, end);
  else fill_block_with<D, 8, S>(b, begin, end);
}
#endif

template <Scramble S>
void fill_block_any(const SobolBlocks& b, std::uint64_t begin, std::uint64_t end) {
  fill_block_any_with<S>(b, begin, end);
}
#if defined(__x86_64__)
template <Scramble S>
[[gnu::target("avx2")]] void fill_block_any_avx2(const SobolBlocks& b, std::uint64_t begin, std::uint64_t end) {
  fill_block_any_with<S>(b, begin, end);
}
#endif

#if defined(__x86_64__)
// SplitMix64's mix64 and hash_combine (core/hash.hpp), the same operations lane by lane on four 64-bit words.
using U64x4 = Vector<std::uint64_t, 32>::type;
[[gnu::target("avx2"), gnu::always_inline]] inline U64x4 mix64_lanes(U64x4 z) {
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}
[[gnu::target("avx2"), gnu::always_inline]] inline U64x4 hash_combine_lanes(U64x4 h, U64x4 value) {
  return mix64_lanes(h ^ (value + kGoldenGamma + (h << 6) + (h >> 2)));
}

// reverse_bits on eight 32-bit lanes in six instructions instead of twenty: the bytes swapped with one
// shuffle, then each byte's bits reversed by looking its two nibbles up in a 16-entry table.
[[gnu::target("avx2")]] inline __m256i reverse_bits_avx2(__m256i x) {
  const __m256i swap_bytes = _mm256_setr_epi8(3, 2, 1, 0, 7, 6, 5, 4, 11, 10, 9, 8, 15, 14, 13, 12,
                                              3, 2, 1, 0, 7, 6, 5, 4, 11, 10, 9, 8, 15, 14, 13, 12);
  const __m256i reversed_nibble = _mm256_setr_epi8(0x0, 0x8, 0x4, 0xC, 0x2, 0xA, 0x6, 0xE, 0x1, 0x9, 0x5, 0xD, 0x3, 0xB, 0x7, 0xF,
                                                   0x0, 0x8, 0x4, 0xC, 0x2, 0xA, 0x6, 0xE, 0x1, 0x9, 0x5, 0xD, 0x3, 0xB, 0x7, 0xF);
  const __m256i low_nibbles = _mm256_set1_epi8(0x0F);
  x = _mm256_shuffle_epi8(x, swap_bytes);
  const __m256i low = _mm256_shuffle_epi8(reversed_nibble, _mm256_and_si256(x, low_nibbles));
  const __m256i high = _mm256_shuffle_epi8(reversed_nibble, _mm256_and_si256(_mm256_srli_epi16(x, 4), low_nibbles));
  return _mm256_or_si256(_mm256_slli_epi16(low, 4), high);  // a byte's low nibble, reversed, is its high one
}

// Owen-scrambled points eight at a time with the points in the lanes, for any dimension: one 8-lane
// vector per coordinate, full whatever D is (fill_block_with puts one point's coordinates in the
// lanes, which leaves 4 of 8 idle in 4D and 7 of 16 in 9D), and the random bits below the digits
// hashed for eight points at once (fill_block_with hashes one point at a time, in scalar code). The
// price is eight scalar stores per coordinate vector (the output is point-major). Points 8k + p share
// the Gray code of 8k above bit 2 (gray(8k + p) = gray(8k) ^ gray(p)), so a coordinate's eight digits
// are its running digits ^ lane_offsets. Same bits as fill_block_with: the same digits, keys, hashes and
// arithmetic, lane by lane; the points before the first multiple of 32 (the step, four batches) and
// after the last take fill_block_any.
// kUnitBox: the domain is [0, 1)^D (the Python engines'), where lo + side u is u exactly and is skipped.
template <bool kUnitBox>
[[gnu::target("avx2"), gnu::always_inline]] inline void fill_block_points_in_lanes(const SobolBlocks& b, std::uint64_t begin,
                                                                                   std::uint64_t end) {
  using U32 = Vector<std::uint32_t, 32>::type;
  using F64 = Vector<double, 32>::type;
  // Four batches of eight points per step, i + 8 g .. i + 8 g + 7 (g = 0..3): their hash and scramble
  // chains are independent and fill each other's multiply latencies (one batch per step left the 2D
  // kernel waiting on them; two took 2D 2^16 from 0.247 to 0.225 ms, four to 0.212).
  constexpr std::size_t kBatches = 4;
  constexpr std::uint64_t kPoints = 8 * kBatches;
  constexpr std::uint64_t kOneBits = 0x3ff0000000000000;  // the bits of 1.0
  constexpr std::uint64_t kBelowMask = (std::uint64_t{1} << 20) - 1;
  const std::uint64_t batch_begin = std::min(end, (begin + kPoints - 1) / kPoints * kPoints);
  const std::uint64_t batch_end = std::max(batch_begin, end / kPoints * kPoints);
  if (begin < batch_begin) fill_block_any_avx2<Scramble::owen>(b, begin, batch_begin);
  const std::size_t dims = b.dims;
  std::vector<std::uint32_t> current(dims);  // digits of point i, reversed
  for (std::size_t j = 0; j < dims; ++j)
    current[j] = reverse_bits(b.sequence.digits(static_cast<std::uint32_t>(batch_begin), static_cast<int>(j)));
  const U64x4 stream = U64x4{} + b.stream;
  const double lo = b.lo, side = b.side;  // locals: the stores below cannot alias them
  const std::size_t stride = SobolBlocks::stride(dims);
  // batch_offsets[g dims + j]: dimension j's directions of the bits of gray(8 g) = 8 g ^ 4 g, reversed.
  std::vector<std::uint32_t> batch_offsets(kBatches * dims, 0);
  for (std::size_t g = 0; g < kBatches; ++g)
    for (std::size_t gray = 8 * g ^ 4 * g, bit = 0; gray != 0; gray >>= 1, ++bit)
      if (gray & 1U)
        for (std::size_t j = 0; j < dims; ++j) batch_offsets[g * dims + j] ^= b.walk[bit * stride + j];
  const std::uint32_t* row_top = b.walk.data() + static_cast<std::size_t>(std::countr_zero(kPoints) - 1) * stride;
  for (std::uint64_t i = batch_begin; i < batch_end; i += kPoints) {
    // hash_combine(stream, point) of points i + 4 q .. i + 4 q + 3, then per word w hash_combine(point_key, 1 + w).
    U64x4 point_keys[2 * kBatches];
    for (std::size_t q = 0; q < 2 * kBatches; ++q) point_keys[q] = hash_combine_lanes(stream, U64x4{0, 1, 2, 3} + (i + 4 * q));
    double* x = b.out + (i - b.first) * dims;
    // Three coordinates per word, unrolled so that their shifts (20 part) are constants.
    for (std::size_t first = 0; first < dims; first += 3) {
      U64x4 words[2 * kBatches];
      for (std::size_t q = 0; q < 2 * kBatches; ++q) words[q] = hash_combine_lanes(point_keys[q], U64x4{} + (1 + first / 3));
#pragma GCC unroll 3
      for (std::size_t part = 0; part < 3; ++part) {
        const std::size_t j = first + part;
        if (j >= dims) break;
        U32 offsets;
        std::memcpy(&offsets, b.lane_offsets.data() + j * 8, sizeof offsets);
        // Point i + 8 g + p: Gray code gray(i) ^ gray(8 g) ^ gray(p) (i is a multiple of 32).
        const U32 digits = offsets ^ current[j];
        U32 mixed[kBatches];
        for (std::size_t batch = 0; batch < kBatches; ++batch)
          mixed[batch] = laine_karras_permutation(digits ^ batch_offsets[batch * dims + j], U32{} + b.keys[j]);
        for (std::size_t batch = 0; batch < kBatches; ++batch) {
          const __m256i high = reverse_bits_avx2(reinterpret_cast<__m256i>(mixed[batch]));
          const __m256i halves[2] = {_mm256_cvtepu32_epi64(_mm256_castsi256_si128(high)),
                                     _mm256_cvtepu32_epi64(_mm256_extracti128_si256(high, 1))};
          for (std::size_t h = 0; h < 2; ++h) {
            // fill_block_with's ((high << 32 | below << 12) >> 12) | 1.0's bits, below = word >> 20 part.
            const U64x4 below = (words[2 * batch + h] >> (20 * part)) & kBelowMask;
            const U64x4 bits = (reinterpret_cast<U64x4>(halves[h]) << 20) | below | kOneBits;
            const F64 unit = reinterpret_cast<F64>(bits) - 1.0;
            F64 value = unit;
            if constexpr (!kUnitBox) value = lo + side * unit;
            for (std::size_t p = 0; p < 4; ++p) x[(8 * batch + 4 * h + p) * dims + j] = value[p];
          }
        }
      }
    }
    if (i + kPoints < batch_end) {
      // Gray-code bit 4 of a multiple of 32 is its bit 5, which flips from one to the next: from point i to
      // i + 32 the Gray code changes in bit ctz(i + 32) and in bit 4 (row_top).
      const std::uint32_t* row = b.walk.data() + static_cast<std::size_t>(std::countr_zero(i + kPoints)) * stride;
      for (std::size_t j = 0; j < dims; ++j) current[j] ^= row[j] ^ row_top[j];
    }
  }
  if (batch_end < end) fill_block_any_avx2<Scramble::owen>(b, std::max(begin, batch_end), end);
}
[[gnu::target("avx2")]] void fill_block_points_in_lanes_avx2(const SobolBlocks& b, std::uint64_t begin, std::uint64_t end) {
  if (b.lo == 0.0 && b.side == 1.0)
    fill_block_points_in_lanes<true>(b, begin, end);
  else
    fill_block_points_in_lanes<false>(b, begin, end);
}
#endif

// One build's kernels for dimensions 1 ... kUnrolledDimensions, indexed by dimension - 1. Dimensions
// above take fill_block_any: each unrolled dimension is four more kernels to compile, and from 16
// coordinates on a loop over them fills the vectors anyway.
using FillBlock = void (*)(const SobolBlocks&, std::uint64_t, std::uint64_t);
constexpr int kUnrolledDimensions = 15;

template <Scramble S, bool kAvx2>
constexpr std::array<FillBlock, kUnrolledDimensions> fill_block_table() {
  return []<std::size_t... I>(std::index_sequence<I...>) {
#if defined(__x86_64__)
    if constexpr (kAvx2) return std::array<FillBlock, kUnrolledDimensions>{&fill_block_avx2<I + 1, S>...};
#endif
    return std::array<FillBlock, kUnrolledDimensions>{&fill_block<I + 1, S>...};
  }(std::make_index_sequence<kUnrolledDimensions>{});
}

// The kernel for a dimension, scramble and instruction set, chosen once per call of sobol_points.
FillBlock choose_fill_block(std::size_t dims, Scramble scramble, Simd simd) {
  const bool owen = scramble == Scramble::owen;
  const bool unrolled = dims <= static_cast<std::size_t>(kUnrolledDimensions);
#if defined(__x86_64__)
  if (simd == Simd::best && cpu_has_avx2()) {
    if (owen) return &fill_block_points_in_lanes_avx2;  // every dimension
    static constexpr auto kNone = fill_block_table<Scramble::none, true>();
    if (!unrolled) return &fill_block_any_avx2<Scramble::none>;
    return kNone[dims - 1];
  }
#endif
  (void)simd;
  static constexpr auto kOwen = fill_block_table<Scramble::owen, false>();
  static constexpr auto kNone = fill_block_table<Scramble::none, false>();
  if (!unrolled) return owen ? &fill_block_any<Scramble::owen> : &fill_block_any<Scramble::none>;
  return (owen ? kOwen : kNone)[dims - 1];
}

std::uint64_t reverse_bits_64(std::uint64_t x) {
  return std::uint64_t{reverse_bits(static_cast<std::uint32_t>(x))} << 32 | reverse_bits(static_cast<std::uint32_t>(x >> 32));
}

// owen_scramble_reversed on 64 bits: adding the key, x ^= x * even constant and x *= odd constant each
// change a bit only according to the bits below it (the digits above it, reversed), so the result is a
// nested scramble of the digits; the constants are SplitMix64's multipliers and the golden-ratio
// increment, made even or odd.
std::uint64_t owen_scramble_reversed_64(std::uint64_t reversed_digits, std::uint64_t key) {
  std::uint64_t x = reversed_digits + key;
  x ^= x * 0xBF58476D1CE4E5BAULL;
  x ^= x * 0x94D049BB133111ECULL;
  x *= 0x9E3779B97F4A7C15ULL;
  x ^= x * 0xD6E8FEB86659FD94ULL;
  return reverse_bits_64(x);
}

// Dimension `dim`'s key of the 64-digit scramble: lane 1 of its (seed, stream, dimension) word, apart from
// the 32-digit scramble's lane 0.
std::uint64_t owen_key_64(std::uint64_t seed, int dim) {
  return random_bits(seed, Stream::sobol_scramble, static_cast<std::uint64_t>(dim), 1);
}

}  // namespace

std::uint32_t owen_scramble(std::uint32_t digits, std::uint64_t seed, int dim) {
  return owen_scramble_reversed(reverse_bits(digits), owen_key(seed, dim));
}

PointSet sobol_points(int dimension, std::uint64_t count, const Box& domain, Scramble scramble, std::uint64_t seed,
                      int threads, Simd simd) {
  return sobol_points_range(dimension, 0, count, domain, scramble, seed, threads, simd);
}

PointSet sobol_points_range(int dimension, std::uint64_t first, std::uint64_t count, const Box& domain, Scramble scramble,
                            std::uint64_t seed, int threads, Simd simd) {
  if (dimension < 1) throw std::invalid_argument("Sobol needs at least one dimension");
  PointSet out{dimension, Coordinates(count * static_cast<std::uint64_t>(dimension)), domain};
  sobol_points_into(dimension, first, count, domain, scramble, seed, threads, out.coordinates.data(), simd);
  return out;
}

void sobol_points_into(int dimension, std::uint64_t first, std::uint64_t count, const Box& domain, Scramble scramble,
                       std::uint64_t seed, int threads, double* out, Simd simd) {
  if (first + count > (std::uint64_t{1} << 32) || first > (std::uint64_t{1} << 32))
    throw std::invalid_argument("at most 2^32 Sobol points");
  const SobolSequence sequence(dimension);
  const auto dims = static_cast<std::size_t>(dimension);
  SobolBlocks blocks{sequence, {}, {}};
  const bool owen = scramble == Scramble::owen;
  blocks.walk.resize(static_cast<std::size_t>(SobolSequence::kBits) * SobolBlocks::stride(dims));
  blocks.keys.resize(dims);
  for (std::size_t j = 0; j < dims; ++j) {
    blocks.keys[j] = owen_key(seed, static_cast<int>(j));
    for (int bit = 0; bit < SobolSequence::kBits; ++bit) {
      const std::uint32_t v = sequence.direction(static_cast<int>(j), bit);
      blocks.walk[static_cast<std::size_t>(bit) * SobolBlocks::stride(dims) + j] = owen ? reverse_bits(v) : v;
    }
  }
  blocks.stream = stream_key(seed, Stream::sobol_scramble);
  blocks.lo = domain.lo;
  blocks.side = domain.side;
  blocks.out = out;
  blocks.first = first;
  blocks.dims = dims;
  if (owen) {
    // Lane p's offset from point 8k: the reversed directions of the bits of gray(p) = p ^ (p >> 1).
    blocks.lane_offsets.assign(dims * 8, 0);
    for (std::size_t j = 0; j < dims; ++j)
      for (std::uint32_t p = 0; p < 8; ++p)
        for (std::uint32_t gray = p ^ (p >> 1), bit = 0; gray != 0; gray >>= 1, ++bit)
          if (gray & 1U) blocks.lane_offsets[j * 8 + p] ^= blocks.walk[bit * SobolBlocks::stride(dims) + j];
  }
  const FillBlock fill = choose_fill_block(dims, scramble, simd);
  // Blocks of consecutive points are independent, so the points do not depend on the thread count (and a
  // range's blocks start at the whole set's block boundaries).
  constexpr std::uint64_t kBlock = 4096;
  const std::uint64_t end = first + count;
  const std::uint64_t first_block = first / kBlock;
  const auto block_count = static_cast<std::int64_t>((end + kBlock - 1) / kBlock - first_block);
  const bool parallel = worth_threads(count * dims);
#pragma omp parallel for schedule(static) num_threads(resolve_threads(threads)) if (parallel)
  for (std::int64_t block = 0; block < block_count; ++block) {
    const std::uint64_t begin = (first_block + static_cast<std::uint64_t>(block)) * kBlock;
    fill(blocks, std::max(first, begin), std::min(end, begin + kBlock));
  }
}

std::uint64_t owen_scramble_64(std::uint64_t digits, std::uint64_t seed, int dim) {
  return owen_scramble_reversed_64(reverse_bits_64(digits), owen_key_64(seed, dim));
}

PointSet sobol_points_64(int dimension, std::uint64_t first, std::uint64_t count, const Box& domain, Scramble scramble,
                         std::uint64_t seed, int threads) {
  if (count > 0 && first + (count - 1) < first)
    throw std::invalid_argument("at most 2^64 Sobol points: point " + std::to_string(first) + " + " +
                                std::to_string(count) + " - 1 is past 2^64 - 1");
  const auto dims = static_cast<std::size_t>(dimension);
  std::vector<std::array<std::uint64_t, 64>> directions;
  for (const JoeKuoRow& row : joe_kuo_rows(dimension)) directions.push_back(direction_numbers<std::uint64_t>(row));
  std::vector<std::uint64_t> keys(dims);
  for (std::size_t j = 0; j < dims; ++j) keys[j] = owen_key_64(seed, static_cast<int>(j));
  PointSet out{dimension, Coordinates(count * dims), domain};
  // Blocks of consecutive points, each starting from the digits of its first point (Gray code of its
  // index, as SobolSequence::digits): the points do not depend on the thread count.
  constexpr std::uint64_t kBlock = 4096;
  const auto blocks = static_cast<std::int64_t>((count + kBlock - 1) / kBlock);
#pragma omp parallel for schedule(static) num_threads(resolve_threads(threads)) if (worth_threads(count * dims))
  for (std::int64_t block = 0; block < blocks; ++block) {
    const std::uint64_t begin = static_cast<std::uint64_t>(block) * kBlock;
    const std::uint64_t end = std::min(count, begin + kBlock);
    std::vector<std::uint64_t> digits(dims);
    const std::uint64_t start = first + begin;
    for (std::size_t j = 0; j < dims; ++j) {
      std::uint64_t gray = start ^ (start >> 1);
      for (int k = 0; gray != 0; ++k, gray >>= 1)
        if (gray & 1U) digits[j] ^= directions[j][static_cast<std::size_t>(k)];
    }
    for (std::uint64_t at = begin; at < end; ++at) {
      double* x = out.coordinates.data() + at * dims;
      for (std::size_t j = 0; j < dims; ++j) {
        const std::uint64_t value =
            scramble == Scramble::owen ? owen_scramble_reversed_64(reverse_bits_64(digits[j]), keys[j]) : digits[j];
        x[j] = domain.lo + domain.side * (static_cast<double>(value >> 11) * 0x1.0p-53);
      }
      if (at + 1 < end) {
        const auto bit = static_cast<std::size_t>(std::countr_zero(first + at + 1));
        for (std::size_t j = 0; j < dims; ++j) digits[j] ^= directions[j][bit];
      }
    }
  }
  return out;
}

}  // namespace dfvn
