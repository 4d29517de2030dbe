#include "dfvn/stats/lattice_displacement.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "dfvn/core/parallel.hpp"

namespace dfvn {

LatticeDisplacementSummary summarize_lattice_displacements(int dimension, int grid, double spacing,
                                                           const std::vector<double>& displacements,
                                                           const std::vector<unsigned char>& include, int threads) {
  const std::size_t n = displacements.size() / static_cast<std::size_t>(dimension);
  if (n == 0 || displacements.size() != n * static_cast<std::size_t>(dimension) || !(spacing > 0.0))
    throw std::invalid_argument("lattice displacements: empty table or bad spacing");
  if (std::pow(static_cast<double>(grid), dimension) != static_cast<double>(n))
    throw std::invalid_argument("lattice displacements: the table does not hold K^N rows");
  if (!include.empty() && include.size() != n) throw std::invalid_argument("lattice displacements: mask size");
  auto u = [&](std::size_t i) { return displacements.data() + i * dimension; };

  LatticeDisplacementSums sums;
  sums.points = n;
  const auto D = static_cast<std::size_t>(dimension);
  sums.pair_sum2.assign(D, 0.0);
  sums.bragg.assign(D, 0.0);
  std::vector<std::uint64_t> axis_pairs(D, 0);
  std::vector<double> lengths;
  lengths.reserve(n);
  double median = 0.0;
  // Tasks 0..N-1: axis a's neighbour pairs (i and i + stride_a while coordinate a of i is below K - 1) and
  // its Bragg amplitude; task N: the lengths and their median. Each sum runs in index order in one task,
  // so the summary is the same bits on any number of threads.
  const int tasks = dimension + 1;
  threads = resolve_threads(threads);
#pragma omp parallel for num_threads(threads) schedule(dynamic, 1) if (threads > 1 && worth_threads(displacements.size()))
  for (int task = 0; task < tasks; ++task) {
    if (task == dimension) {
      for (std::size_t i = 0; i < n; ++i) {
        if (!include.empty() && !include[i]) continue;
        double r2 = 0.0;
        for (int a = 0; a < dimension; ++a) r2 += u(i)[a] * u(i)[a];
        sums.sum2 += r2;
        lengths.push_back(std::sqrt(r2));
        sums.unmoved += lengths.back() < 0.01 * spacing;
      }
      // median_of_sorted's values, by selection: the middle one, and for an even count the largest below it.
      const std::size_t m = lengths.size();
      if (m > 0) {
        const auto mid = lengths.begin() + static_cast<std::ptrdiff_t>(m / 2);
        std::nth_element(lengths.begin(), mid, lengths.end());
        median = m % 2 == 1 ? *mid : 0.5 * (*std::max_element(lengths.begin(), mid) + *mid);
      }
      continue;
    }
    const auto a = static_cast<std::size_t>(task);
    std::size_t stride = 1;
    for (std::size_t b = 0; b < a; ++b) stride *= static_cast<std::size_t>(grid);
    double pair_sum2 = 0.0;
    std::uint64_t pairs = 0;
    for (std::size_t i = 0; i < n; ++i) {
      if ((i / stride) % static_cast<std::size_t>(grid) == static_cast<std::size_t>(grid - 1)) continue;
      const std::size_t j = i + stride;
      for (int b = 0; b < dimension; ++b) pair_sum2 += (u(i)[b] - u(j)[b]) * (u(i)[b] - u(j)[b]);
      ++pairs;
    }
    std::complex<double> bragg = 0.0;
    for (std::size_t i = 0; i < n; ++i) bragg += std::polar(1.0, 2.0 * std::numbers::pi * u(i)[a] / spacing);
    sums.pair_sum2[a] = pair_sum2;
    sums.bragg[a] = bragg;
    axis_pairs[a] = pairs;
  }
  sums.included = lengths.size();
  for (const std::uint64_t p : axis_pairs) sums.pairs += p;
  return finish_lattice_displacements(dimension, spacing, sums, median);
}

LatticeDisplacementSummary finish_lattice_displacements(int dimension, double spacing, const LatticeDisplacementSums& sums,
                                                        double median_length) {
  LatticeDisplacementSummary s;
  if (sums.included > 0) {
    const auto m = static_cast<double>(sums.included);
    s.rms = std::sqrt(sums.sum2 / m);
    s.fraction_unmoved = static_cast<double>(sums.unmoved) / m;
    s.median = median_length;
  }
  double pair_sum2 = 0.0;  // the axes' sums, in axis order
  for (double axis_sum : sums.pair_sum2) pair_sum2 += axis_sum;
  s.neighbour_disorder = sums.pairs ? std::sqrt(pair_sum2 / static_cast<double>(sums.pairs)) / spacing : 0.0;
  double order = 0.0;
  for (int a = 0; a < dimension; ++a) order += std::norm(sums.bragg[static_cast<std::size_t>(a)] / static_cast<double>(sums.points));
  s.lattice_order = order / dimension;
  return s;
}

}  // namespace dfvn
