// The FLANN backend of nearest_neighbour_distances(_of_first): an exact single-tree KD-index (FLANN 1.9) over
// every point, queried at the first `queries`.
#include <flann/flann.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

#include "dfvn/core/parallel.hpp"
#include "dfvn/core/point_set.hpp"
#include "dfvn/stats/kd_tree.hpp"
#include "dfvn/stats/nearest_neighbour.hpp"

namespace dfvn {

std::vector<double> nearest_neighbour_distances_flann(const PointSet& points, std::size_t queries, int threads,
                                                      const FractionProgress& progress) {
  const std::size_t n = points.size();
  const auto d = static_cast<std::size_t>(points.dimension);
  // FLANN's Matrix takes a non-const pointer but the index only reads the data.
  flann::Matrix<double> data(const_cast<double*>(points.coordinates.data()), n, d);
  flann::Index<flann::L2<double>> index(data, flann::KDTreeSingleIndexParams(kKdTreeLeafSize));
  index.buildIndex();
  std::vector<std::size_t> indices(queries * 2);
  std::vector<double> dist2(queries * 2);  // FLANN's L2 returns squared distances
  flann::SearchParams params(flann::FLANN_CHECKS_UNLIMITED);  // exact search
  params.cores = resolve_threads(threads);
  // Queries in chunks, to report progress between them; each query's answer does not depend on the
  // others, so the chunking changes nothing.
  constexpr std::size_t kChunk = std::size_t{1} << 16;
  for (std::size_t first = 0; first < queries; first += kChunk) {
    const std::size_t rows = std::min(kChunk, queries - first);
    flann::Matrix<double> query_matrix(const_cast<double*>(points.point(first)), rows, d);
    flann::Matrix<std::size_t> index_matrix(indices.data() + first * 2, rows, 2);
    flann::Matrix<double> dist2_matrix(dist2.data() + first * 2, rows, 2);
    index.knnSearch(query_matrix, index_matrix, dist2_matrix, 2, params);
    if (progress) progress(static_cast<double>(first + rows) / static_cast<double>(queries));
  }
  std::vector<double> distances(queries);
  for (std::size_t i = 0; i < queries; ++i) {
    const std::size_t other = indices[i * 2] == i ? indices[i * 2 + 1] : indices[i * 2];
    distances[i] = distance_between(points, i, other);
  }
  return distances;
}

}  // namespace dfvn
