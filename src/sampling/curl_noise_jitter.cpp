#include "dfvn/sampling/curl_noise_jitter.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "dfvn/core/message_text.hpp"
#include "dfvn/noise/noise_domain.hpp"
#include "dfvn/integrate/trace_table.hpp"

namespace dfvn {

DomainMode parse_domain_mode(std::string_view name) {
  if (name == "conformant") return DomainMode::conformant;
  if (name == "drop") return DomainMode::drop;
  throw std::invalid_argument("unknown domain mode " + quote_for_message(name) + " (allowed: conformant, drop)");
}

std::string_view to_string(DomainMode mode) { return mode == DomainMode::conformant ? "conformant" : "drop"; }

int cnj_steps(const CnjOptions& options) {
  if (options.trace.steps != CnjOptions::kStepsByDomainMode) return options.trace.steps;
  const bool free_field = options.domain_mode == DomainMode::drop || options.domain == DomainKind::torus;
  return free_field ? kFreeFieldSteps : 1;
}

TraceOptions cnj_trace_options(const CnjOptions& options) {
  TraceOptions trace = options.trace;
  trace.steps = cnj_steps(options);
  return trace;
}

void CnjOptions::validate() const {
  if (trace.steps < 0)
    throw std::invalid_argument(
        fmt::format("CNJ steps must be at least 1, or 0 for the domain mode's count; got {}", trace.steps));
  cnj_trace_options(*this).validate();
  if (!(step_scale > 0.0 && step_scale <= kMaxStepScale))
    throw std::invalid_argument(fmt::format("step scale must be in (0, 2^20], got {:g}", step_scale));
  check_noise_frequency(frequency, "--cycles-per-spacing (CNJ's frequency per lattice spacing)");
  check_noise_phase(phase);
  transform.validate();
  parse_noise_basis(to_string(noise));  // an unknown enum value throws
  parse_domain_kind(to_string(domain));
  if (domain == DomainKind::sphere && domain_mode == DomainMode::drop)
    throw std::invalid_argument("CNJ on the sphere traces along it: it has no boundary to drop points at");
  parse_bound(to_string(bound));
  if (domain == DomainKind::torus && domain_mode == DomainMode::drop)
    throw std::invalid_argument("the torus has no boundary to drop points at: use domain mode conformant (its traces wrap)");
  if (domain == DomainKind::torus && noise != NoiseBasis::turning_bands)
    throw std::invalid_argument(fmt::format("the torus needs a periodic noise basis: turning-bands (not {})", to_string(noise)));
  parse_field_kind(to_string(field));
  if (field == FieldKind::curl && trace.reprojection != Reprojection::none)
    throw std::invalid_argument(
        "curl noise has no reprojection (its streamlines are not intersections of iso-surfaces): --reproject none");
  if (field == FieldKind::curl && domain != DomainKind::torus && domain_mode == DomainMode::conformant)
    throw std::invalid_argument(
        "CNJ along curl noise has no boundary treatment (Bridson's boundaries exist for `field` only): conformant CNJ "
        "in the cube or ball needs --field dfvn; use the torus or --domain-mode drop");
  if (!(boundary_width > 0.0 && boundary_width <= 1e6))
    throw std::invalid_argument(fmt::format("boundary width must be in (0, 1e6] lattice spacings, got {:g}", boundary_width));
  // Refinements double the steps kMaxRefinements times: keep that an int.
  if (cnj_steps(*this) > kMaxSteps)
    throw std::invalid_argument(fmt::format("CNJ takes at most 2^20 steps, got {}", cnj_steps(*this)));
}

namespace {
double transition_width_for_spacing(const CnjOptions& options, double spacing) {
  return std::min(options.boundary_width * spacing, 0.25);
}
}  // namespace

double cnj_transition_width(const CnjOptions& options, const LatticeSpec& lattice) {
  return transition_width_for_spacing(options, lattice.spacing());
}

namespace {

bool site_in_domain(const double* x, int dimension, DomainKind domain) {
  if (domain != DomainKind::ball) return true;
  double from_centre2 = 0.0;
  for (int j = 0; j < dimension; ++j) from_centre2 += (x[j] - 0.5) * (x[j] - 0.5);
  return from_centre2 < 0.25;
}

FieldConstraint field_constraint(const CnjOptions& options) {
  if (options.domain_mode == DomainMode::drop || options.domain == DomainKind::torus) return FieldConstraint::none;
  return options.domain == DomainKind::cube ? FieldConstraint::inside_cube : FieldConstraint::inside_ball;
}

}  // namespace

FieldOptions cnj_field_options(const CnjOptions& options, double spacing) {
  FieldOptions field{options.noise,     options.frequency / spacing,
                     field_constraint(options), transition_width_for_spacing(options, spacing),
                     options.bound,     options.domain == DomainKind::torus,
                     options.field,     options.phase,
                     options.transform};
  field.flow = options.flow;
  return field;
}

LatticeSpec cnj_lattice(const LatticeSpec& lattice, DomainKind domain) {
  LatticeSpec out = lattice;
  if (domain == DomainKind::torus) out.protocol = Protocol::fair;
  return out;
}

std::vector<double> cnj_start_sites(const LatticeSpec& lattice, DomainKind domain) {
  const int n = lattice.dimension;
  const std::uint64_t count = lattice.point_count();
  std::vector<double> sites;
  sites.reserve(domain != DomainKind::ball ? count * n : 0);
  std::vector<double> x(static_cast<std::size_t>(n));
  for (std::uint64_t i = 0; i < count; ++i) {
    lattice.point(i, x.data());
    if (site_in_domain(x.data(), n, domain)) sites.insert(sites.end(), x.begin(), x.end());
  }
  return sites;
}

std::uint64_t cnj_start_count(const LatticeSpec& lattice, DomainKind domain) {
  const std::uint64_t count = lattice.point_count();
  if (domain != DomainKind::ball) return count;
  std::uint64_t inside = 0;
  std::vector<double> x(static_cast<std::size_t>(lattice.dimension));
  for (std::uint64_t i = 0; i < count; ++i) {
    lattice.point(i, x.data());
    inside += site_in_domain(x.data(), lattice.dimension, domain);
  }
  return inside;
}

namespace {

// CNJ of the start sites `sites` (rows of the lattice CNJ starts from, in its order): every point's trace
// depends only on its site, the options and the seed, so a slab of sites gives the whole run's rows.
template <int N>
CnjResult curl_noise_jitter_sites(const LatticeSpec& lattice, const CnjOptions& options, std::uint64_t seed,
                                  const std::vector<double>& sites, int threads, const FractionProgress& progress) {
  const bool torus = options.domain == DomainKind::torus;
  CnjResult result;
  result.trace_time = options.step_scale * average_neighbour_distance(N) * lattice.spacing();
  const DfvnField<N> field(seed, cnj_field_options(options, lattice.spacing()));
  result.field_frequency = field.frequency();
  const Domain domain = Domain::unit(options.domain);
  const auto count = static_cast<std::int64_t>(sites.size() / N);
  result.started = static_cast<std::uint64_t>(count);

  std::vector<double> ends(sites.size());
  // On the torus every end is accepted (and wrapped below); elsewhere the domain decides.
  const TracedPoints traced = trace_table<N>(
      field, cnj_trace_options(options), sites.data(), static_cast<std::size_t>(count), ends.data(), result.trace_time,
      [&](const Vec<N>& x) { return torus || domain.contains(x.data(), N); },
      options.domain_mode == DomainMode::conformant ? OnReject::retrace : OnReject::drop, threads, progress);
  // Compact and sum in index order, so every output is the same for any thread count.
  result.points = PointSet{N, {}, domain};
  result.points.coordinates.reserve(ends.size());
  result.displacements.resize(ends.size());
  double total_squared_displacement = 0.0;
  for (std::int64_t i = 0; i < count; ++i) {
    auto u = Eigen::Map<Vec<N>>(result.displacements.data() + i * N);
    u = Eigen::Map<const Vec<N>>(ends.data() + i * N) - Eigen::Map<const Vec<N>>(sites.data() + i * N);
    total_squared_displacement += u.squaredNorm();
    if (traced.accepted[static_cast<std::size_t>(i)])
      result.points.coordinates.insert(result.points.coordinates.end(), ends.begin() + i * N, ends.begin() + (i + 1) * N);
    else
      ++result.dropped;
  }
  for (std::size_t i = 0; torus && i < result.points.size(); ++i) domain.wrap(result.points.coordinates.data() + i * N, N);
  result.rms_displacement = count > 0 ? std::sqrt(total_squared_displacement / static_cast<double>(count)) : 0.0;
  result.retraced = traced.retraced;
  result.kept_at_site = traced.kept_at_start;
  result.trace_stats = traced.stats;
  if (progress) progress(1.0);
  return result;
}

}  // namespace

template <int N>
CnjResult curl_noise_jitter(const LatticeSpec& requested_lattice, const CnjOptions& options, std::uint64_t seed,
                            int threads, const FractionProgress& progress) {
  options.validate();
  if (requested_lattice.dimension != N) throw std::invalid_argument("lattice dimension does not match");
  const LatticeSpec lattice = cnj_lattice(requested_lattice, options.domain);
  return curl_noise_jitter_sites<N>(lattice, options, seed, cnj_start_sites(lattice, options.domain), threads, progress);
}

CnjResult curl_noise_jitter(const LatticeSpec& lattice, const CnjOptions& options, std::uint64_t seed, int threads,
                            const FractionProgress& progress) {
  return dispatch_dimension(lattice.dimension, [&]<int N>() {
    return curl_noise_jitter<N>(lattice, options, seed, threads, progress);
  });
}

CnjResult curl_noise_jitter_range(const LatticeSpec& requested_lattice, const CnjOptions& options, std::uint64_t seed,
                                  std::uint64_t first, std::uint64_t count, int threads) {
  options.validate();
  if (options.domain == DomainKind::ball)
    throw std::invalid_argument("CNJ in the ball starts from the clipped lattice, whose rows are not lattice indices");
  const LatticeSpec lattice = cnj_lattice(requested_lattice, options.domain);
  const int n = lattice.dimension;
  std::vector<double> sites(static_cast<std::size_t>(count) * n);
  for (std::uint64_t r = 0; r < count; ++r) lattice.point(first + r, sites.data() + r * n);
  return dispatch_dimension(n, [&]<int N>() {
    return curl_noise_jitter_sites<N>(lattice, options, seed, sites, threads, {});
  });
}

}  // namespace dfvn
