#include "dfvn/stats/distance_scale.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include <fmt/format.h>

namespace dfvn {

void check_domain_side(double side, std::string_view what) {
  if (!(side >= kMinDomainSide && side <= kMaxDomainSide))
    throw std::invalid_argument(fmt::format(
        "{} {:g} is outside [2^-1000, 2^1000] = [{:.4g}, {:.4g}], the sides whose distances stay finite, normal "
        "doubles",
        what, side, kMinDomainSide, kMaxDomainSide));
}

double coordinate_scale(const PointSet& points) {
  double largest = 0.0;
  for (std::size_t c = 0; c < points.coordinates.size(); ++c) {
    const double x = points.coordinates[c];
    if (!std::isfinite(x))
      throw std::invalid_argument(fmt::format("point {} (0-based) has x{} = {}; coordinates must be finite",
                                              c / static_cast<std::size_t>(points.dimension),
                                              c % static_cast<std::size_t>(points.dimension), x));
    largest = std::max(largest, std::abs(x));
  }
  if (largest == 0.0 || (largest >= 0x1p-256 && largest <= 0x1p256)) return 1.0;
  return std::ldexp(1.0, std::ilogb(largest));
}

double domain_scale(double side) {
  if (!(side > 0.0) || !std::isfinite(side) || (side >= 0x1p-32 && side <= 0x1p32)) return 1.0;
  return std::ldexp(1.0, std::ilogb(side));
}

PointSet scaled_point_set(const PointSet& points, double scale) {
  PointSet scaled = points;
  for (double& x : scaled.coordinates) x /= scale;
  scaled.domain.lo /= scale;
  scaled.domain.side /= scale;
  return scaled;
}

void check_nearest_neighbours_resolved(const PointSet& points, const std::vector<double>& distances) {
  const double bound = kMinResolvedDistance * coordinate_scale(points);
  std::vector<std::size_t> unresolved;
  for (std::size_t i = 0; i < distances.size(); ++i)
    if (distances[i] < bound) unresolved.push_back(i);
  if (unresolved.empty()) return;
  // A distance of exactly 0 is right for a point with an exact duplicate: find duplicates by sorting
  // the points lexicographically, O(n log n), only when some distance is this small.
  const std::size_t n = points.size();
  const auto dimension = static_cast<std::size_t>(points.dimension);
  auto less = [&](std::size_t a, std::size_t b) {
    return std::lexicographical_compare(points.point(a), points.point(a) + dimension, points.point(b),
                                        points.point(b) + dimension);
  };
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), less);
  std::vector<char> duplicated(n, 0);
  for (std::size_t r = 1; r < n; ++r)
    if (std::equal(points.point(order[r]), points.point(order[r]) + dimension, points.point(order[r - 1])))
      duplicated[order[r]] = duplicated[order[r - 1]] = 1;
  for (std::size_t i : unresolved)
    if (distances[i] != 0.0 || !duplicated[i])
      throw std::invalid_argument(fmt::format(
          "point {} (0-based) and its nearest neighbour are closer than 2^-510 x {:g} = {:.3g} without being equal: "
          "squared distances that small underflow, and the KD-tree cannot tell neighbours apart",
          i, coordinate_scale(points), bound));
}

}  // namespace dfvn
