#include "dfvn/stats/radial_distribution.hpp"

#include <atomic>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include <fmt/format.h>

#include "dfvn/core/dimension.hpp"
#include "dfvn/core/hash.hpp"
#include "dfvn/core/parallel.hpp"
#include "dfvn/stats/distance_scale.hpp"
#include "dfvn/stats/kd_tree.hpp"
#include "dfvn/stats/periodic_images.hpp"
#include "dfvn/stats/periodic_neighbours.hpp"

namespace dfvn {

void RdfOptions::validate() const {
  if (!std::isfinite(r_max) || r_max < 0.0) throw std::invalid_argument("RDF r_max must be a finite number >= 0");
  if (bins < 1 || bins > 100000) throw std::invalid_argument("RDF bins must be in 1..100000");
}

double unit_ball_volume(int dimension) {
  return std::pow(std::numbers::pi, 0.5 * dimension) / std::tgamma(0.5 * dimension + 1.0);
}

void check_rdf_resolution(int dimension, double side, double r_max, int bins) {
  // Each pair weight is at most 1 / (L - r_max)^N, since the overlap of the cube with its translate
  // by d is prod_a (L - |d_a|) and |d_a| <= r_max; with at most q (n - 1) pairs, which the
  // normalisation V^2 / (q (n - 1)) divides out, g_k <= V^2 / ((L - r_max)^N shell_k). The first
  // shell, ball * width^N, is the narrowest. In base-2 logarithms, so the check cannot overflow.
  const double width = r_max / bins;
  const double log2_bound = 2.0 * dimension * std::log2(side) - dimension * std::log2(side - r_max) -
                            std::log2(unit_ball_volume(dimension)) - dimension * std::log2(width);
  // 2^1000 leaves room below DBL_MAX (about 2^1024) for the sums; the shell must not be subnormal.
  const double shell = unit_ball_volume(dimension) * std::pow(width, dimension);
  if (!(width > 0.0) || !(log2_bound < 1000.0) || !(shell >= std::numeric_limits<double>::min()))
    throw std::invalid_argument(fmt::format(
        "RDF r_max {:g} with {} bins gives bins {:.3g} wide, too narrow for a finite g(r) in {}D (the shell volumes "
        "underflow); raise r_max or use fewer bins",
        r_max, bins, width, dimension));
}

namespace {

template <int N>
RdfCurve radial_distribution_impl(const PointSet& points, const RdfOptions& options, std::uint64_t seed, int threads,
                                  const FractionProgress& progress) {
  const std::size_t n = points.size();
  if (n < 2) throw std::invalid_argument("the RDF needs at least 2 points");
  const double side = points.domain.side;
  const double volume = points.domain.volume(N);
  RdfCurve curve;
  curve.r_max = options.r_max > 0.0 ? options.r_max : 2.5 * std::pow(volume / static_cast<double>(n), 1.0 / N);
  if (options.periodic) {
    // Below half the side, a pair has one minimum image within r_max: no pair is counted twice.
    if (options.r_max >= 0.5 * side)
      throw std::invalid_argument(fmt::format("a periodic RDF needs r_max below half the side ({:g}), got {:g}", 0.5 * side,
                                              options.r_max));
    if (curve.r_max >= 0.5 * side) curve.r_max = 0.499 * side;
    check_in_periodic_box(points);
  }
  if (curve.r_max >= side) curve.r_max = 0.999 * side;  // the edge correction needs |d_a| < L
  check_rdf_resolution(N, side, curve.r_max, options.bins);

  std::vector<std::uint32_t> queries;
  if (options.max_queries == 0 || n <= options.max_queries) {
    queries.resize(n);
    for (std::size_t i = 0; i < n; ++i) queries[i] = static_cast<std::uint32_t>(i);
  } else {
    const double keep = static_cast<double>(options.max_queries) / static_cast<double>(n);
    for (std::size_t i = 0; i < n; ++i)
      if (random_unit(seed, Stream::rdf_queries, i) < keep) queries.push_back(static_cast<std::uint32_t>(i));
  }
  curve.queries = queries.size();

  const PointSetAdaptor<N> adaptor{points};
  const KdTree<N> tree(N, adaptor, kd_tree_params());  // built by its constructor

  const int bins = options.bins;
  const double bin_width = curve.r_max / bins;
  constexpr std::int64_t kBlock = 64;
  const auto q = static_cast<std::int64_t>(queries.size());
  const std::int64_t blocks = (q + kBlock - 1) / kBlock;
  std::vector<double> histograms(static_cast<std::size_t>(blocks * bins), 0.0);
  std::atomic<std::int64_t> blocks_done{0};
#pragma omp parallel for schedule(dynamic, 1) num_threads(resolve_threads(threads))
  for (std::int64_t b = 0; b < blocks; ++b) {
    if (progress) {  // only the first thread reports
      const std::int64_t done = blocks_done.fetch_add(1, std::memory_order_relaxed);
      if (omp_get_thread_num() == 0) progress(static_cast<double>(done) / static_cast<double>(blocks));
    }
    double* histogram = histograms.data() + b * bins;
    std::vector<std::pair<std::uint32_t, double>> matches;
    for (std::int64_t k = b * kBlock; k < std::min(q, (b + 1) * kBlock); ++k) {
      const std::uint32_t i = queries[static_cast<std::size_t>(k)];
      const double* x = points.point(i);
      // The pairs within r_max of x (or, on the torus, of one of its images): each pair once.
      const auto count_pairs = [&](const double* position, bool image) {
        matches.clear();
        tree.radiusSearch(position, curve.r_max * curve.r_max, matches, nanoflann::SearchParams(32, 0.0f, false));
        for (const auto& [j, dist2] : matches) {
          if (j == i && !image) continue;
          const double r = std::sqrt(dist2);
          const auto bin = static_cast<int>(r / bin_width);
          if (bin >= bins) continue;
          double overlap = 1.0;  // |W intersect (W + d)| for the cube of side L; the torus has no edge
          const double* y = points.point(j);
          if (!options.periodic)
            for (int a = 0; a < N; ++a) overlap *= side - std::abs(x[a] - y[a]);
          histogram[bin] += 1.0 / overlap;
        }
      };
      count_pairs(x, false);
      if (options.periodic)
        for_each_periodic_image<N>(x, points.domain.lo, side, [&] { return curve.r_max; },
                                   [&](const double* image) { count_pairs(image, true); });
    }
  }
  curve.r.resize(bins);
  curve.g.assign(bins, 0.0);
  for (std::int64_t b = 0; b < blocks; ++b)
    for (int k = 0; k < bins; ++k) curve.g[k] += histograms[static_cast<std::size_t>(b * bins + k)];
  const double ball = unit_ball_volume(N);
  const double normalisation = volume * volume / (static_cast<double>(q) * static_cast<double>(n - 1));
  for (int k = 0; k < bins; ++k) {
    const double lo = k * bin_width, hi = (k + 1) * bin_width;
    curve.r[k] = 0.5 * (lo + hi);
    const double shell = ball * (std::pow(hi, N) - std::pow(lo, N));
    curve.g[k] *= normalisation / shell;
  }
  return curve;
}

}  // namespace

RdfCurve radial_distribution(const PointSet& points, const RdfOptions& options, std::uint64_t seed, int threads,
                             const FractionProgress& progress) {
  options.validate();
  // Volumes and squared distances of extreme domains overflow: compute at unit scale, where g is the
  // same (it has no unit), and scale r back (stats/distance_scale.hpp).
  double scale = domain_scale(points.domain.side);
  if (scale == 1.0) scale = coordinate_scale(points);
  if (scale != 1.0) {
    RdfOptions scaled = options;
    scaled.r_max /= scale;
    RdfCurve curve = radial_distribution(scaled_point_set(points, scale), scaled, seed, threads, progress);
    for (double& r : curve.r) r *= scale;
    curve.r_max *= scale;
    return curve;
  }
  RdfCurve curve = dispatch_dimension(
      points.dimension, [&]<int N>() { return radial_distribution_impl<N>(points, options, seed, threads, progress); });
  if (progress) progress(1.0);
  return curve;
}

}  // namespace dfvn
