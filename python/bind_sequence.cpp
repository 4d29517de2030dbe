// dfvn._core._sequence: points [start, start + count) of the Sobol, Halton and uniform random sequences,
// for the engines dfvn.Sobol, dfvn.Halton and dfvn.Random (python/dfvn/qmc.py), whose random(n) calls
// continue where the last one stopped and whose fast_forward(k) skips k points, as SciPy's do.
//
// From point 0 the library's generators are called (sobol_points, halton_points, uniform_random_points:
// the same bits as `dfvn-sample --points`). Every point of the three is a function of its index alone, so
// a later start computes points start.. by the same formulas, point by point: the Sobol digits of the
// Gray-code walk, Owen-scrambled with owen_scramble, and the 20 bits below them from the same hashes
// (sampling/sobol.cpp); the Halton digit permutations of the library (halton_digit_permutations);
// random_unit of Stream::random_points. tests/python/test_qmc.py checks that both ways give the same bits.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <numeric>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <pybind11/pybind11.h>

#include "dfvn/core/hash.hpp"
#include "dfvn/core/parallel.hpp"
#include "dfvn/sampling/halton.hpp"
#include "dfvn/sampling/jitter.hpp"
#include "dfvn/sampling/sobol.hpp"
#include "checked_def.hpp"
#include "numpy_points.hpp"

