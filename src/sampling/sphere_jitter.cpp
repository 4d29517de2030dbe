#include "dfvn/sampling/sphere_jitter.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include <fmt/format.h>

#include "dfvn/core/hash.hpp"
#include "dfvn/core/message_text.hpp"
#include "dfvn/core/parallel.hpp"
#include "dfvn/integrate/trace_table.hpp"

namespace dfvn {

double sphere_start_spacing(int grid) { return 2.0 / grid; }

PointSet sphere_start_set(int dimension, int grid) {
  if (dimension < 3) throw std::invalid_argument(fmt::format("points on the sphere need N >= 3, got {}", dimension));
  const LatticeSpec lattice{dimension, grid, Protocol::fair};  // (i + 1/2) / K in [0, 1]
  const double h = sphere_start_spacing(grid);
  const std::uint64_t count = lattice.point_count();
  PointSet out{dimension, {}, Domain::unit(DomainKind::sphere)};
  std::vector<double> x(static_cast<std::size_t>(dimension));
  for (std::uint64_t i = 0; i < count; ++i) {
    lattice.point(i, x.data());
    double r2 = 0.0;
    for (double& v : x) {
      v = 2.0 * v - 1.0;
      r2 += v * v;
    }
    const double r = std::sqrt(r2);
    if (!(r >= 1.0 - 0.5 * h && r < 1.0 + 0.5 * h)) continue;
    for (double v : x) out.coordinates.push_back(v / r);
  }
  return out;
}

template <int N>
static SphereCnjResult sphere_curl_noise_jitter(int grid, const CnjOptions& requested, std::uint64_t seed,
                                                int threads, const FractionProgress& progress) {
  const CnjOptions options = sphere_cnj_options(requested);
  options.validate();
  const double h = sphere_start_spacing(grid);
  SphereCnjResult result;
  result.trace_time = options.step_scale * average_neighbour_distance(N - 1) * h;
  result.field_frequency = options.frequency / h;
  FieldOptions field_options{options.noise, result.field_frequency, FieldConstraint::on_sphere};
  field_options.phase = options.phase;
  field_options.transform = options.transform;
  const DfvnField<N> field(seed, field_options);
  const PointSet starts = sphere_start_set(N, grid);
  Coordinates ends(starts.coordinates.size());  // trace_table writes every row
  const TracedPoints traced = trace_table<N>(
      field, cnj_trace_options(options), starts.coordinates.data(), starts.size(), ends.data(), result.trace_time,
      [](const Vec<N>& x) { return satisfies_constraint<N>(FieldConstraint::on_sphere, x); }, OnReject::retrace,
      threads, progress);
  double total_squared_displacement = 0.0;  // in index order
  for (std::size_t i = 0; i < ends.size(); ++i) {
    const double u = ends[i] - starts.coordinates[i];
    total_squared_displacement += u * u;
  }
  result.points = PointSet{N, std::move(ends), starts.domain};
  result.rms_displacement =
      starts.size() ? std::sqrt(total_squared_displacement / static_cast<double>(starts.size())) : 0.0;
  result.retraced = traced.retraced;
  result.kept_at_site = traced.kept_at_start;
  result.trace_stats = traced.stats;
  if (progress) progress(1.0);
  return result;
}

CnjOptions sphere_cnj_options(const CnjOptions& options) {
  CnjOptions bound = options;
  bound.domain_mode = DomainMode::conformant;
  bound.domain = DomainKind::sphere;
  return bound;
}

SphereCnjResult sphere_curl_noise_jitter(int dimension, int grid, const CnjOptions& options, std::uint64_t seed,
                                         int threads, const FractionProgress& progress) {
  if (dimension < 3) throw std::invalid_argument(fmt::format("points on the sphere need N >= 3, got {}", dimension));
  return dispatch_dimension(dimension, [&]<int N>() {
    return sphere_curl_noise_jitter<N>(grid, options, seed, threads, progress);
  });
}

PointSet uniform_points_on_sphere(int dimension, std::uint64_t count, std::uint64_t seed, int threads) {
  PointSet out{dimension, Coordinates(count * static_cast<std::uint64_t>(dimension)), Domain::unit(DomainKind::sphere)};
#pragma omp parallel for schedule(static) num_threads(resolve_threads(threads))
  for (std::int64_t i = 0; i < static_cast<std::int64_t>(count); ++i) {
    double* x = out.coordinates.data() + static_cast<std::size_t>(i) * dimension;
    for (std::uint64_t lane = 0;; lane += static_cast<std::uint64_t>(dimension)) {
      double r2 = 0.0;
      for (int j = 0; j < dimension; ++j) {  // Box-Muller: 1 - u in (0, 1], so the log is finite
        const double u = 1.0 - random_unit(seed, Stream::sphere_points, static_cast<std::uint64_t>(i), 2 * (lane + j));
        const double v = random_unit(seed, Stream::sphere_points, static_cast<std::uint64_t>(i), 2 * (lane + j) + 1);
        x[j] = std::sqrt(-2.0 * std::log(u)) * std::cos(2.0 * std::numbers::pi * v);
        r2 += x[j] * x[j];
      }
      if (r2 > 1e-200) {  // a zero vector has no direction: draw again (probability ~ 0)
        const double r = std::sqrt(r2);
        for (int j = 0; j < dimension; ++j) x[j] /= r;
        break;
      }
    }
  }
  return out;
}

}  // namespace dfvn
