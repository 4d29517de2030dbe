// Tracing a table of start points along a field, in parallel and independent of the thread count: the
// one loop behind trace_points (integrate/trace_points.hpp: the CLI's and Python's), curl noise
// jittering in a domain (sampling/curl_noise_jitter.cpp) and on the sphere (sampling/sphere_jitter.cpp).
// Private (not installed): it includes OpenMP.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <omp.h>
#include <vector>

#include "dfvn/core/parallel.hpp"
#include "dfvn/core/progress.hpp"
#include "dfvn/integrate/trace.hpp"

namespace dfvn {

// drop: a trace that ends outside the constraint is reported as not accepted.
// retrace: it is traced again with 2, 4, ..., 2^kMaxRefinements times the steps (an integration step
// that jumped across the boundary, where reprojection cannot help, is the only way out of a
// constrained field); if no refinement ends inside, the point stays at its start, which is inside.
enum class OnReject { drop, retrace };
inline constexpr int kMaxRefinements = 6;

struct TracedPoints {
  std::vector<unsigned char> accepted;   // per point: the end point satisfies the constraint
  TraceStats stats;                      // over every trace, refinements included
  std::uint64_t retraced = 0;            // points traced again with more steps
  std::uint64_t kept_at_start = 0;       // points no refinement brought to an accepted end
};

// starts and end: count x N, row-major; end may be starts (each row is read before it is written).
// accept(x) says whether an end point satisfies the constraint. A trace that stopped at the edge of the
// noise domain (TraceStats::stopped_at_edge: a step that would have left it, e.g. a field of speed 1e15)
// did not end where it was going, so it is never accepted either: retraced, then kept at its start and
// counted, or dropped. (It was taken as an end: CNJ reported every point moved while none had.)
template <int N, typename Accept>
TracedPoints trace_table(const DfvnField<N>& field, const TraceOptions& options, const double* starts,
                         std::size_t rows, double* end, double time, const Accept& accept, OnReject on_reject,
                         int threads, const FractionProgress& progress) {
  const auto count = static_cast<std::int64_t>(rows);
  std::vector<Tracer<N>> tracers;  // [0]: the configured steps; [k]: 2^k times as many
  for (int k = 0; k <= (on_reject == OnReject::retrace ? kMaxRefinements : 0); ++k) {
    TraceOptions refined = options;
    refined.steps = options.steps << k;
    tracers.emplace_back(field, refined);
  }
  TracedPoints out;
  out.accepted.resize(static_cast<std::size_t>(count));
  std::atomic<std::int64_t> done{0};
  std::int64_t retraced = 0, kept = 0;
  const std::int64_t report_every = std::max<std::int64_t>(count / 100, 1024);
  // Chunks of up to 1024 points, smaller for small tables (a few hundred points traced with many steps
  // still use every thread). Which thread traces a point never changes its result.
  const auto chunk = static_cast<int>(std::clamp<std::int64_t>(count / 64, 1, 1024));
#pragma omp parallel num_threads(resolve_threads(threads)) reduction(+ : retraced, kept)
  {
    TraceStats local;
#pragma omp for schedule(dynamic, chunk)
    for (std::int64_t i = 0; i < count; ++i) {
      const Vec<N> x0 = Eigen::Map<const Vec<N>>(starts + i * N);
      Vec<N> x;
      const auto ends_accepted = [&](const Tracer<N>& tracer) {
        const std::int64_t stops = local.stopped_at_edge;
        x = tracer.trace(x0, time, &local);
        return local.stopped_at_edge == stops && accept(x);
      };
      bool ok = ends_accepted(tracers[0]);
      if (!ok && on_reject == OnReject::retrace) {
        ++retraced;
        for (std::size_t k = 1; k < tracers.size() && !ok; ++k) ok = ends_accepted(tracers[k]);
        if (!ok) {
          x = x0;
          ok = true;
          ++kept;
        }
      }
      Eigen::Map<Vec<N>>(end + i * N) = x;
      out.accepted[static_cast<std::size_t>(i)] = ok;
      if (progress && (i + 1) % report_every == 0) {
        const std::int64_t d = done.fetch_add(report_every) + report_every;
        if (omp_get_thread_num() == 0) progress(static_cast<double>(d) / static_cast<double>(count));
      }
    }
#pragma omp critical
    out.stats += local;
  }
  out.retraced = static_cast<std::uint64_t>(retraced);
  out.kept_at_start = static_cast<std::uint64_t>(kept);
  return out;
}

}  // namespace dfvn