namespace dfvn::python {

namespace {

// Sobol points [start, end) from their 32 digits per dimension, as sampling/sobol.cpp's fill_block;
// `out` holds point `first` at its start.
void sobol_block(const SobolSequence& sequence, std::uint64_t first, std::uint64_t start, std::uint64_t end, int d,
                 Scramble scramble, std::uint64_t seed, double* out) {
  const std::uint64_t count = end - start;
  out += (start - first) * static_cast<std::uint64_t>(d);
  std::vector<std::uint32_t> digits(static_cast<std::size_t>(d));
  for (int j = 0; j < d; ++j) digits[static_cast<std::size_t>(j)] = sequence.digits(static_cast<std::uint32_t>(start), j);
  const std::uint64_t stream = stream_key(seed, Stream::sobol_scramble);
  constexpr std::uint64_t kOneBits = 0x3ff0000000000000;
  std::vector<std::uint64_t> words(static_cast<std::size_t>((d + 2) / 3));
  for (std::uint64_t i = start; i < start + count; ++i) {
    double* x = out + (i - start) * static_cast<std::uint64_t>(d);
    if (scramble == Scramble::owen) {
      const std::uint64_t point_key = hash_combine(stream, i);
      for (std::size_t w = 0; w < words.size(); ++w) words[w] = hash_combine(point_key, 1 + w);
      for (int j = 0; j < d; ++j) {
        const std::uint64_t high = owen_scramble(digits[static_cast<std::size_t>(j)], seed, j);
        const std::uint64_t low = static_cast<std::uint32_t>(static_cast<std::uint32_t>(words[static_cast<std::size_t>(j / 3)] >> (20 * (j % 3))) << 12);
        const std::uint64_t bits = (((high << 32) | low) >> 12) | kOneBits;
        double unit;
        std::memcpy(&unit, &bits, sizeof unit);
        x[j] = unit - 1.0;
      }
    } else {
      for (int j = 0; j < d; ++j) x[j] = static_cast<double>(digits[static_cast<std::size_t>(j)]) * 0x1.0p-32;
    }
    if (i + 1 < start + count)
      for (int j = 0; j < d; ++j) digits[static_cast<std::size_t>(j)] ^= sequence.direction(j, std::countr_zero(i + 1));
  }
}

// Blocks of 4096 points, each from the digits of its first point: the same bits on any thread count.
void sobol_from(const SobolSequence& sequence, std::uint64_t start, std::uint64_t count, int d, Scramble scramble,
                std::uint64_t seed, int threads, double* out) {
  constexpr std::uint64_t kBlock = 4096;
  const auto blocks = static_cast<std::int64_t>((count + kBlock - 1) / kBlock);
#pragma omp parallel for schedule(static) num_threads(resolve_threads(threads)) if (worth_threads(count * static_cast<std::uint64_t>(d)))
  for (std::int64_t b = 0; b < blocks; ++b) {
    const std::uint64_t begin = start + static_cast<std::uint64_t>(b) * kBlock;
    sobol_block(sequence, start, begin, std::min(start + count, begin + kBlock), d, scramble, seed, out);
  }
}

void halton_from(std::uint64_t start, std::uint64_t count, int d, bool scramble, std::uint64_t seed, int threads,
                 double* out) {
  for (int k = 0; k < d; ++k) {
    const int base = halton_base(k);
    const auto b = static_cast<std::uint64_t>(base);
    const auto permutations = scramble ? halton_digit_permutations(base, k, seed) : std::vector<std::vector<int>>{};
#pragma omp parallel for schedule(static) num_threads(resolve_threads(threads)) if (worth_threads(count * static_cast<std::uint64_t>(d)))
    for (std::int64_t at = 0; at < static_cast<std::int64_t>(count); ++at) {
      const std::uint64_t i = start + static_cast<std::uint64_t>(at);
      double unit = 0.0;
      if (!scramble) {
        unit = radical_inverse(i, base);
      } else {
        const double inverse_base = 1.0 / base;
        std::uint64_t index = i;
        double scale = inverse_base;
        for (const auto& permutation : permutations) {
          unit += permutation[index % b] * scale;
          index /= b;
          scale *= inverse_base;
        }
      }
      out[(i - start) * static_cast<std::uint64_t>(d) + static_cast<std::uint64_t>(k)] = unit;
    }
  }
}

py::array_t<double> sequence(const std::string& method, int d, std::uint64_t start, std::uint64_t count,
                             std::uint64_t seed, bool scramble, int threads) {
  if (d < 1) throw py::value_error("d must be at least 1, got " + std::to_string(d));
  const Box unit{0.0, 1.0};
  const Scramble owen = scramble ? Scramble::owen : Scramble::none;
  if (method == "sobol") {
    if (start + count > (std::uint64_t{1} << 32) || count > (std::uint64_t{1} << 32))
      throw py::value_error("Sobol supports at most 2^32 points; " + std::to_string(start) + " + " + std::to_string(count) +
                            " asked");
    SobolSequence checked(d);  // throws above the direction table's dimensions
  } else if (method == "halton") {
    halton_base(d - 1);  // throws above the 16 prime bases
  } else if (method != "random") {
    throw py::value_error("no sequence '" + method + "' (allowed: sobol, halton, random)");
  }
  if (start == 0) {
    PointSet points;
    {
      py::gil_scoped_release unlocked;
      if (method == "sobol") points = sobol_points(d, count, unit, owen, seed, threads);
      else if (method == "halton") points = halton_points(d, count, unit, scramble, seed, threads);
      else points = uniform_random_points(d, count, unit, seed, threads);
    }
    return array_owning(std::move(points.coordinates), count, static_cast<std::size_t>(d));
  }
  std::vector<double> out(count * static_cast<std::uint64_t>(d));
  {
    py::gil_scoped_release unlocked;
    if (method == "sobol") {
      sobol_from(SobolSequence(d), start, count, d, owen, seed, threads, out.data());
    } else if (method == "halton") {
      halton_from(start, count, d, scramble, seed, threads, out.data());
    } else {
#pragma omp parallel for schedule(static) num_threads(resolve_threads(threads)) if (worth_threads(out.size()))
      for (std::int64_t at = 0; at < static_cast<std::int64_t>(count); ++at)
        for (int j = 0; j < d; ++j)
          out[static_cast<std::uint64_t>(at) * static_cast<std::uint64_t>(d) + static_cast<std::uint64_t>(j)] =
              random_unit(seed, Stream::random_points, start + static_cast<std::uint64_t>(at), static_cast<std::uint64_t>(j));
    }
  }
  return array_owning(std::move(out), count, static_cast<std::size_t>(d));
}

}  // namespace

void bind_sequence(py::module_& module) {
  using namespace pybind11::literals;
  def_checked(module, "_sequence", &sequence, "method"_a, "d"_a, "start"_a, "count"_a, "seed"_a, "scramble"_a, "threads"_a = 0,
             "Internal: points [start, start + count) of 'sobol', 'halton' or 'random' in [0,1)^d (dfvn.Sobol etc.).");
}

}  // namespace dfvn::python
