#include "dfvn/stats/periodic_neighbours.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <utility>

#include <fmt/format.h>

#include "dfvn/core/dimension.hpp"
#include "dfvn/stats/cell_grid_neighbours.hpp"
#include "dfvn/stats/distance_scale.hpp"
#include "dfvn/stats/neighbour_loop.hpp"
#include "dfvn/stats/nearest_other.hpp"
#include "dfvn/stats/periodic_images.hpp"

namespace dfvn {

double periodic_distance_between(const PointSet& points, std::size_t i, std::size_t j) {
  const double* a = points.point(i);
  const double* b = points.point(j);
  const double side = points.domain.side;
  double dist2 = 0.0;
  for (int k = 0; k < points.dimension; ++k) {
    const double d = minimum_image(a[k] - b[k], side);
    dist2 += d * d;
  }
  return std::sqrt(dist2);
}

void check_in_periodic_box(const PointSet& points) {
  const double lo = points.domain.lo, hi = points.domain.lo + points.domain.side;
  for (std::size_t i = 0; i < points.size(); ++i)
    for (int k = 0; k < points.dimension; ++k)
      if (!(points.point(i)[k] >= lo && points.point(i)[k] <= hi))
        throw std::invalid_argument(fmt::format(
            "periodic distances need every point in the torus [{:g}, {:g})^{}: point {} (0-based) has x{} = {:.17g}", lo,
            hi, points.dimension, i, k, points.point(i)[k]));
}

namespace {

// 1D: after sorting, a point's nearest neighbour is the one before or after it, around the circle.
std::vector<double> periodic_distances_1d(const PointSet& points, std::size_t queries) {
  const std::size_t n = points.size();
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return points.coordinates[a] < points.coordinates[b]; });
  std::vector<double> distances(queries);
  for (std::size_t r = 0; r < n; ++r) {
    if (order[r] >= queries) continue;
    const std::size_t before = order[(r + n - 1) % n], after = order[(r + 1) % n];
    distances[order[r]] = std::min(periodic_distance_between(points, order[r], before),
                                   periodic_distance_between(points, order[r], after));
  }
  return distances;
}

// stats/nearest_other.hpp's search on the torus: one walk of nanoflann's tree per point, a subtree as near
// as the way round through the opposite face allows, made a leaf at a time in the tree's order and
// scattered back to the input's indices; each pair's distance is periodic_distance_between's.
template <int N>
std::vector<double> periodic_distances_kd_tree(const PointSet& points, std::size_t queries, int threads,
                                               const FractionProgress& progress) {
  const double lo = points.domain.lo, side = points.domain.side;
  return nearest_other::nearest_distances<N, true>(points, queries, threads, progress, nearest_other::periodic_torus(lo, side),
                                                   [&](std::size_t i, std::size_t j) { return periodic_distance_between(points, i, j); });
}

}  // namespace

std::vector<double> periodic_nearest_neighbour_distances(const PointSet& points, int threads,
                                                         const FractionProgress& progress) {
  return periodic_nearest_neighbour_distances_of_first(points, points.size(), threads, progress);
}

namespace {

// The search itself, on a set already at unit scale.
std::vector<double> periodic_distances_at_scale(const PointSet& points, std::size_t queries, int threads,
                                                const FractionProgress& progress) {
  std::vector<double> distances;
  if (queries > 0) {
    if (points.dimension == 1)
      distances = periodic_distances_1d(points, queries);
    else if (auto grid = cell_grid::periodic_nearest_distances(points, queries, threads, progress))
      distances = std::move(*grid);
    else
      distances = dispatch_dimension(points.dimension,
                                     [&]<int N>() { return periodic_distances_kd_tree<N>(points, queries, threads, progress); });
  }
  if (progress) progress(1.0);
  return distances;
}

}  // namespace

std::vector<double> periodic_nearest_neighbour_distances_of_first(const PointSet& points, std::size_t queries, int threads,
                                                                  const FractionProgress& progress) {
  if (points.size() < 2) throw std::invalid_argument("nearest-neighbour statistics need at least 2 points");
  if (queries > points.size()) throw std::invalid_argument("more query points than points");
  check_in_periodic_box(points);
  // Squared differences of huge or tiny coordinates overflow or underflow: compute at unit scale, exactly
  // (stats/distance_scale.hpp), box and all, with one scale: the box's when it is out of range, else the
  // coordinates'. (Rescaling again after the first scaling went back and forth for ever when the two were
  // far apart, points in [0, 1] of a box of side 1e300, and overflowed the stack.)
  double scale = domain_scale(points.domain.side);
  if (scale == 1.0) scale = coordinate_scale(points);
  if (scale == 1.0) return periodic_distances_at_scale(points, queries, threads, progress);
  std::vector<double> distances = periodic_distances_at_scale(scaled_point_set(points, scale), queries, threads, progress);
  for (double& d : distances) d *= scale;
  return distances;
}

std::vector<double> periodic_nearest_neighbour_distances_brute_force(const PointSet& points) {
  return neighbour_loop::brute_force(points.size(),
                                     [&](std::size_t i, std::size_t k) { return periodic_distance_between(points, i, k); });
}

}  // namespace dfvn
