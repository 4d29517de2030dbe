#include "integrate/trace_points.hpp"

#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "core/parallel.hpp"

namespace dfvn {

TraceStats trace_points(const TracePointsQuery& query, const double* points, std::size_t rows, double* out) {
  check_thread_count(query.threads);
  query.trace.validate();
  if (!std::isfinite(query.time)) throw std::invalid_argument(fmt::format("trace time must be finite, got {}", query.time));
  return dispatch_dimension(query.dimension, [&]<int N>() {
    const DfvnField<N> field(query.seed, query.field);
    const Tracer<N> tracer(field, query.trace);
    // Checked before the parallel loop: an exception must not escape an OpenMP region.
    for (std::size_t i = 0; i < rows; ++i) {
      const Vec<N> x = Eigen::Map<const Vec<N>>(points + i * N);
      if (!field.in_domain(x)) field.check_in_domain(x, fmt::format("point {}", i + 1));
    }
    // Each point is traced alone and written to its own row; the integer counters add up the same
    // in any order.
    std::int64_t evaluations = 0, updates = 0, skipped = 0, outside = 0;
#pragma omp parallel for schedule(dynamic, 256) num_threads(resolve_threads(query.threads)) \
    reduction(+ : evaluations, updates, skipped, outside)
    for (std::int64_t i = 0; i < static_cast<std::int64_t>(rows); ++i) {
      const auto row = static_cast<std::size_t>(i);
      TraceStats stats;
      const Vec<N> end = tracer.trace(Eigen::Map<const Vec<N>>(points + row * N), query.time, &stats);
      Eigen::Map<Vec<N>>(out + row * N) = end;
      evaluations += stats.field_evaluations;
      updates += stats.reprojection_updates;
      skipped += stats.skipped_updates;
      outside += stats.outside_domain;
    }
    return TraceStats{evaluations, updates, skipped, outside};
  });
}

}  // namespace dfvn
