#include "stats/periodic_neighbours.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

#include <fmt/format.h>

#include "core/dimension.hpp"
#include "core/parallel.hpp"
#include "stats/kd_tree.hpp"
#include "stats/periodic_images.hpp"

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
std::vector<double> periodic_distances_1d(const PointSet& points) {
  const std::size_t n = points.size();
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return points.coordinates[a] < points.coordinates[b]; });
  std::vector<double> distances(n);
  for (std::size_t r = 0; r < n; ++r) {
    const std::size_t before = order[(r + n - 1) % n], after = order[(r + 1) % n];
    distances[order[r]] = std::min(periodic_distance_between(points, order[r], before),
                                   periodic_distance_between(points, order[r], after));
  }
  return distances;
}

template <int N>
std::vector<double> periodic_distances_kd_tree(const PointSet& points, int threads, const FractionProgress& progress) {
  const PointSetAdaptor<N> adaptor{points};
  KdTree<N> tree(N, adaptor, nanoflann::KDTreeSingleIndexAdaptorParams(kKdTreeLeafSize));
  tree.buildIndex();
  const auto count = static_cast<std::int64_t>(points.size());
  const double lo = points.domain.lo, side = points.domain.side;
  std::vector<double> distances(static_cast<std::size_t>(count));
  constexpr std::int64_t kChunk = 4096;
  std::atomic<std::uint64_t> done{0};
#pragma omp parallel for schedule(dynamic, kChunk) num_threads(resolve_threads(threads))
  for (std::int64_t i = 0; i < count; ++i) {
    if (progress && i % kChunk == 0) {
      const std::uint64_t d = done.fetch_add(static_cast<std::uint64_t>(kChunk), std::memory_order_relaxed);
      if (omp_get_thread_num() == 0) progress(std::min(1.0, static_cast<double>(d) / static_cast<double>(count)));
    }
    const auto self = static_cast<std::size_t>(i);
    double best = std::numeric_limits<double>::infinity();
    // The nearest point other than i to a query position (the point or one of its images); its
    // minimum-image distance decides, so that every image agrees with the brute force to the bit.
    const auto query = [&](const double* y) {
      std::uint32_t index[2];
      double dist2[2];
      nanoflann::KNNResultSet<double, std::uint32_t> result(2);
      result.init(index, dist2);
      tree.findNeighbors(result, y, nanoflann::SearchParams());
      for (std::size_t r = 0; r < result.size(); ++r)
        if (index[r] != self) {
          best = std::min(best, periodic_distance_between(points, self, index[r]));
          break;
        }
    };
    const double* x = points.point(self);
    query(x);
    for_each_periodic_image<N>(x, lo, side, [&] { return best; }, query);
    distances[self] = best;
  }
  return distances;
}

}  // namespace

std::vector<double> periodic_nearest_neighbour_distances(const PointSet& points, int threads,
                                                         const FractionProgress& progress) {
  if (points.size() < 2) throw std::invalid_argument("nearest-neighbour statistics need at least 2 points");
  check_in_periodic_box(points);
  std::vector<double> distances =
      points.dimension == 1
          ? periodic_distances_1d(points)
          : dispatch_dimension(points.dimension,
                               [&]<int N>() { return periodic_distances_kd_tree<N>(points, threads, progress); });
  if (progress) progress(1.0);
  return distances;
}

std::vector<double> periodic_nearest_neighbour_distances_brute_force(const PointSet& points) {
  const std::size_t n = points.size();
  std::vector<double> best(n, std::numeric_limits<double>::infinity());
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t k = i + 1; k < n; ++k) {
      const double d = periodic_distance_between(points, i, k);
      best[i] = std::min(best[i], d);
      best[k] = std::min(best[k], d);
    }
  return best;
}

}  // namespace dfvn
