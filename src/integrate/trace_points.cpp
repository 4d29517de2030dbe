#include "dfvn/integrate/trace_points.hpp"

#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "dfvn/core/parallel.hpp"
#include "dfvn/core/torus.hpp"
#include "dfvn/integrate/trace_table.hpp"

namespace dfvn {

TraceStats trace_points(const TracePointsQuery& query, const double* points, std::size_t rows, double* out) {
  check_thread_count(query.threads);
  query.trace.validate();
  if (!std::isfinite(query.time)) throw std::invalid_argument(fmt::format("trace time must be finite, got {}", query.time));
  return dispatch_dimension(query.dimension, [&]<int N>() {
    const DfvnField<N> field(query.seed, query.field);
    // Checked before the parallel loop: an exception must not escape an OpenMP region.
    for (std::size_t i = 0; i < rows; ++i) {
      const Vec<N> x = Eigen::Map<const Vec<N>>(points + i * N);
      if (!field.in_domain(x)) field.check_in_domain(x, fmt::format("point {}", i + 1));
    }
    // In a bounded domain an end that a long step carried out is traced again with more steps, as CNJ does;
    // otherwise every end is accepted. On the torus the ends are wrapped into [0,1)^N.
    const FieldConstraint constraint = query.field.constraint;
    const bool bounded = constraint == FieldConstraint::inside_cube || constraint == FieldConstraint::inside_ball;
    const TraceStats stats =
        trace_table<N>(field, query.trace, points, rows, out, query.time,
                       [&](const Vec<N>& x) { return !bounded || field.contains(x); },
                       bounded ? OnReject::retrace : OnReject::drop, query.threads, {})
            .stats;
    if (query.field.periodic) wrap_to_unit_torus(out, rows * N);
    return stats;
  });
}

}  // namespace dfvn
