#include "dfvn/stats/nearest_neighbour.hpp"

#include "dfvn/core/message_text.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "dfvn/core/dimension.hpp"
#include "dfvn/core/quantile.hpp"
#include "dfvn/stats/distance_scale.hpp"
#include "dfvn/stats/nearest_other.hpp"
#include "dfvn/stats/neighbour_loop.hpp"

namespace dfvn {

// FLANN backend, in its own translation unit (stats/knn_flann.cpp) to keep FLANN's headers apart: the
// first `queries` points queried against all of them.
std::vector<double> nearest_neighbour_distances_flann(const PointSet& points, std::size_t queries, int threads,
                                                      const FractionProgress& progress);

KnnBackend parse_knn_backend(std::string_view name) {
  if (name == "nanoflann") return KnnBackend::nanoflann;
  if (name == "flann") return KnnBackend::flann;
  throw std::invalid_argument("unknown KD-tree backend " + quote_for_message(name) + " (allowed: nanoflann, flann)");
}

std::string_view to_string(KnnBackend backend) { return backend == KnnBackend::nanoflann ? "nanoflann" : "flann"; }

namespace {

// nanoflann builds the tree over every point; the queries (the first `queries` points) are
// stats/nearest_other.hpp's, made a leaf at a time in the tree's order and scattered back to the input's
// indices.
template <int N>
std::vector<double> nearest_neighbour_distances_nanoflann(const PointSet& points, std::size_t queries, int threads,
                                                          const FractionProgress& progress) {
  return nearest_other::nearest_distances<N, false>(points, queries, threads, progress, nearest_other::Torus{},
                                                    [&](std::size_t i, std::size_t j) { return distance_between(points, i, j); });
}

}  // namespace

std::vector<double> nearest_neighbour_distances(const PointSet& points, KnnBackend backend, int threads,
                                                const FractionProgress& progress) {
  return nearest_neighbour_distances_of_first(points, points.size(), backend, threads, progress);
}

std::vector<double> nearest_neighbour_distances_of_first(const PointSet& points, std::size_t queries, KnnBackend backend,
                                                         int threads, const FractionProgress& progress) {
  if (points.size() < 2) throw std::invalid_argument("nearest-neighbour statistics need at least 2 points");
  if (queries > points.size()) throw std::invalid_argument("more query points than points");
  // Squared differences of huge or tiny coordinates overflow or underflow: compute at unit scale
  // (stats/distance_scale.hpp; exact, and no copy for ordinary sets).
  if (const double scale = coordinate_scale(points); scale != 1.0) {
    std::vector<double> distances =
        nearest_neighbour_distances_of_first(scaled_point_set(points, scale), queries, backend, threads, progress);
    for (double& d : distances) d *= scale;
    return distances;
  }
  std::vector<double> distances;
  if (queries > 0)
    distances = backend == KnnBackend::flann
                    ? nearest_neighbour_distances_flann(points, queries, threads, progress)
                    : dispatch_dimension(points.dimension, [&]<int N>() {
                        return nearest_neighbour_distances_nanoflann<N>(points, queries, threads, progress);
                      });
  if (progress) progress(1.0);
  return distances;
}

double distance_between(const PointSet& points, std::size_t i, std::size_t j) {
  const double* a = points.point(i);
  const double* b = points.point(j);
  double dist2 = 0.0;
  for (int k = 0; k < points.dimension; ++k) dist2 += (a[k] - b[k]) * (a[k] - b[k]);
  return std::sqrt(dist2);
}

std::vector<double> nearest_neighbour_distances_brute_force(const PointSet& points) {
  return neighbour_loop::brute_force(points.size(), [&](std::size_t i, std::size_t k) { return distance_between(points, i, k); });
}

NearestNeighbourSummary summarize_nearest_neighbours(std::vector<double> distances, const PointSet& points) {
  // side^N overflows or underflows for extreme sides: summarise at unit scale (stats/distance_scale.hpp).
  if (const double scale = domain_scale(points.domain.side); scale != 1.0) {
    for (double& d : distances) d /= scale;
    NearestNeighbourSummary s = summarize_nearest_neighbours(std::move(distances), scaled_point_set(PointSet{points.dimension, {}, points.domain}, scale));
    for (double* value : {&s.min, &s.median, &s.q01, &s.mean}) *value *= scale;
    return s;
  }
  return summarize_nearest_neighbours(std::move(distances), points.domain.measure(points.dimension),
                                      points.domain.manifold_dimension(points.dimension));
}

NearestNeighbourSummary summarize_nearest_neighbours(std::vector<double> distances, double measure,
                                                     int manifold_dimension) {
  if (distances.empty()) throw std::invalid_argument("no distances to summarise");
  double sum = 0.0;  // in index order: the same for any thread count
  for (double d : distances) sum += d;
  // Only the order statistics the summary reads, by selection in ascending rank order (each one splits
  // off the part below it): the values a full sort puts there, in linear time.
  const std::vector<std::uint64_t> ranks = nearest_neighbour_summary_ranks(distances.size());
  std::vector<double> values;
  values.reserve(ranks.size());
  auto from = distances.begin();
  for (const std::uint64_t k : ranks) {
    const auto at = distances.begin() + static_cast<std::ptrdiff_t>(k);
    std::nth_element(from, at, distances.end());
    values.push_back(*at);
    from = at + 1;
  }
  return summarize_nearest_neighbours(distances.size(), sum, sorted_at_ranks(ranks, std::move(values)), measure,
                                      manifold_dimension);
}

std::vector<std::uint64_t> nearest_neighbour_summary_ranks(std::uint64_t n) {
  if (n == 0) return {};
  const auto below = static_cast<std::uint64_t>(0.01 * static_cast<double>(n - 1));
  std::vector<std::uint64_t> ranks{0, below, std::min(below + 1, n - 1), n / 2};
  if (n % 2 == 0) ranks.push_back(n / 2 - 1);
  std::sort(ranks.begin(), ranks.end());
  ranks.erase(std::unique(ranks.begin(), ranks.end()), ranks.end());
  return ranks;
}

std::function<double(std::uint64_t)> sorted_at_ranks(std::vector<std::uint64_t> ranks, std::vector<double> values) {
  return [ranks = std::move(ranks), values = std::move(values)](std::uint64_t k) {
    const auto it = std::lower_bound(ranks.begin(), ranks.end(), k);
    if (it == ranks.end() || *it != k) throw std::logic_error("an order statistic that was not fetched");
    return values[static_cast<std::size_t>(it - ranks.begin())];
  };
}

NearestNeighbourSummary summarize_nearest_neighbours(std::uint64_t count, double sum,
                                                     const std::function<double(std::uint64_t)>& sorted_at,
                                                     double measure, int manifold_dimension) {
  if (count == 0) throw std::invalid_argument("no distances to summarise");
  NearestNeighbourSummary s;
  s.points = count;
  s.mean = sum / static_cast<double>(count);
  const std::uint64_t n = count;
  s.min = sorted_at(0);
  // median_of_sorted and quantile_of_sorted (core/quantile.hpp), on sorted_at.
  s.median = n % 2 == 1 ? sorted_at(n / 2) : 0.5 * (sorted_at(n / 2 - 1) + sorted_at(n / 2));
  const double rank = 0.01 * static_cast<double>(n - 1);
  const auto below = static_cast<std::uint64_t>(rank);
  const std::uint64_t above = std::min(below + 1, n - 1);
  const double at_below = sorted_at(below);
  s.q01 = at_below + (rank - static_cast<double>(below)) * (sorted_at(above) - at_below);
  const double density = static_cast<double>(n) / measure;
  s.median_scaled = s.median * std::pow(density, 1.0 / manifold_dimension);
  return s;
}

}  // namespace dfvn
