#include "dfvn/stats/nearest_neighbour.hpp"

#include "dfvn/core/message_text.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "dfvn/core/dimension.hpp"
#include "dfvn/core/parallel.hpp"
#include "dfvn/core/quantile.hpp"
#include "dfvn/stats/distance_scale.hpp"
#include "dfvn/stats/kd_tree.hpp"
#include "dfvn/stats/neighbour_loop.hpp"

namespace dfvn {

// FLANN backend, in its own translation unit (stats/knn_flann.cpp) to keep FLANN's headers apart.
std::vector<double> nearest_neighbour_distances_flann(const PointSet& points, int threads, const FractionProgress& progress);

KnnBackend parse_knn_backend(std::string_view name) {
  if (name == "nanoflann") return KnnBackend::nanoflann;
  if (name == "flann") return KnnBackend::flann;
  throw std::invalid_argument("unknown KD-tree backend " + quote_for_message(name) + " (allowed: nanoflann, flann)");
}

std::string_view to_string(KnnBackend backend) { return backend == KnnBackend::nanoflann ? "nanoflann" : "flann"; }

namespace {

template <int N>
std::vector<double> nearest_neighbour_distances_nanoflann(const PointSet& points, int threads, const FractionProgress& progress) {
  const LeafOrderedTree<N> ordered(points);
  const PointSet& rows = ordered.sorted();
  return neighbour_loop::for_every_point(ordered.original(), threads, progress, [&](std::size_t i) {
    std::uint32_t index[2];
    double dist2[2];
    nanoflann::KNNResultSet<double, std::uint32_t> result(2);
    result.init(index, dist2);
    ordered.tree().findNeighbors(result, rows.point(i), nanoflann::SearchParams());
    // The point itself is at distance 0, so one of the two results is the nearest other point (or a
    // duplicate, also at 0); take whichever is not i.
    const std::uint32_t other = index[0] == static_cast<std::uint32_t>(i) ? index[1] : index[0];
    return distance_between(rows, i, other);
  });
}

}  // namespace

std::vector<double> nearest_neighbour_distances(const PointSet& points, KnnBackend backend, int threads,
                                                const FractionProgress& progress) {
  if (points.size() < 2) throw std::invalid_argument("nearest-neighbour statistics need at least 2 points");
  // Squared differences of huge or tiny coordinates overflow or underflow: compute at unit scale
  // (stats/distance_scale.hpp; exact, and no copy for ordinary sets).
  if (const double scale = coordinate_scale(points); scale != 1.0) {
    std::vector<double> distances = nearest_neighbour_distances(scaled_point_set(points, scale), backend, threads, progress);
    for (double& d : distances) d *= scale;
    return distances;
  }
  std::vector<double> distances =
      backend == KnnBackend::flann
          ? nearest_neighbour_distances_flann(points, threads, progress)
          : dispatch_dimension(points.dimension,
                               [&]<int N>() { return nearest_neighbour_distances_nanoflann<N>(points, threads, progress); });
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
  return summarize_nearest_neighbours(std::move(distances), points.domain.volume(points.dimension), points.dimension);
}

NearestNeighbourSummary summarize_nearest_neighbours(std::vector<double> distances, double measure,
                                                     int manifold_dimension) {
  if (distances.empty()) throw std::invalid_argument("no distances to summarise");
  NearestNeighbourSummary s;
  s.points = distances.size();
  double sum = 0.0;  // in index order: the same for any thread count
  for (double d : distances) sum += d;
  s.mean = sum / static_cast<double>(distances.size());
  std::sort(distances.begin(), distances.end());
  const std::size_t n = distances.size();
  s.min = distances.front();
  s.median = median_of_sorted(distances);
  s.q01 = quantile_of_sorted(distances, 0.01);
  const double density = static_cast<double>(n) / measure;
  s.median_scaled = s.median * std::pow(density, 1.0 / manifold_dimension);
  return s;
}

}  // namespace dfvn
