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

  LatticeDisplacementSummary s;
  std::vector<double> lengths;
  lengths.reserve(n);
  double sum2 = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    if (!include.empty() && !include[i]) continue;
    double r2 = 0.0;
    for (int a = 0; a < dimension; ++a) r2 += u(i)[a] * u(i)[a];
    sum2 += r2;
    lengths.push_back(std::sqrt(r2));
  }
  if (!lengths.empty()) {
    const std::size_t m = lengths.size();
    s.rms = std::sqrt(sum2 / static_cast<double>(m));
    s.fraction_unmoved = static_cast<double>(std::count_if(lengths.begin(), lengths.end(),
                                                           [&](double r) { return r < 0.01 * spacing; })) /
                         static_cast<double>(m);
    std::sort(lengths.begin(), lengths.end());
    s.median = median_of_sorted(lengths);
  }

  // Neighbour pairs along each axis: i and i + stride_a while coordinate a of i is below K - 1.
  double pair_sum2 = 0.0;
  std::size_t pairs = 0;
  std::size_t stride = 1;
  for (int a = 0; a < dimension; ++a) {
    for (std::size_t i = 0; i < n; ++i) {
      if ((i / stride) % static_cast<std::size_t>(grid) == static_cast<std::size_t>(grid - 1)) continue;
      const std::size_t j = i + stride;
      for (int b = 0; b < dimension; ++b) pair_sum2 += (u(i)[b] - u(j)[b]) * (u(i)[b] - u(j)[b]);
      ++pairs;
    }
    stride *= static_cast<std::size_t>(grid);
  }
  s.neighbour_disorder = pairs ? std::sqrt(pair_sum2 / static_cast<double>(pairs)) / spacing : 0.0;

  double order = 0.0;
  for (int a = 0; a < dimension; ++a) {
    std::complex<double> mean = 0.0;
    for (std::size_t i = 0; i < n; ++i) mean += std::polar(1.0, 2.0 * std::numbers::pi * u(i)[a] / spacing);
    order += std::norm(mean / static_cast<double>(n));
  }
  s.lattice_order = order / dimension;
  return s;
}

}  // namespace dfvn
