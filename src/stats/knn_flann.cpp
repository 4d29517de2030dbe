// The FLANN backend of nearest_neighbour_distances: an exact single-tree KD-index (FLANN 1.9).
#include <flann/flann.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

#include "dfvn/core/parallel.hpp"
#include "dfvn/core/point_set.hpp"
#include "dfvn/stats/kd_tree.hpp"
#include "dfvn/stats/nearest_neighbour.hpp"

namespace dfvn {

std::vector<double> nearest_neighbour_distances_flann(const PointSet& points, int threads, const FractionProgress& progress) {
  const std::size_t n = points.size();
  const auto d = static_cast<std::size_t>(points.dimension);
  // FLANN's Matrix takes a non-const pointer but the index only reads the data.
  flann::Matrix<double> data(const_cast<double*>(points.coordinates.data()), n, d);
  flann::Index<flann::L2<double>> index(data, flann::KDTreeSingleIndexParams(kKdTreeLeafSize));
  index.buildIndex();
  std::vector<std::size_t> indices(n * 2);
  std::vector<double> dist2(n * 2);  // FLANN's L2 returns squared distances
  flann::SearchParams params(flann::FLANN_CHECKS_UNLIMITED);  // exact search
  params.cores = resolve_threads(threads);
  // Queries in chunks, to report progress between them; each query's answer does not depend on the
  // others, so the chunking changes nothing.
  constexpr std::size_t kChunk = std::size_t{1} << 16;
  for (std::size_t first = 0; first < n; first += kChunk) {
    const std::size_t rows = std::min(kChunk, n - first);
    flann::Matrix<double> queries(const_cast<double*>(points.point(first)), rows, d);
    flann::Matrix<std::size_t> index_matrix(indices.data() + first * 2, rows, 2);
    flann::Matrix<double> dist2_matrix(dist2.data() + first * 2, rows, 2);
    index.knnSearch(queries, index_matrix, dist2_matrix, 2, params);
    if (progress) progress(static_cast<double>(first + rows) / static_cast<double>(n));
  }
  std::vector<double> distances(n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t other = indices[i * 2] == i ? indices[i * 2 + 1] : indices[i * 2];
    distances[i] = distance_between(points, i, other);
  }
  return distances;
}

}  // namespace dfvn
