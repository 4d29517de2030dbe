// Order statistics of samples, as NumPy computes them by default (to within an ulp: the same
// interpolation, written in one order): one definition for the statistics (nearest-neighbour q01 and
// median, displacement medians), the field diagnostics and the CNJ study.
#pragma once

#include <algorithm>
#include <cstddef>
#include <stdexcept>
#include <vector>

namespace dfvn {

// numpy.quantile(values, q) with its default 'linear' method: the value at rank q (n - 1) of the
// sorted values, interpolated between the two order statistics around it. `sorted` is non-empty and
// ascending; q outside [0, 1] (or NaN) is refused, as it would index past the values.
inline double quantile_of_sorted(const std::vector<double>& sorted, double q) {
  if (sorted.empty()) throw std::invalid_argument("the quantile of no values");
  if (!(q >= 0.0 && q <= 1.0)) throw std::invalid_argument("a quantile's q must be in [0, 1]");
  const double rank = q * static_cast<double>(sorted.size() - 1);
  const auto below = static_cast<std::size_t>(rank);
  const std::size_t above = std::min(below + 1, sorted.size() - 1);
  return sorted[below] + (rank - static_cast<double>(below)) * (sorted[above] - sorted[below]);
}

// numpy.median: the middle value, or the mean of the two middle values, of ascending `sorted`.
inline double median_of_sorted(const std::vector<double>& sorted) {
  if (sorted.empty()) throw std::invalid_argument("the median of no values");
  const std::size_t n = sorted.size();
  return n % 2 == 1 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
}

}  // namespace dfvn
