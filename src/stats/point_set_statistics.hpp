// Every statistic of one point set that came from anywhere (a file, another program): nearest-
// neighbour summary in 1D-8D and, when asked, the four L2 discrepancies. Used by `dfvn-sample stats`.
#pragma once

#include <array>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "dfvn/core/progress.hpp"
#include "dfvn/core/point_set.hpp"
#include "dfvn/stats/discrepancy.hpp"
#include "dfvn/stats/nearest_neighbour.hpp"

namespace dfvn {

// The set's domain (PointSet::domain) decides the metric: minimum-image distances on the torus
// (stats/periodic_neighbours.hpp), great-circle angles on the sphere (stats/geodesic.hpp), Euclidean
// distances in the cube and the ball.
struct PointSetStatisticsOptions {
  bool discrepancy = false;  // O(n^2): only when asked
  KnnBackend knn = KnnBackend::nanoflann;
  int threads = 0;
};

struct PointSetStatistics {
  NearestNeighbourSummary nearest;
  std::array<std::optional<double>, 4> discrepancies;  // indexed like kAllDiscrepancies
  double seconds = 0.0;
};

// Nearest-neighbour distances in any dimension >= 1: 1D by sorting (the KD-trees start at 2D),
// otherwise nearest_neighbour_distances(). Needs at least 2 points.
std::vector<double> nearest_neighbour_distances_any_dimension(const PointSet& points, KnnBackend backend, int threads,
                                                              const FractionProgress& progress = {});

// Every point's distance to its nearest other point in the metric of points.domain (above). Needs at
// least 2 points; independent of thread count.
std::vector<double> nearest_neighbour_distances_in_domain(const PointSet& points, KnnBackend backend, int threads,
                                                          const FractionProgress& progress = {});

// Throws std::invalid_argument if a point lies outside points.domain (naming the point and axis) or
// there are fewer than 2 points.
void check_point_set(const PointSet& points);

// Stages reported: "statistics" (queries done), then each discrepancy when asked.
using StatisticsProgress = StageProgress;
PointSetStatistics measure_point_set(const PointSet& points, const PointSetStatisticsOptions& options,
                                     const StatisticsProgress& progress = {});

// Stages one measure_point_set call reports.
int point_statistics_stage_count(const PointSetStatisticsOptions& options);
// The radial distribution function's cost against the nearest-neighbour statistics of the same set
// (measured alike); the main job and `stats --rdf` weigh their RDF stages with it.
inline constexpr double kRdfCostOverStatistics = 4.0;
// The expected cost of each of those stages for a set of `points` points in `dimension` dimensions,
// in their order (a model of the operations, calibrated by timing; for the progress line's ETA).
std::vector<double> point_statistics_stage_weights(const PointSetStatisticsOptions& options, std::size_t points,
                                                   int dimension);

// CSV of `dfvn-sample stats`: input,set,dim,points, the nearest-neighbour columns of the sampling stats
// (nn_min,nn_q01,nn_median,nn_mean,nn_median_scaled), seconds_stats,domain,domain_side,cd,wd,md,l2_star:
// one row per set, data rows only (experiment/realizations.hpp's realization_summary_csv summarises the
// sets of a file for --summary). The discrepancy columns are empty unless computed, seconds_stats with
// `timing` off. Reals as io/csv.hpp's format_real writes them (9 significant digits), times to 6 decimals.
std::string point_statistics_csv_header();
std::string point_statistics_csv_row(std::string_view input, std::string_view set, const PointSet& points,
                                     const PointSetStatistics& statistics, bool timing = true);

}  // namespace dfvn
