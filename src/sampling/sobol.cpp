#include "sampling/sobol.hpp"

#include <algorithm>
#include <bit>
#include "core/message_text.hpp"

#include <sstream>
#include <stdexcept>
#include <string>

#include "core/hash.hpp"
#include "core/parallel.hpp"
#include "joe_kuo_table.hpp"

namespace dfvn {

Scramble parse_scramble(std::string_view name) {
  if (name == "owen") return Scramble::owen;
  if (name == "none") return Scramble::none;
  throw std::invalid_argument("unknown scramble " + quote_for_message(name) + " (allowed: owen, none)");
}

std::string_view to_string(Scramble scramble) { return scramble == Scramble::owen ? "owen" : "none"; }

SobolSequence::SobolSequence(int dimensions) {
  if (dimensions < 1) throw std::invalid_argument("Sobol needs at least one dimension");
  // Dimension 1: van der Corput, v_k = 2^(31-k).
  std::array<std::uint32_t, kBits> first{};
  for (int k = 0; k < kBits; ++k) first[k] = std::uint32_t{1} << (kBits - 1 - k);
  directions_.push_back(first);

  std::istringstream table(kJoeKuoDirectionNumbers);
  std::string line;
  while (static_cast<int>(directions_.size()) < dimensions && std::getline(table, line)) {
    if (line.empty() || line[0] == '#' || line[0] == 'd') continue;
    std::istringstream row(line);
    int d = 0, s = 0;
    std::uint32_t a = 0;
    row >> d >> s >> a;
    std::array<std::uint32_t, kBits> v{};
    for (int k = 0; k < s; ++k) {
      std::uint32_t m = 0;
      row >> m;
      v[k] = m << (kBits - 1 - k);
    }
    if (!row || d != static_cast<int>(directions_.size()) + 1) throw std::logic_error("malformed Joe-Kuo table row: " + line);
    // Recurrence of the primitive polynomial x^s + a_1 x^(s-1) + ... + a_(s-1) x + 1 (Joe & Kuo, Eq. 2):
    // v_k = a_1 v_(k-1) ^ ... ^ a_(s-1) v_(k-s+1) ^ v_(k-s) ^ (v_(k-s) >> s).
    for (int k = s; k < kBits; ++k) {
      std::uint32_t value = v[k - s] ^ (v[k - s] >> s);
      for (int i = 1; i < s; ++i)
        if ((a >> (s - 1 - i)) & 1U) value ^= v[k - i];
      v[k] = value;
    }
    directions_.push_back(v);
  }
  if (static_cast<int>(directions_.size()) < dimensions)
    throw std::invalid_argument("Sobol direction numbers are available for " + std::to_string(directions_.size()) +
                                " dimensions, asked for " + std::to_string(dimensions));
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

std::uint32_t reverse_bits(std::uint32_t x) {
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

std::uint32_t owen_scramble_with_key(std::uint32_t digits, std::uint32_t key) {
  // Burley 2020, "Practical Hash-based Owen Scrambling" (JCGT 9(4)): with the digits bit-reversed, a
  // Laine-Karras permutation (adding the key, then x ^= x * even constant) changes each bit only
  // according to the bits below it, i.e. each original digit according to the digits above it: a
  // nested (Owen) scramble keyed by the seed and the dimension, in a handful of operations.
  std::uint32_t x = reverse_bits(digits);
  x += key;
  x ^= x * 0x6c50b47cU;
  x ^= x * 0xb82f1e52U;
  x ^= x * 0xc7afe638U;
  x ^= x * 0x8d22f6e6U;
  return reverse_bits(x);
}

}  // namespace

std::uint32_t owen_scramble(std::uint32_t digits, std::uint64_t seed, int dim) {
  return owen_scramble_with_key(digits, owen_key(seed, dim));
}

PointSet sobol_points(int dimension, std::uint64_t count, const Box& domain, Scramble scramble, std::uint64_t seed,
                      int threads) {
  if (count > (std::uint64_t{1} << 32)) throw std::invalid_argument("at most 2^32 Sobol points");
  const SobolSequence sequence(dimension);
  PointSet out{dimension, std::vector<double>(count * static_cast<std::uint64_t>(dimension)), domain};
  // Each block of consecutive points starts from digits() of its first index and then walks the Gray
  // code: one XOR per coordinate instead of one per set bit of the index.
  constexpr std::uint64_t kBlock = 4096;
  const std::uint64_t scramble_key = stream_key(seed, Stream::sobol_scramble);
  const auto blocks = static_cast<std::int64_t>((count + kBlock - 1) / kBlock);
  // Below about 2^16 coordinates (a few hundred microseconds of work) waking a second thread costs more
  // than it saves: 8192 4D points took 0.8 ms on one thread and 8-17 ms on two while the machine was busy.
  // The points do not depend on this choice (blocks are independent).
  constexpr std::uint64_t kSerialBelow = std::uint64_t{1} << 16;
  const bool parallel = count * static_cast<std::uint64_t>(dimension) >= kSerialBelow;
#pragma omp parallel for schedule(static) num_threads(resolve_threads(threads)) if (parallel)
  for (std::int64_t block = 0; block < blocks; ++block) {
    const std::uint64_t begin = static_cast<std::uint64_t>(block) * kBlock;
    const std::uint64_t end = std::min(count, begin + kBlock);
    std::array<std::uint32_t, 64> digits{}, keys{};
    for (int j = 0; j < dimension; ++j) keys[static_cast<std::size_t>(j)] = owen_key(seed, j);
    for (int j = 0; j < dimension; ++j) digits[static_cast<std::size_t>(j)] = sequence.digits(static_cast<std::uint32_t>(begin), j);
    for (std::uint64_t i = begin; i < end; ++i) {
      double* x = out.coordinates.data() + i * static_cast<std::uint64_t>(dimension);
      // The bits below the 32 digits: 32 random bits per coordinate, two coordinates per hash of
      // (seed, stream, point, pair). More would not survive: the sum has 53 significant bits.
      const std::uint64_t point_key = hash_combine(scramble_key, i);
      std::uint64_t below_bits = 0;
      for (int j = 0; j < dimension; ++j) {
        const std::uint32_t d = digits[static_cast<std::size_t>(j)];
        double unit;
        if (scramble == Scramble::owen) {
          if (j % 2 == 0) below_bits = hash_combine(point_key, static_cast<std::uint64_t>(j / 2) + 1000);
          const auto below = static_cast<std::uint32_t>(j % 2 == 0 ? below_bits : below_bits >> 32);
          unit = (static_cast<double>(owen_scramble_with_key(d, keys[static_cast<std::size_t>(j)])) +
                  static_cast<double>(below) * 0x1.0p-32) *
                 0x1.0p-32;
        } else {
          unit = static_cast<double>(d) * 0x1.0p-32;
        }
        x[j] = domain.lo + domain.side * unit;
      }
      if (i + 1 < end) {
        const int bit = std::countr_zero(i + 1);
        for (int j = 0; j < dimension; ++j) digits[static_cast<std::size_t>(j)] ^= sequence.direction(j, bit);
      }
    }
  }
  return out;
}

}  // namespace dfvn
