#include "sampling/curl_noise_jitter.hpp"

#include <atomic>
#include <cmath>
#include <omp.h>
#include <stdexcept>

#include <fmt/format.h>

#include "core/parallel.hpp"
#include "noise/noise_domain.hpp"

namespace dfvn {

void CnjOptions::validate() const {
  trace.validate();
  if (!(step_scale > 0.0 && step_scale <= kMaxStepScale))
    throw std::invalid_argument(fmt::format("step scale must be in (0, 2^20], got {:g}", step_scale));
  check_noise_frequency(frequency);
  parse_noise_basis(to_string(noise));  // an unknown enum value throws
}

template <int N>
CnjResult curl_noise_jitter(const LatticeSpec& lattice, const CnjOptions& options, std::uint64_t seed, int threads,
                            const ProgressCallback& progress) {
  options.validate();
  if (lattice.dimension != N) throw std::invalid_argument("lattice dimension does not match");
  const auto count = static_cast<std::int64_t>(lattice.point_count());
  CnjResult result;
  result.trace_time = options.step_scale * average_neighbour_distance(N) * lattice.spacing();
  result.field_frequency = options.frequency / lattice.spacing();
  const DfvnField<N> field(seed, FieldOptions{options.noise, result.field_frequency});
  const Tracer<N> tracer(field, options.trace);

  std::vector<double> moved(static_cast<std::size_t>(count) * N);
  std::vector<unsigned char> inside(static_cast<std::size_t>(count));
  result.displacements.resize(static_cast<std::size_t>(count) * N);
  TraceStats stats;
  std::atomic<std::int64_t> done{0};
  const std::int64_t report_every = std::max<std::int64_t>(count / 100, 1024);
#pragma omp parallel num_threads(resolve_threads(threads))
  {
    TraceStats local;
#pragma omp for schedule(dynamic, 1024)
    for (std::int64_t i = 0; i < count; ++i) {
      Vec<N> x0;
      lattice.point(static_cast<std::uint64_t>(i), x0.data());
      const Vec<N> x = tracer.trace(x0, result.trace_time, &local);
      Eigen::Map<Vec<N>>(moved.data() + i * N) = x;
      inside[static_cast<std::size_t>(i)] = Box{0.0, 1.0}.contains(x.data(), N);
      Eigen::Map<Vec<N>>(result.displacements.data() + i * N) = x - x0;
      if (progress && (i + 1) % report_every == 0) {
        const std::int64_t d = done.fetch_add(report_every) + report_every;
        if (omp_get_thread_num() == 0) progress(static_cast<double>(d) / static_cast<double>(count));
      }
    }
#pragma omp critical
    stats += local;
  }
  // Compact and sum in index order, so every output is the same for any thread count.
  result.points = PointSet{N, {}, Box{0.0, 1.0}};
  result.points.coordinates.reserve(moved.size());
  double total_squared_displacement = 0.0;
  for (std::int64_t i = 0; i < count; ++i) {
    total_squared_displacement += Eigen::Map<const Vec<N>>(result.displacements.data() + i * N).squaredNorm();
    if (inside[static_cast<std::size_t>(i)])
      result.points.coordinates.insert(result.points.coordinates.end(), moved.begin() + i * N, moved.begin() + (i + 1) * N);
    else
      ++result.dropped;
  }
  result.rms_displacement = std::sqrt(total_squared_displacement / static_cast<double>(count));
  result.trace_stats = stats;
  if (progress) progress(1.0);
  return result;
}

CnjResult curl_noise_jitter(const LatticeSpec& lattice, const CnjOptions& options, std::uint64_t seed, int threads,
                            const ProgressCallback& progress) {
  return dispatch_dimension(lattice.dimension, [&]<int N>() {
    return curl_noise_jitter<N>(lattice, options, seed, threads, progress);
  });
}

}  // namespace dfvn
