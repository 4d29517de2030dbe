#include "dfvn/stats/lattice_displacement.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <stdexcept>

#include "dfvn/core/quantile.hpp"

namespace dfvn {

LatticeDisplacementSummary summarize_lattice_displacements(int dimension, int grid, double spacing,
                                                           const std::vector<double>& displacements,
                                                           const std::vector<unsigned char>& include) {
  const std::size_t n = displacements.size() / static_cast<std::size_t>(dimension);
  if (n == 0 || displacements.size() != n * static_cast<std::size_t>(dimension) || !(spacing > 0.0))
    throw std::invalid_argument("lattice displacements: empty table or bad spacing");
  if (std::pow(static_cast<double>(grid), dimension) != static_cast<double>(n))
    throw std::invalid_argument("lattice displacements: the table does not hold K^N rows");
  if (!include.empty() && include.size() != n) throw std::invalid_argument("lattice displacements: mask size");
  auto u = [&](std::size_t i) { return displacements.data() + i * dimension; };

  LatticeDisplacementSums sums;
  sums.points = n;
  std::vector<double> lengths;
  lengths.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (!include.empty() && !include[i]) continue;
    double r2 = 0.0;
    for (int a = 0; a < dimension; ++a) r2 += u(i)[a] * u(i)[a];
    sums.sum2 += r2;
    lengths.push_back(std::sqrt(r2));
    sums.unmoved += lengths.back() < 0.01 * spacing;
  }
  sums.included = lengths.size();

  // Neighbour pairs along each axis: i and i + stride_a while coordinate a of i is below K - 1.
  sums.pair_sum2.assign(static_cast<std::size_t>(dimension), 0.0);
  std::size_t stride = 1;
  for (int a = 0; a < dimension; ++a) {
    for (std::size_t i = 0; i < n; ++i) {
      if ((i / stride) % static_cast<std::size_t>(grid) == static_cast<std::size_t>(grid - 1)) continue;
      const std::size_t j = i + stride;
      for (int b = 0; b < dimension; ++b) sums.pair_sum2[a] += (u(i)[b] - u(j)[b]) * (u(i)[b] - u(j)[b]);
      ++sums.pairs;
    }
    stride *= static_cast<std::size_t>(grid);
  }
  sums.bragg.assign(static_cast<std::size_t>(dimension), 0.0);
  for (int a = 0; a < dimension; ++a)
    for (std::size_t i = 0; i < n; ++i) sums.bragg[a] += std::polar(1.0, 2.0 * std::numbers::pi * u(i)[a] / spacing);
  double median = 0.0;
  if (!lengths.empty()) {
    std::sort(lengths.begin(), lengths.end());
    median = median_of_sorted(lengths);
  }
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
