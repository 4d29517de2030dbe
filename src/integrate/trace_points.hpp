// Tracing a table of points along one DFVN field: Algorithm 1 for every point, in parallel.
#pragma once

#include <cstddef>
#include <cstdint>

#include "dfvn/field/dfvn_field.hpp"
#include "dfvn/integrate/trace.hpp"

namespace dfvn {

struct TracePointsQuery {
  int dimension = 3;
  std::uint64_t seed = 1;
  FieldOptions field;   // the field traced along: basis, frequency, domain (constraint, bound, periodic)
  TraceOptions trace;   // integrator, reprojection, steps
  double time = 0.0;    // t of Algorithm 1; negative traces backwards
  int threads = 0;      // 0: all cores
};

// Traces each of `rows` points (points: rows x N, row-major) for query.time and writes where it ends
// to out (rows x N, row-major; out may equal points). In a bounded field (query.field.constraint) a trace
// that ends outside is traced again with 2, 4, ..., 64 times the steps, or stays at its start
// (integrate/trace_table.hpp); on the torus (query.field.periodic) the ends are wrapped into [0,1)^N. Returns the counters summed over all traces.
// The numbers do not depend on the thread count. Throws std::invalid_argument for bad options, a
// non-finite time, or a start point outside the noise domain (naming the point, 1-based), before
// anything is written.
TraceStats trace_points(const TracePointsQuery& query, const double* points, std::size_t rows, double* out);

}  // namespace dfvn
