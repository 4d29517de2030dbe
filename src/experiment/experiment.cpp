#include "dfvn/experiment/experiment.hpp"

#include <algorithm>
#include <cmath>
#include <new>
#include <stdexcept>
#include <string>
#include <unistd.h>

#include <fmt/format.h>

#include "dfvn/core/dimension.hpp"
#include "dfvn/core/message_text.hpp"
#include "dfvn/core/parallel.hpp"
#include "dfvn/core/stopwatch.hpp"
#include "dfvn/experiment/streamed_sampling.hpp"
#include "dfvn/io/csv.hpp"
#include "dfvn/noise/noise_domain.hpp"
#include "dfvn/sampling/halton.hpp"
#include "dfvn/sampling/jitter.hpp"
#include "dfvn/sampling/latin_hypercube.hpp"
#include "dfvn/sampling/poisson_disk.hpp"
#include "dfvn/stats/geodesic.hpp"
#include "dfvn/stats/periodic_neighbours.hpp"
#include "dfvn/stats/point_set_statistics.hpp"

namespace dfvn {

namespace {

bool is_lattice_method(Method m) { return m == Method::cnj || m == Method::jitter || m == Method::jitter_matched; }

double physical_memory_bytes() {
  const long pages = ::sysconf(_SC_PHYS_PAGES);
  const long page_size = ::sysconf(_SC_PAGE_SIZE);
  return (pages > 0 && page_size > 0) ? static_cast<double>(pages) * static_cast<double>(page_size) : 8.0 * (1ULL << 30);
}

// Whether the inscribed ball holds a site of `lattice`: its site nearest the centre has every coordinate
// the one nearest 1/2, and is inside when its squared distance, summed as site_in_domain sums it, is
// below 1/4.
bool ball_holds_a_site(const LatticeSpec& lattice) {
  double nearest = 1.0;
  for (int i = 0; i < lattice.grid; ++i) nearest = std::min(nearest, std::abs(lattice.coordinate(i) - 0.5));
  double from_centre2 = 0.0;
  for (int j = 0; j < lattice.dimension; ++j) from_centre2 += nearest * nearest;
  return from_centre2 < 0.25;
}

// An empty ball is an error naming the smallest --grid whose lattice has a site (3 at most: an odd K has a
// site at the centre).
void check_ball_holds_a_site(const LatticeSpec& lattice) {
  if (ball_holds_a_site(lattice)) return;
  LatticeSpec larger = lattice;
  while (!ball_holds_a_site(larger)) ++larger.grid;
  throw std::invalid_argument(fmt::format("--domain ball: the ball inscribed in the cube holds no site of the {}^{} "
                                          "lattice of --grid {}; the smallest --grid with a site inside is {}",
                                          lattice.grid, lattice.dimension, lattice.grid, larger.grid));
}

}  // namespace

std::vector<std::string> sampling_warnings(const SampleConfig& config) {
  std::vector<std::string> warnings;
  const bool has = std::any_of(config.methods.begin(), config.methods.end(), is_lattice_method);
  if (config.count > 0 && has) {
    const std::uint64_t lattice_points = config.lattice().point_count();
    if (lattice_points != config.count)
      warnings.push_back(fmt::format("-n {}: the lattice methods use K = {}, {}^{} = {} points, the nearest K^N", config.count,
                                     config.grid, config.grid, config.dimension, lattice_points));
  }
  for (Method m : config.methods) {
    if (m != Method::sobol) continue;
    const std::uint64_t n = plan_method(config, m).requested;
    if (n > 0 && (n & (n - 1)) != 0) {
      const int below = static_cast<int>(std::floor(std::log2(static_cast<double>(n))));
      warnings.push_back(fmt::format("sobol: {} points is not a power of 2; Sobol points are balanced only at 2^m points "
                                     "(nearest: {} or {})",
                                     n, std::uint64_t{1} << below, std::uint64_t{1} << (below + 1)));
    }
  }
  return warnings;
}

int sampling_stage_count(const SampleConfig& config) {
  const int per_method = 1 + (config.compute_statistics ? 1 : 0) + (config.compute_statistics && config.compute_rdf ? 1 : 0);
  return per_method * static_cast<int>(config.methods.size());
}

double sampling_generation_cost(Method method) {
  switch (method) {
    case Method::cnj: return 3.0;
    case Method::pds: return 4.0;
    case Method::jitter:
    case Method::jitter_matched:
    case Method::halton: return 0.2;
    case Method::sobol:
    case Method::random:
    case Method::lhs: return 0.03;
  }
  return 1.0;
}

std::vector<double> sampling_stage_weights(const SampleConfig& config) {
  std::vector<double> weights;
  for (Method method : config.methods) {
    const double points = static_cast<double>(plan_method(config, method).requested);
    weights.push_back(points * sampling_generation_cost(method));
    if (config.compute_statistics) weights.push_back(points);
    if (config.compute_statistics && config.compute_rdf) weights.push_back(points * kRdfCostOverStatistics);
  }
  return weights;
}

MethodPlan plan_method(const SampleConfig& config, Method method) {
  const LatticeSpec lattice = config.lattice();
  const std::uint64_t lattice_points = lattice.point_count();
  const DomainKind kind = config.domain();
  MethodPlan plan{method, lattice_points, Domain::unit(kind), 0.0};
  // The ball's and the sphere's counts are counted site by site up to kExactCountLimit lattice points
  // (about a second); beyond, where the memory check refuses the run on any usual machine, they are
  // estimated from the volume fraction (ball) or area / h^(N-1) (sphere), so that validating a huge
  // --grid never loops over it.
  constexpr std::uint64_t kExactCountLimit = std::uint64_t{1} << 27;
  const bool exact = lattice_points <= kExactCountLimit;
  if (config.protocol == Protocol::paper) {
    // Section 5.1 (data/PROTOCOL.md), in the cube: the lattice methods on the paper's lattice, measured in
    // the box its cells fill; PDS and Sobol (and the other sequences, the alternatives a user would pick)
    // on [0, delta K]^N, the box a 0.1-spaced K^N lattice would fill: the unit cube for K = 10, [0, 0.7]^6
    // and [0, 0.6]^7 in Table 1, where the same count is (0.15 / 0.1)^6 = 11.4 and (0.18 / 0.1)^7 = 61
    // times denser than the lattice methods' (the paper's densities; table1.md names it).
    const Box paper_box{0.0, kPaperDelta * config.grid};
    plan.domain = is_lattice_method(method) ? Domain(lattice.cells()) : Domain(paper_box);
    if (method == Method::pds) plan.pds_radius = config.pds_radius > 0.0 ? config.pds_radius : kPaperDelta;
    if (method == Method::sobol && config.count == 0) {  // SciPy's count: 2^round(log2(K^N))
      const int exponent = static_cast<int>(std::lround(std::log2(static_cast<double>(lattice_points))));
      plan.requested = std::uint64_t{1} << std::min(exponent, 32);
    }
  } else {
    // Fair: every method in the run's unit domain at the count of the lattice's sites in it.
    if (kind == DomainKind::sphere) {
      plan.requested = exact ? sphere_start_set(config.dimension, config.grid).size()
                             : static_cast<std::uint64_t>(sphere_area(config.dimension) /
                                                          std::pow(sphere_start_spacing(config.grid), config.dimension - 1));
    } else if (kind == DomainKind::ball) {
      check_ball_holds_a_site(lattice);
      plan.requested = exact ? cnj_start_count(lattice, DomainKind::ball)
                             : static_cast<std::uint64_t>(static_cast<double>(lattice_points) *
                                                          plan.domain.measure(config.dimension));
    }
    if (method == Method::pds) plan.pds_radius = config.pds_radius;  // 0: the largest that reaches the count
  }
  // -n: every method that is not a lattice makes exactly the count asked for.
  if (config.count > 0 && !is_lattice_method(method)) plan.requested = config.count;
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

double memory_limit_bytes(const SampleConfig& config) {
  return config.max_memory_gib > 0.0 ? config.max_memory_gib * double(1ULL << 30) : 0.8 * physical_memory_bytes();
}

void SampleConfig::use_protocol(Protocol chosen) {
  protocol = chosen;
  if (chosen != Protocol::paper) return;
  cnj.domain = DomainKind::cube;
  cnj.domain_mode = DomainMode::drop;
  if (cnj.trace.steps == CnjOptions::kStepsByDomainMode) cnj.trace.steps = 1;
}

void SampleConfig::validate() const {
  if (dimension < kMinDimension || dimension > kMaxDimension)
    throw std::invalid_argument(fmt::format("--dim must be in {}..{}, got {}", kMinDimension, kMaxDimension, dimension));
  if (grid < 2) throw std::invalid_argument(fmt::format("--grid must be at least 2, got {}", grid));
  if (count > (std::uint64_t{1} << 40)) throw std::invalid_argument(fmt::format("-n {} is more points than any memory holds", count));
  if (methods.empty()) throw std::invalid_argument("--methods must name at least one method");
  check_thread_count(threads);
  if (protocol == Protocol::paper && grid * kPaperDelta > 1e6) throw std::invalid_argument("--grid is too large");
  // On the sphere CNJ validates as the sphere uses it (sphere_cnj_options: conformant along the sphere).
  (domain() == DomainKind::sphere ? sphere_cnj_options(cnj) : cnj).validate();
  const bool has_cnj = std::find(methods.begin(), methods.end(), Method::cnj) != methods.end();
  if (has_cnj) {
    const double field_frequency = cnj.frequency / lattice().spacing();
    if (!(field_frequency >= kMinNoiseFrequency && field_frequency <= kMaxNoiseFrequency))
      throw std::invalid_argument(fmt::format(
          "--cycles-per-spacing {:g} with --grid {} is a field frequency of {:g}, outside the "
          "noise's [2^-50, 2^50]",
          cnj.frequency, grid, field_frequency));
  }
  const DomainKind kind = domain();
  if (protocol == Protocol::paper) {
    if (kind != DomainKind::cube)
      throw std::invalid_argument(fmt::format("--protocol paper is Section 5.1, in the cube: --domain {} needs --protocol fair",
                                              to_string(kind)));
    if (has_cnj && cnj.domain_mode != DomainMode::drop)
      throw std::invalid_argument("--protocol paper drops the CNJ points that leave the cube (--domain-mode drop); "
                                  "conformant CNJ needs --protocol fair");
  }
  if (kind == DomainKind::sphere) {
    if (dimension < 3) throw std::invalid_argument(fmt::format("--domain sphere needs --dim 3..8, got {}", dimension));
    for (Method m : methods)
      if (m != Method::cnj && m != Method::random)
        throw std::invalid_argument(fmt::format("--domain sphere takes --methods cnj and random, not {}", to_string(m)));
    if (compute_rdf) throw std::invalid_argument("--rdf is for points in a torus, cube or ball, not --domain sphere");
  }
  if (kind == DomainKind::ball)
    for (Method m : methods)
      if (m == Method::jitter_matched || m == Method::lhs)
        throw std::invalid_argument(fmt::format(
            "{} in the ball: {} (--domain torus or cube)", to_string(m),
            m == Method::lhs ? "a Latin hypercube stratifies the cube's axes, which the ball cuts"
                             : "jitter-matched reflects at the cube's faces to match CNJ's displacement"));
  if (!std::isfinite(pds_radius) || pds_radius < 0.0) throw std::invalid_argument("--pds-radius must be a finite number > 0");
  if (pds_candidates < 1) throw std::invalid_argument("--pds-candidates must be at least 1");
  if (!std::isfinite(max_memory_gib) || max_memory_gib < 0.0) throw std::invalid_argument("--max-memory must be >= 0");
  rdf.validate();
  const LatticeSpec l = lattice();
  std::uint64_t lattice_points = 0;
  try {
    lattice_points = l.point_count();
  } catch (const std::invalid_argument&) {
    throw std::invalid_argument(fmt::format("--grid {} in {}D gives {}^{} = {:.3g} points, far more than any memory holds",
                                            grid, dimension, grid, dimension, std::pow(double(grid), dimension)));
  }
  for (Method m : methods) {
    const MethodPlan plan = plan_method(*this, m);
    if (compute_rdf && periodic_statistics() && rdf.r_max >= 0.5 * plan.domain.side)
      throw std::invalid_argument(fmt::format("--rdf-max {:g} with --periodic must be below half the {} set's side ({:g})",
                                              rdf.r_max, to_string(m), 0.5 * plan.domain.side));
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
    if (m == Method::pds && plan.pds_radius > 0.0) {
      PoissonDiskOptions o;
      o.radius = plan.pds_radius;
      o.domain = plan.domain;
      o.validate(dimension);
    }
  }
  // An absurd --max-memory makes the limit Inf: then nothing is refused here, and an allocation that
  // fails is reported by run_sampling.
  const double limit = memory_limit_bytes(*this);
  const auto check_sobol_count = [&] {  // after the memory, which says more about a huge run
    for (Method m : methods)
      if (m == Method::sobol && plan_method(*this, m).requested > (std::uint64_t{1} << 32))
        throw std::invalid_argument("Sobol supports at most 2^32 points");
  };
  if (stream) {
    if (const std::string why = stream_refusal(*this); !why.empty()) throw std::invalid_argument(why);
    const int slabs = stream_slab_count(*this, stream_slabs);
    const double need = streamed_peak_bytes(*this, slabs);
    if (need > limit)
      throw std::invalid_argument(fmt::format("--stream: a slab with its halo needs about {} of memory (limit {}); {}",
                                              byte_size(need), byte_size(limit), streamed_memory_advice(*this, slabs, limit)));
    check_sobol_count();
    return;
  }
  const double need = estimated_peak_bytes(*this);
  if (need <= limit) check_sobol_count();
  if (need > limit) {
    // Name the option the user gave: with -n the lattice's K was derived from the count.
    std::uint64_t largest = 0;
    for (Method m : methods) largest = std::max(largest, plan_method(*this, m).requested);
    const std::string size_option = count > 0 ? "-n" : "--grid";
    throw std::invalid_argument(fmt::format(
        "{} {} in {}D gives {} points, which need about {} of memory (limit {}); lower {} or raise the limit with "
        "--max-memory GIB",
        size_option, count > 0 ? count : static_cast<std::uint64_t>(grid), dimension, count > 0 ? largest : lattice_points,
        byte_size(need), byte_size(limit), size_option));
  }
}

namespace {

// The first `count` points of a sequence (make(m): its first m points in the cube) that lie in `domain`,
// in the sequence's order: the ball's points by rejection from the cube's, so that the sequence keeps its
// order and a longer run extends a shorter one. Other domains: make(count) as it is.
PointSet first_in_domain(const std::function<PointSet(std::uint64_t)>& make, const Domain& domain, std::uint64_t count,
                         int dimension) {
  if (domain.kind != DomainKind::ball) return make(count);
  const double fraction = domain.measure(dimension) / domain.box().volume(dimension);
  auto asked = static_cast<std::uint64_t>(std::ceil(1.2 * static_cast<double>(count) / fraction)) + 64;
  for (;;) {
    const PointSet all = make(asked);
    PointSet inside{dimension, Coordinates(static_cast<std::size_t>(count) * dimension), domain};
    std::uint64_t kept = 0;
    for (std::size_t i = 0; i < all.size() && kept < count; ++i)
      if (domain.contains(all.point(i), dimension)) {
        std::copy(all.point(i), all.point(i) + dimension, inside.coordinates.data() + kept * dimension);
        ++kept;
      }
    if (kept == count) return inside;
    asked *= 2;
  }
}

PointSet generate_points(const SampleConfig& config, const MethodPlan& plan, MethodResult& result,
                         SamplingContext& context, const StageProgress& progress) {
  const LatticeSpec lattice = config.lattice();
  const std::string stage(to_string(plan.method));
  const FractionProgress report = [&](double f) {
    if (progress) progress(stage, f);
  };
  GenerationFacts& facts = result.facts;
  const Domain& domain = plan.domain;
  const int n = config.dimension;
  switch (plan.method) {
    case Method::cnj: {
      if (domain.kind == DomainKind::sphere) {
        SphereCnjResult r = sphere_curl_noise_jitter(n, config.grid, config.cnj, config.seed, config.threads, report);
        facts.frequency = config.cnj.frequency;
        facts.field_frequency = r.field_frequency;
        facts.trace_time = r.trace_time;
        facts.skipped_updates = r.trace_stats.skipped_updates;
        facts.retraced = r.retraced;
        facts.kept_at_site = r.kept_at_site;
        result.notes = fmt::format("{} noise", to_string(config.cnj.noise));
        return std::move(r.points);
      }
      CnjResult r = curl_noise_jitter(lattice, config.cnj, config.seed, config.threads, report);
      context.cnj_rms_displacement = r.rms_displacement;
      facts.frequency = config.cnj.frequency;
      facts.field_frequency = r.field_frequency;
      facts.trace_time = r.trace_time;
      facts.dropped = r.dropped;
      facts.skipped_updates = r.trace_stats.skipped_updates;
      facts.retraced = r.retraced;
      facts.kept_at_site = r.kept_at_site;
      result.notes = fmt::format("{} noise; {}", to_string(config.cnj.noise), to_string(config.cnj.domain_mode));
      if (config.cnj.field == FieldKind::curl) result.notes += "; curl noise field, no reprojection";
      if (config.cnj.domain != DomainKind::ball)  // the ball's clipped lattice has no K^N neighbour structure
        result.displacement = summarize_lattice_displacements(n, config.grid, cnj_lattice(lattice, config.cnj.domain).spacing(),
                                                              r.displacements, {}, config.threads);
      return std::move(r.points);
    }
    case Method::jitter: {
      facts.half_width = jitter_half_width(lattice);
      if (domain.kind == DomainKind::ball) {
        result.notes = "the sites in the ball; an offset leaving it drawn again";
        return jittered_sites_in_ball(lattice, config.seed, config.threads);
      }
      PointSet points = jittered_lattice(lattice, config.seed, config.threads);
      result.displacement = summarize_lattice_displacements(n, config.grid, lattice.spacing(),
                                                            lattice_displacements(lattice, points), {}, config.threads);
      return points;
    }
    case Method::jitter_matched: {
      if (!context.cnj_rms_displacement)  // CNJ has not run: its displacements, without its points
        context.cnj_rms_displacement =
            curl_noise_jitter(lattice, config.cnj, config.seed, config.threads).rms_displacement;
      const bool torus = config.cnj.domain == DomainKind::torus;
      const LatticeSpec cnj_sites = cnj_lattice(lattice, config.cnj.domain);
      MatchedJitter j = jitter_matching_rms(cnj_sites, *context.cnj_rms_displacement,
                                            torus ? JitterBoundary::wrap : JitterBoundary::reflect, config.seed,
                                            config.threads);
      facts.half_width = j.half_width;
      result.notes = fmt::format("CNJ's RMS displacement; {}", torus ? "wrapped on the torus" : "reflected at the faces");
      result.displacement =
          summarize_lattice_displacements(n, config.grid, cnj_sites.spacing(), j.displacements, {}, config.threads);
      return std::move(j.points);
    }
    case Method::random:
      if (domain.kind == DomainKind::sphere) return uniform_points_on_sphere(n, plan.requested, config.seed, config.threads);
      return first_in_domain(
          [&](std::uint64_t m) { return uniform_random_points(n, m, domain.box(), config.seed, config.threads); }, domain,
          plan.requested, n);
    case Method::pds: {
      PoissonDiskOptions o;
      o.radius = plan.pds_radius;
      o.candidates = config.pds_candidates;
      o.max_points = plan.requested;
      o.domain = domain;
      PoissonDiskResult r = plan.pds_radius > 0.0 ? poisson_disk(n, o, config.seed, config.threads, report)
                                                  : poisson_disk_reaching(n, o, config.seed, config.threads, report);
      facts.radius = r.radius;
      facts.saturated = !r.reached_max_points;
      result.notes = plan.pds_radius > 0.0
                         ? (r.reached_max_points ? "stopped at the requested count" : "saturated (active list empty)")
                         : fmt::format("the largest radius found to reach the count ({} run{})", r.runs,
                                       r.runs == 1 ? "" : "s");
      return std::move(r.points);
    }
    case Method::sobol:
      result.notes = fmt::format("{} scrambling", to_string(config.scramble));
      return first_in_domain(
          [&](std::uint64_t m) { return sobol_points(n, m, domain.box(), config.scramble, config.seed, config.threads); },
          domain, plan.requested, n);
    case Method::halton:
      result.notes = config.scramble == Scramble::owen ? "digit-permutation scrambling" : "no scrambling";
      return first_in_domain(
          [&](std::uint64_t m) {
            return halton_points(n, m, domain.box(), config.scramble == Scramble::owen, config.seed, config.threads);
          },
          domain, plan.requested, n);
    case Method::lhs:
      return latin_hypercube_points(n, plan.requested, domain.box(), config.seed, config.threads);
  }
  throw std::logic_error("unknown method");
}

}  // namespace

void generate_points(const SampleConfig& config, MethodResult& result, SamplingContext& context,
                     const StageProgress& progress) {
  result.points = generate_points(config, result.plan, result, context, progress);
  // Every set lives where its plan says, whatever box its generator filled (the torus' points are in
  // [0,1)^N; the paper's lattice sets in the box their cells fill), and is measured there.
  result.points.domain = result.plan.domain;
  result.point_count = result.points.size();
}

void generate_points(const SampleConfig& config, MethodResult& result, const StageProgress& progress) {
  SamplingContext context;
  generate_points(config, result, context, progress);
}

namespace {

std::string out_of_memory_message(const SampleConfig& config, const MethodPlan& plan) {
  return fmt::format("out of memory for the {} point set: {} points in {}D need about {}; lower {}{}",
                     to_string(plan.method), plan.requested, config.dimension,
                     byte_size(estimated_bytes(plan, config.dimension)), config.count > 0 ? "-n" : "--grid",
                     config.max_memory_gib > 0.0 ? " or --max-memory" : "");
}

// Generate one point set, then its statistics.
MethodResult run_method(const SampleConfig& config, const MethodPlan& plan, bool keep_points, SamplingContext& context,
                        const StageProgress& progress, const std::function<void(const MethodResult&)>& on_result) {
  const Method method = plan.method;
  MethodResult result;
  result.plan = plan;
  const std::string name(to_string(method));
  if (progress) progress(name, 0.0);
  Stopwatch stopwatch;
  generate_points(config, result, context, progress);
  result.seconds_generate = stopwatch.seconds();
  if (!config.compute_statistics) {
    if (on_result) on_result(result);
    if (!keep_points) result.points = PointSet{result.points.dimension, {}, result.points.domain};
    return result;
  }
  if (result.points.size() < 2)  // CNJ drops the points that leave the unit cube
    throw std::invalid_argument(fmt::format("the {} point set has {} point(s) ({}); the statistics need at least 2",
                                            name, result.points.size(),
                                            result.facts.dropped ? fmt::format("{} dropped", *result.facts.dropped)
                                                                 : result.notes));
  const std::string statistics_stage = name + " statistics";
  const FractionProgress report_statistics = [&](double f) {
    if (progress) progress(statistics_stage, f);
  };
  report_statistics(0.0);
  stopwatch.restart();
  // In the set's domain: great-circle angles on the sphere, minimum-image distances on the torus.
  result.nearest = summarize_nearest_neighbours(
      nearest_neighbour_distances_in_domain(result.points, config.knn, config.threads, report_statistics), result.points);
  result.measured = true;
  result.seconds_stats = stopwatch.seconds();
  if (config.compute_rdf) {
    const std::string rdf_stage = name + " rdf";
    const FractionProgress report_rdf = [&](double f) {
      if (progress) progress(rdf_stage, f);
    };
    report_rdf(0.0);
    result.rdf = radial_distribution(result.points, config.rdf, config.seed, config.threads, report_rdf);
  }
  if (on_result) on_result(result);
  if (!keep_points) result.points = PointSet{result.points.dimension, {}, result.points.domain};
  return result;
}

}  // namespace

MethodResult sample_method(const SampleConfig& config, Method method) {
  SampleConfig one = config;
  one.methods = {method};
  one.validate();
  MethodResult result;
  result.plan = plan_method(one, method);
  try {
    generate_points(one, result);
  } catch (const std::bad_alloc&) {
    throw std::runtime_error(out_of_memory_message(one, result.plan));
  } catch (const std::length_error&) {
    throw std::runtime_error(out_of_memory_message(one, result.plan));
  }
  return result;
}

std::vector<MethodResult> run_sampling(const SampleConfig& config, bool keep_points, const StageProgress& progress,
                                       const std::function<void(const MethodResult&)>& on_result) {
  config.validate();
  std::vector<MethodResult> results;
  SamplingContext context;
  for (Method method : config.methods) {
    const MethodPlan plan = plan_method(config, method);
    try {
      results.push_back(run_method(config, plan, keep_points, context, progress, on_result));
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
         "protocol,domain,domain_side,requested,cycles_per_spacing,field_frequency,trace_time,dropped,skipped_updates,retraced,kept_at_site,"
         "half_width,radius,saturated,noise,mode,scramble,notes\n";
}

namespace {

// One CSV field per value; empty when the value does not apply.
std::string field_or_empty(const std::optional<double>& value) { return value ? format_real(*value) : std::string(); }
std::string field_or_empty(const std::optional<std::uint64_t>& value) { return value ? std::to_string(*value) : std::string(); }
std::string field_or_empty(const std::optional<bool>& value) { return value ? std::string(*value ? "1" : "0") : std::string(); }

// The settings a method's row names in their own columns (noise and mode for CNJ, the scrambling for
// Sobol and Halton), and the notes' words that remain.
struct RowSettings {
  std::string noise, mode, scramble, notes;
};
RowSettings row_settings(const SampleConfig& config, const MethodResult& r) {
  RowSettings s;
  s.notes = r.notes;
  switch (r.plan.method) {
    case Method::cnj:
      s.noise = to_string(config.cnj.noise);
      if (r.plan.domain.kind != DomainKind::sphere) s.mode = to_string(config.cnj.domain_mode);
      s.notes = config.cnj.field == FieldKind::curl ? "curl noise field, no reprojection" : "";
      break;
    case Method::sobol:
      s.scramble = to_string(config.scramble);
      s.notes.clear();
      break;
    case Method::halton:
      s.scramble = config.scramble == Scramble::owen ? "digit-permutation" : "none";
      s.notes.clear();
      break;
    default:
      break;
  }
  return s;
}

}  // namespace

std::string stats_csv_row(const SampleConfig& config, const MethodResult& r, bool timing) {
  std::string nearest = ",,,,";
  if (r.measured)
    nearest = fmt::format("{},{},{},{},{}", format_real(r.nearest.min), format_real(r.nearest.q01), format_real(r.nearest.median),
                          format_real(r.nearest.mean), format_real(r.nearest.median_scaled));
  std::string displacement = ",,,,";  // no lattice: the columns stay empty
  if (r.displacement)
    displacement = fmt::format("{},{},{},{},{}", format_real(r.displacement->rms), format_real(r.displacement->median),
                               format_real(r.displacement->fraction_unmoved), format_real(r.displacement->neighbour_disorder),
                               format_real(r.displacement->lattice_order));
  const std::string seconds =
      timing ? fmt::format("{:.6f},{}", r.seconds_generate, r.measured ? fmt::format("{:.6f}", r.seconds_stats) : "") : ",";
  const GenerationFacts& f = r.facts;
  const RowSettings settings = row_settings(config, r);
  return fmt::format("{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n", config.dimension,
                     config.grid,
                     to_string(r.plan.method), r.point_count,
                     nearest, displacement, seconds, config.seed, to_string(config.protocol),
                     to_string(r.plan.domain.kind), format_real(r.plan.domain.side),
                     r.plan.requested, field_or_empty(f.frequency), field_or_empty(f.field_frequency),
                     field_or_empty(f.trace_time), field_or_empty(f.dropped), field_or_empty(f.skipped_updates),
                     field_or_empty(f.retraced), field_or_empty(f.kept_at_site), field_or_empty(f.half_width),
                     field_or_empty(f.radius), field_or_empty(f.saturated), settings.noise, settings.mode,
                     settings.scramble, csv_quoted(settings.notes));
}

std::string rdf_csv_header() { return "dim,method,r,g\n"; }

std::string rdf_csv_rows(const SampleConfig& config, const MethodResult& r) {
  std::string out;
  if (!r.rdf) return out;
  for (std::size_t k = 0; k < r.rdf->r.size(); ++k)
    fmt::format_to(std::back_inserter(out), "{},{},{},{}\n", config.dimension, to_string(r.plan.method),
                   format_real(r.rdf->r[k]), format_real(r.rdf->g[k]));
  return out;
}

}  // namespace dfvn
