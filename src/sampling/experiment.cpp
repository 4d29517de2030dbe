#include "sampling/experiment.hpp"

#include <algorithm>
#include <cmath>
#include <new>
#include <stdexcept>
#include <string>
#include <unistd.h>

#include <fmt/format.h>

#include "core/dimension.hpp"
#include "core/message_text.hpp"
#include "core/parallel.hpp"
#include "core/stopwatch.hpp"
#include "noise/noise_domain.hpp"
#include "sampling/halton.hpp"
#include "sampling/jitter.hpp"
#include "sampling/latin_hypercube.hpp"
#include "sampling/poisson_disk.hpp"

namespace dfvn {

namespace {

double physical_memory_bytes() {
  const long pages = ::sysconf(_SC_PHYS_PAGES);
  const long page_size = ::sysconf(_SC_PAGE_SIZE);
  return (pages > 0 && page_size > 0) ? static_cast<double>(pages) * static_cast<double>(page_size) : 8.0 * (1ULL << 30);
}

}  // namespace

MethodPlan plan_method(const SampleConfig& config, Method method) {
  const LatticeSpec lattice = config.lattice();
  const std::uint64_t lattice_points = lattice.point_count();
  MethodPlan plan{method, lattice_points, Box{0.0, 1.0}, 0.0};
  const bool paper = config.protocol == Protocol::paper;
  // paper: PDS and Sobol live on [0, delta K]^N, the box a 0.1-spaced K^N lattice would fill
  // (data/PROTOCOL.md): the unit cube for K = 10, [0, 0.7]^6 and [0, 0.6]^7 in Table 1.
  const Box paper_box{0.0, kPaperDelta * config.grid};
  switch (method) {
    case Method::cnj:
    case Method::jitter:
    case Method::random:
      break;
    case Method::pds:
      plan.domain = paper ? paper_box : Box{0.0, 1.0};
      plan.pds_radius = config.pds_radius > 0.0 ? config.pds_radius : (paper ? kPaperDelta : 1.0 / config.grid);
      break;
    case Method::sobol:
      plan.domain = paper ? paper_box : Box{0.0, 1.0};
      if (paper) {  // SciPy's count: 2^round(log2(K^N))
        const int exponent = static_cast<int>(std::lround(std::log2(static_cast<double>(lattice_points))));
        plan.requested = std::uint64_t{1} << std::min(exponent, 32);
      }
      break;
    case Method::halton:
    case Method::lhs:  // the alternatives to Sobol a user would pick: Sobol's domain, the lattice's count
      plan.domain = paper ? paper_box : Box{0.0, 1.0};
      break;
  }
  return plan;
}

namespace {

// Per point: its coordinates, the moved copy or KD-tree index and bookkeeping (CNJ keeps a moved
// copy, a flag and a displacement; the KD-tree a 4-byte index; the statistics an 8-byte distance).
double estimated_bytes(const MethodPlan& plan, int dimension) {
  return static_cast<double>(plan.requested) * (16.0 * dimension + 48.0);
}

}  // namespace

double estimated_peak_bytes(const SampleConfig& config) {
  double peak = 0.0;
  for (Method m : config.methods) peak = std::max(peak, estimated_bytes(plan_method(config, m), config.dimension));
  return peak;
}

void SampleConfig::validate() const {
  if (dimension < kMinDimension || dimension > kMaxDimension)
    throw std::invalid_argument(fmt::format("--dim must be in {}..{}, got {}", kMinDimension, kMaxDimension, dimension));
  if (grid < 2) throw std::invalid_argument(fmt::format("--grid must be at least 2, got {}", grid));
  if (methods.empty()) throw std::invalid_argument("--methods must name at least one method");
  check_thread_count(threads);
  if (protocol == Protocol::paper && grid * kPaperDelta > 1e6) throw std::invalid_argument("--grid is too large");
  cnj.validate();
  if (std::find(methods.begin(), methods.end(), Method::cnj) != methods.end()) {
    const double field_frequency = cnj.frequency / lattice().spacing();
    if (!(field_frequency >= kMinNoiseFrequency && field_frequency <= kMaxNoiseFrequency))
      throw std::invalid_argument(fmt::format(
          "--frequency {:g} cycles per lattice spacing with --grid {} is a field frequency of {:g}, outside the "
          "noise's [2^-50, 2^50]",
          cnj.frequency, grid, field_frequency));
  }
  if (!std::isfinite(pds_radius) || pds_radius < 0.0) throw std::invalid_argument("--pds-radius must be a finite number > 0");
  if (pds_candidates < 1) throw std::invalid_argument("--pds-candidates must be at least 1");
  if (!std::isfinite(max_memory_gib) || max_memory_gib < 0.0) throw std::invalid_argument("--max-memory must be >= 0");
  rdf.validate();
  const LatticeSpec l = lattice();
  std::uint64_t count = 0;
  try {
    count = l.point_count();
  } catch (const std::invalid_argument&) {
    throw std::invalid_argument(fmt::format("--grid {} in {}D gives {}^{} = {:.3g} points, far more than any memory holds",
                                            grid, dimension, grid, dimension, std::pow(double(grid), dimension)));
  }
  for (Method m : methods) {
    const MethodPlan plan = plan_method(*this, m);
    if (m == Method::sobol && plan.requested > (std::uint64_t{1} << 32))
      throw std::invalid_argument("Sobol supports at most 2^32 points");
    if (compute_rdf && rdf.r_max > 0.0) {
      try {
        check_rdf_resolution(dimension, plan.domain.side, std::min(rdf.r_max, 0.999 * plan.domain.side), rdf.bins);
      } catch (const std::invalid_argument&) {
        throw std::invalid_argument(fmt::format(
            "--rdf-max {:g} with --rdf-bins {} gives bins {:.3g} wide, too narrow for a finite g(r) in {}D; raise "
            "--rdf-max or lower --rdf-bins",
            rdf.r_max, rdf.bins, rdf.r_max / rdf.bins, dimension));
      }
    }
    if (m == Method::pds) {
      PoissonDiskOptions o;
      o.radius = plan.pds_radius;
      o.domain = plan.domain;
      o.validate(dimension);
    }
  }
  // An absurd --max-memory makes the limit Inf: then nothing is refused here, and an allocation that
  // fails is reported by run_sampling.
  const double limit = max_memory_gib > 0.0 ? max_memory_gib * double(1ULL << 30) : 0.8 * physical_memory_bytes();
  const double need = estimated_peak_bytes(*this);
  if (need > limit)
    throw std::invalid_argument(fmt::format(
        "--grid {} in {}D gives {} points, which need about {} of memory (limit {}); "
        "lower --grid or raise the limit with --max-memory GIB",
        grid, dimension, count, byte_size(need), byte_size(limit)));
}

static PointSet generate_points(const SampleConfig& config, const MethodPlan& plan, std::string& notes,
                         std::optional<LatticeDisplacementSummary>& displacement, const StageProgress& progress) {
  const LatticeSpec lattice = config.lattice();
  switch (plan.method) {
    case Method::cnj: {
      CnjResult r = curl_noise_jitter(lattice, config.cnj, config.seed, config.threads, [&](double f) {
        if (progress) progress("cnj", f);
      });
      notes = fmt::format("noise={} t={:.4g} F={:.4g} rms_move={:.4g} dropped={} skipped_updates={}",
                          to_string(config.cnj.noise), r.trace_time, r.field_frequency, r.rms_displacement, r.dropped,
                          r.trace_stats.skipped_updates);
      displacement = summarize_lattice_displacements(config.dimension, config.grid, lattice.spacing(), r.displacements);
      return std::move(r.points);
    }
    case Method::jitter: {
      notes = fmt::format("half_width={:.4g}", jitter_half_width(lattice));
      PointSet points = jittered_lattice(lattice, config.seed, config.threads);
      displacement = summarize_lattice_displacements(config.dimension, config.grid, lattice.spacing(),
                                                     lattice_displacements(lattice, points));
      return points;
    }
    case Method::random:
      return uniform_random_points(config.dimension, plan.requested, plan.domain, config.seed, config.threads);
    case Method::pds: {
      PoissonDiskOptions o;
      o.radius = plan.pds_radius;
      o.candidates = config.pds_candidates;
      o.max_points = plan.requested;
      o.domain = plan.domain;
      PoissonDiskResult r = poisson_disk(config.dimension, o, config.seed);
      notes = fmt::format("radius={:.4g} placed={} {}", plan.pds_radius, r.points.size(),
                          r.reached_max_points ? "stopped at requested count" : "saturated (active list empty)");
      return std::move(r.points);
    }
    case Method::sobol:
      notes = fmt::format("scramble={}", to_string(config.scramble));
      return sobol_points(config.dimension, plan.requested, plan.domain, config.scramble, config.seed, config.threads);
    case Method::halton:
      notes = fmt::format("scramble={}", config.scramble == Scramble::owen ? "digit-permutation" : "none");
      return halton_points(config.dimension, plan.requested, plan.domain, config.scramble == Scramble::owen, config.seed,
                           config.threads);
    case Method::lhs:
      return latin_hypercube_points(config.dimension, plan.requested, plan.domain, config.seed, config.threads);
  }
  throw std::logic_error("unknown method");
}

void generate_points(const SampleConfig& config, MethodResult& result, const StageProgress& progress) {
  result.points = generate_points(config, result.plan, result.notes, result.displacement, progress);
}

namespace {

std::string out_of_memory_message(const SampleConfig& config, const MethodPlan& plan) {
  return fmt::format("out of memory for the {} point set: {} points in {}D need about {}; lower --grid{}",
                     to_string(plan.method), plan.requested, config.dimension,
                     byte_size(estimated_bytes(plan, config.dimension)),
                     config.max_memory_gib > 0.0 ? " or --max-memory" : "");
}

// Generate one point set, then its statistics.
MethodResult run_method(const SampleConfig& config, const MethodPlan& plan, bool keep_points,
                        const StageProgress& progress, const std::function<void(const MethodResult&)>& on_result) {
  const Method method = plan.method;
  MethodResult result;
  result.plan = plan;
  if (progress) progress(to_string(method), 0.0);
  Stopwatch stopwatch;
  generate_points(config, result, progress);
  result.seconds_generate = stopwatch.seconds();
  if (result.points.size() < 2)  // CNJ drops the points that leave the unit cube
    throw std::invalid_argument(fmt::format("the {} point set has {} point(s) ({}); the statistics need at least 2",
                                            to_string(method), result.points.size(), result.notes));
  if (progress) progress("statistics", 0.0);
  stopwatch.restart();
  result.nearest = summarize_nearest_neighbours(nearest_neighbour_distances(result.points, config.knn, config.threads),
                                                result.points);
  result.seconds_stats = stopwatch.seconds();
  if (config.compute_rdf) {
    if (progress) progress("rdf", 0.0);
    result.rdf = radial_distribution(result.points, config.rdf, config.seed, config.threads);
  }
  if (on_result) on_result(result);
  if (!keep_points) result.points = PointSet{result.points.dimension, {}, result.points.domain};
  return result;
}

}  // namespace

std::vector<MethodResult> run_sampling(const SampleConfig& config, bool keep_points, const StageProgress& progress,
                                       const std::function<void(const MethodResult&)>& on_result) {
  config.validate();
  std::vector<MethodResult> results;
  for (Method method : config.methods) {
    const MethodPlan plan = plan_method(config, method);
    try {
      results.push_back(run_method(config, plan, keep_points, progress, on_result));
    } catch (const std::bad_alloc&) {
      throw std::runtime_error(out_of_memory_message(config, plan));
    } catch (const std::length_error&) {  // a std::vector longer than its max_size()
      throw std::runtime_error(out_of_memory_message(config, plan));
    }
  }
  return results;
}

std::string stats_csv_header() {
  return "dim,grid,method,points,nn_min,nn_q01,nn_median,nn_mean,nn_median_scaled,rms_displacement,"
         "median_displacement,frac_unmoved,neighbour_disorder,lattice_order,seconds_generate,seconds_stats,seed,"
         "protocol,domain_side,requested,notes\n";
}

std::string stats_csv_row(const SampleConfig& config, const MethodResult& r) {
  std::string displacement = ",,,,";  // no lattice: the columns stay empty
  if (r.displacement)
    displacement = fmt::format("{:.9g},{:.9g},{:.9g},{:.9g},{:.9g}", r.displacement->rms, r.displacement->median,
                               r.displacement->fraction_unmoved, r.displacement->neighbour_disorder,
                               r.displacement->lattice_order);
  return fmt::format("{},{},{},{},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{},{:.6f},{:.6f},{},{},{:.9g},{},\"{}\"\n",
                     config.dimension, config.grid, to_string(r.plan.method), r.nearest.points, r.nearest.min,
                     r.nearest.q01, r.nearest.median, r.nearest.mean, r.nearest.median_scaled, displacement,
                     r.seconds_generate, r.seconds_stats, config.seed, to_string(config.protocol), r.plan.domain.side,
                     r.plan.requested, r.notes);
}

std::string rdf_csv_header() { return "dim,method,r,g\n"; }

std::string rdf_csv_rows(const SampleConfig& config, const MethodResult& r) {
  std::string out;
  if (!r.rdf) return out;
  for (std::size_t k = 0; k < r.rdf->r.size(); ++k)
    fmt::format_to(std::back_inserter(out), "{},{},{:.9g},{:.9g}\n", config.dimension, to_string(r.plan.method),
                   r.rdf->r[k], r.rdf->g[k]);
  return out;
}

}  // namespace dfvn
