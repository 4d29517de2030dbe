// Nearest-neighbour distances and their summary (Table 1's statistics).
#pragma once

#include <cstdint>
#include <functional>
#include <string_view>
#include <vector>

#include "dfvn/core/progress.hpp"
#include "dfvn/core/point_set.hpp"

namespace dfvn {

enum class KnnBackend { nanoflann, flann };
KnnBackend parse_knn_backend(std::string_view name);  // "nanoflann" | "flann"
std::string_view to_string(KnnBackend backend);

// For every point, the Euclidean distance to its nearest other point (k = 2 self-query on an exact
// KD-tree; a duplicate point has distance 0). Needs at least 2 points. Independent of thread count.
// Both backends only find the neighbour; its distance comes from distance_between(). `progress`:
// queries done over points.
std::vector<double> nearest_neighbour_distances(const PointSet& points, KnnBackend backend, int threads,
                                                const FractionProgress& progress = {});

// The same distances for the first `queries` points only (rows 0 .. queries - 1), each to its nearest
// other point among ALL the points: the tree is built over every point and only the first `queries` are
// queried, so each is bit for bit nearest_neighbour_distances(points, ...)'s value for that point (the
// same tree, search and distance_between). For a region measured with a halo around it (sample --stream's
// buckets): the region's points first, the halo's after. Needs at least 2 points and queries <= size()
// (queries = 0 gives no distances). Independent of thread count. `progress`: the tree's leaves done.
std::vector<double> nearest_neighbour_distances_of_first(const PointSet& points, std::size_t queries, KnnBackend backend,
                                                         int threads, const FractionProgress& progress = {});

// Euclidean distance between points i and j, summing squared differences over axes in order. Every
// backend reports distances through this one function, so they agree to the last bit whenever they
// find the same neighbour (FLANN's own L2 sums in another order).
double distance_between(const PointSet& points, std::size_t i, std::size_t j);

// Brute force, O(n^2): the reference the KD-trees are tested against.
std::vector<double> nearest_neighbour_distances_brute_force(const PointSet& points);

struct NearestNeighbourSummary {
  std::uint64_t points = 0;
  double min = 0.0;
  double median = 0.0;  // the mean of the two middle values for an even count (as numpy.median)
  double q01 = 0.0;     // the 1% quantile (numpy.quantile's default linear interpolation)
  double mean = 0.0;
  // median * (points / domain measure)^(1/M): the median in units of the mean spacing, so that sets
  // of different density compare (a cubic lattice scores 1); M the dimension of the domain (N, or N - 1
  // on the sphere), the measure its volume or area (core/domain.hpp).
  double median_scaled = 0.0;
};

// The ranks of n sorted distances that summarize_nearest_neighbours(count, sum, sorted_at, ...) reads (the
// minimum, q01's two neighbours, the median's one or two), sorted and without repeats; and a sorted_at that
// answers those ranks from their values (any other rank is a logic_error). For selections over data that
// is not in one sorted array (sample --stream's sorted runs, dfvn-sample-mpi's ranks).
std::vector<std::uint64_t> nearest_neighbour_summary_ranks(std::uint64_t n);
std::function<double(std::uint64_t)> sorted_at_ranks(std::vector<std::uint64_t> ranks, std::vector<double> values);

NearestNeighbourSummary summarize_nearest_neighbours(std::vector<double> distances, const PointSet& points);
// The same for points on a manifold of `manifold_dimension` and `measure` (volume or area): the
// median is scaled by (points / measure)^(1 / manifold_dimension).
NearestNeighbourSummary summarize_nearest_neighbours(std::vector<double> distances, double measure,
                                                     int manifold_dimension);
// The same from the count, the sum of the distances in index order and the ascending order statistics
// (sorted_at(k): the k-th smallest distance), for distances that are never all in memory at once
// (experiment/streamed_sampling.hpp). The formulas are summarize_nearest_neighbours'.
NearestNeighbourSummary summarize_nearest_neighbours(std::uint64_t count, double sum,
                                                     const std::function<double(std::uint64_t)>& sorted_at,
                                                     double measure, int manifold_dimension);

}  // namespace dfvn
