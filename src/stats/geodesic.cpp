#include "dfvn/stats/geodesic.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "dfvn/core/point_set.hpp"

namespace dfvn {

std::vector<double> geodesic_nearest_neighbour_distances(const PointSet& points, KnnBackend backend, int threads) {
  std::vector<double> angles = nearest_neighbour_distances(points, backend, threads);
  for (double& a : angles) a = 2.0 * std::asin(std::min(1.0, 0.5 * a));  // chord -> angle
  return angles;
}

std::vector<double> geodesic_nearest_neighbour_distances_brute_force(const PointSet& points) {
  const std::size_t n = points.size();
  std::vector<double> best(n, std::numeric_limits<double>::infinity());
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t k = i + 1; k < n; ++k) {
      double dot = 0.0;
      for (int j = 0; j < points.dimension; ++j) dot += points.point(i)[j] * points.point(k)[j];
      const double angle = std::acos(std::clamp(dot, -1.0, 1.0));
      best[i] = std::min(best[i], angle);
      best[k] = std::min(best[k], angle);
    }
  return best;
}

NearestNeighbourSummary summarize_geodesic_nearest_neighbours(std::vector<double> angles, int dimension) {
  return summarize_nearest_neighbours(std::move(angles), sphere_area(dimension), dimension - 1);
}

}  // namespace dfvn
