#include "dfvn/stats/point_set_statistics.hpp"

#include <algorithm>
#include <limits>
#include <numeric>
#include <stdexcept>

#include <fmt/format.h>

#include "dfvn/core/stopwatch.hpp"
#include "dfvn/io/csv.hpp"
#include "dfvn/stats/distance_scale.hpp"
#include "dfvn/stats/geodesic.hpp"
#include "dfvn/stats/periodic_neighbours.hpp"

namespace dfvn {

std::vector<double> nearest_neighbour_distances_any_dimension(const PointSet& points, KnnBackend backend, int threads,
                                                              const FractionProgress& progress) {
  if (points.size() < 2) throw std::invalid_argument("nearest-neighbour statistics need at least 2 points");
  if (points.dimension != 1) return nearest_neighbour_distances(points, backend, threads, progress);
  // 1D: after sorting, a point's nearest neighbour is the one before or after it.
  const std::size_t n = points.size();
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return points.coordinates[a] < points.coordinates[b]; });
  std::vector<double> distances(n);
  for (std::size_t r = 0; r < n; ++r) {
    const double x = points.coordinates[order[r]];
    double best = std::numeric_limits<double>::infinity();
    if (r > 0) best = std::min(best, x - points.coordinates[order[r - 1]]);
    if (r + 1 < n) best = std::min(best, points.coordinates[order[r + 1]] - x);
    distances[order[r]] = best;
  }
  return distances;
}

std::vector<double> nearest_neighbour_distances_in_domain(const PointSet& points, KnnBackend backend, int threads,
                                                          const FractionProgress& progress) {
  switch (points.domain.kind) {
    case DomainKind::torus: return periodic_nearest_neighbour_distances(points, threads, progress);
    case DomainKind::sphere: {
      std::vector<double> angles = geodesic_nearest_neighbour_distances(points, backend, threads);
      if (progress) progress(1.0);
      return angles;
    }
    case DomainKind::cube:
    case DomainKind::ball: break;
  }
  return nearest_neighbour_distances_any_dimension(points, backend, threads, progress);
}

void check_point_set(const PointSet& points) {
  if (points.size() < 2) throw std::invalid_argument(fmt::format("the set has {} point(s); at least 2 are needed", points.size()));
  check_domain_side(points.domain.side);
  const Box box = points.domain.box();
  const bool sphere = points.domain.kind == DomainKind::sphere;
  for (std::size_t i = 0; i < points.size(); ++i) {
    for (int k = 0; k < points.dimension && !sphere; ++k)
      if (!box.contains(points.point(i) + k, 1))
        throw std::invalid_argument(fmt::format(
            "point {} (0-based) has x{} = {:.17g}, outside the domain [{:g}, {:g}]^{}; give the side with --domain-side", i,
            k, points.point(i)[k], box.lo, box.lo + box.side, points.dimension));
    if (!points.domain.contains(points.point(i), points.dimension))
      throw std::invalid_argument(fmt::format("point {} (0-based) lies outside {}", i, points.domain.describe(points.dimension)));
  }
}

PointSetStatistics measure_point_set(const PointSet& points, const PointSetStatisticsOptions& options,
                                     const StatisticsProgress& progress) {
  check_point_set(points);
  PointSetStatistics out;
  Stopwatch stopwatch;
  const FractionProgress report = [&](double f) {
    if (progress) progress("statistics", f);
  };
  report(0.0);
  std::vector<double> distances = nearest_neighbour_distances_in_domain(points, options.knn, options.threads, report);
  // 1D needs no squares; the sphere's angles come from unit vectors
  if (points.dimension > 1 && points.domain.kind != DomainKind::sphere) check_nearest_neighbours_resolved(points, distances);
  out.nearest = summarize_nearest_neighbours(std::move(distances), points);
  if (options.discrepancy) {
    for (std::size_t d = 0; d < std::size(kAllDiscrepancies); ++d) {
      const DiscrepancyKind kind = kAllDiscrepancies[d];
      const std::string stage(to_string(kind));
      out.discrepancies[d] = discrepancy(points, kind, options.threads, [&](double f) {
        if (progress) progress(stage, f);
      });
    }
  }
  out.seconds = stopwatch.seconds();
  return out;
}

int point_statistics_stage_count(const PointSetStatisticsOptions& options) {
  return 1 + (options.discrepancy ? static_cast<int>(std::size(kAllDiscrepancies)) : 0);
}

namespace {
// Costs per point and dimension of a nearest-neighbour query, and per pair and dimension of a
// discrepancy's sum, in the same (arbitrary) unit as expected_spectrum_cost's; from timings of 2D-5D sets.
constexpr double kNearestNeighbourCost = 300.0, kDiscrepancyPairCost = 1.0;
}  // namespace

std::vector<double> point_statistics_stage_weights(const PointSetStatisticsOptions& options, std::size_t points,
                                                   int dimension) {
  const double n = static_cast<double>(points), d = dimension;
  // A kd-tree query per point against each discrepancy's sum over the n^2 / 2 pairs.
  std::vector<double> weights{n * kNearestNeighbourCost * d};
  if (options.discrepancy)
    for (std::size_t k = 0; k < std::size(kAllDiscrepancies); ++k) weights.push_back(0.5 * n * n * d * kDiscrepancyPairCost);
  return weights;
}

std::string point_statistics_csv_header() {
  std::string header =
      "input,set,dim,points,nn_min,nn_q01,nn_median,nn_mean,nn_median_scaled,seconds_stats,domain,domain_side";
  for (DiscrepancyKind kind : kAllDiscrepancies) header += "," + std::string(csv_column(kind));
  return header + "\n";
}

std::string point_statistics_csv_row(std::string_view input, std::string_view set, const PointSet& points,
                                     const PointSetStatistics& s, bool timing) {
  std::string row = fmt::format("{},{},{},{},{},{},{},{},{},{},{},{}", csv_quoted(input), set, points.dimension,
                                s.nearest.points, format_real(s.nearest.min), format_real(s.nearest.q01),
                                format_real(s.nearest.median), format_real(s.nearest.mean),
                                format_real(s.nearest.median_scaled), timing ? fmt::format("{:.6f}", s.seconds) : std::string(),
                                to_string(points.domain.kind), format_real(points.domain.side));
  for (const auto& value : s.discrepancies) {
    row += ',';
    if (value) row += format_real(*value);  // statistics to 9 significant digits, as every other
  }
  return row + "\n";
}

}  // namespace dfvn
