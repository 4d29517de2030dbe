#include "dfvn/animate/animation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include <fmt/format.h>

#include "dfvn/core/message_text.hpp"
#include "dfvn/core/parallel.hpp"
#include "dfvn/core/quantile.hpp"
#include "dfvn/integrate/trace_table.hpp"
#include "dfvn/noise/noise_functions.hpp"
#include "dfvn/stats/point_set_statistics.hpp"

namespace dfvn {

StartLattice parse_start_lattice(std::string_view name) {
  if (name == "cubic") return StartLattice::cubic;
  if (name == "bcc") return StartLattice::bcc;
  throw std::invalid_argument("unknown lattice " + quote_for_message(name) + " (allowed: cubic, bcc)");
}

std::string_view to_string(StartLattice lattice) { return lattice == StartLattice::cubic ? "cubic" : "bcc"; }

AnimationMode parse_animation_mode(std::string_view name) {
  if (name == "cnj") return AnimationMode::cnj;
  if (name == "advect") return AnimationMode::advect;
  throw std::invalid_argument("unknown animation mode " + quote_for_message(name) + " (allowed: cnj, advect)");
}

std::string_view to_string(AnimationMode mode) {
  switch (mode) {
    case AnimationMode::cnj: return "cnj";
    case AnimationMode::advect: return "advect";
  }
  return "?";
}

namespace {

int pad_spacings(const AnimationOptions& options) {
  return options.cnj.domain_mode == DomainMode::drop ? options.drop_margin : 0;
}

// An upper bound of the start sites (the padded box's lattice), in double so that it cannot overflow.
double site_bound(const AnimationOptions& options) {
  const int pad = pad_spacings(options);
  double count = std::pow(options.grid + 2.0 * pad, options.dimension);
  if (options.lattice == StartLattice::bcc) count += std::pow(options.grid - 1.0 + 2.0 * pad, options.dimension);
  return count;
}

// Whether the start set keeps the site x: conformant, the sites in the domain; drop, those within
// drop_margin spacings of it (the padded box already bounds the cube's).
bool keeps_start_site(const AnimationOptions& options, const double* x) {
  const int n = options.dimension;
  const bool ball = options.cnj.domain == DomainKind::ball;
  if (options.cnj.domain_mode != DomainMode::drop) return Domain::unit(ball ? DomainKind::ball : DomainKind::cube).contains(x, n);
  if (!ball) return true;
  double r2 = 0.0;
  for (int j = 0; j < n; ++j) r2 += (x[j] - 0.5) * (x[j] - 0.5);
  return std::sqrt(r2) <= 0.5 + pad_spacings(options) * (1.0 / options.grid);
}

// The start lattices as animation_start_sites makes them: per axis `per_axis` coordinates (first + i) / K.
struct StartLatticePart {
  int per_axis;
  double first;
};
std::vector<StartLatticePart> start_lattice_parts(const AnimationOptions& options) {
  const int k = options.grid, pad = pad_spacings(options);
  std::vector<StartLatticePart> parts{{k + 2 * pad, 0.5 - pad}};
  if (options.lattice == StartLattice::bcc) parts.push_back({k - 1 + 2 * pad, 1.0 - pad});
  return parts;
}

// Whether the start set has a site: the one of each lattice nearest the centre (every coordinate the one
// nearest 1/2) is kept when any is (the domain and the margin are balls or boxes about the centre).
bool holds_a_start_site(const AnimationOptions& options) {
  std::vector<double> x(static_cast<std::size_t>(options.dimension));
  for (const StartLatticePart& part : start_lattice_parts(options)) {
    if (part.per_axis <= 0) continue;
    double nearest = part.first / options.grid;
    for (int i = 1; i < part.per_axis; ++i) {
      const double c = (part.first + i) / options.grid;
      if (std::abs(c - 0.5) < std::abs(nearest - 0.5)) nearest = c;
    }
    std::fill(x.begin(), x.end(), nearest);
    if (keeps_start_site(options, x.data())) return true;
  }
  return false;
}

}  // namespace

void AnimationOptions::validate() const {
  if (dimension < kMinDimension || dimension > kMaxDimension)
    throw std::invalid_argument(fmt::format("dimension must be in [{}, {}], got {}", kMinDimension, kMaxDimension, dimension));
  if (grid < 2 || grid > (1 << 20)) throw std::invalid_argument(fmt::format("grid must be in [2, 2^20], got {}", grid));
  if (frames < 1 || frames > kMaxFrames)
    throw std::invalid_argument(fmt::format("frames must be in [1, {}], got {}", kMaxFrames, frames));
  if (!(std::isfinite(phase_step) && phase_step >= kMinPhaseStep && phase_step <= 2.0 * std::numbers::pi))
    throw std::invalid_argument(
        fmt::format("phase step must be in [2^-30, 2 pi] = [{:g}, {:g}] radians per frame, got {:g}", kMinPhaseStep,
                    2.0 * std::numbers::pi, phase_step));
  if (!std::isfinite(start_phase)) throw std::invalid_argument(fmt::format("phase must be finite, got {:g}", start_phase));
  // The last frame's phase must stay finite and exact enough to turn the gradients.
  check_noise_phase(start_phase + phase_step * frames);
  parse_start_lattice(to_string(lattice));
  parse_animation_mode(to_string(mode));
  if (drop_margin < 0 || drop_margin > kMaxDropMargin)
    throw std::invalid_argument(fmt::format("drop margin must be in [0, {}] lattice spacings, got {}", kMaxDropMargin, drop_margin));
  if (cnj.domain == DomainKind::torus)
    throw std::invalid_argument("animate needs a domain with a boundary: cube or ball (the torus has none to keep points in)");
  if (cnj.field != FieldKind::dfvn) throw std::invalid_argument("animate traces along the DFVN field (--field dfvn)");
  cnj.validate();
  // The help's limit: a transition width of at most a quarter of the side (the field clamped it there).
  if (cnj.domain_mode == DomainMode::conformant && cnj.boundary_width / grid > 0.25)
    throw std::invalid_argument(fmt::format(
        "boundary width {:g} lattice spacings is {:g} of the side, more than a quarter: at most {:g} spacings with grid {}",
        cnj.boundary_width, cnj.boundary_width / grid, 0.25 * grid, grid));
  if (!holds_a_start_site(*this)) {  // an empty run would write empty frames and exit 0
    AnimationOptions larger = *this;
    while (!holds_a_start_site(larger)) ++larger.grid;
    throw std::invalid_argument(fmt::format(
        "the {} holds no site of the {} start lattice of grid {} in {}D; the smallest grid with a site inside is {}",
        cnj.domain == DomainKind::ball ? "ball inscribed in the cube" : "cube", to_string(lattice), grid, dimension,
        larger.grid));
  }
  const double bytes = site_bound(*this) * frames * dimension * sizeof(double);
  if (bytes > kMaxFrameBytes)
    throw std::invalid_argument(fmt::format(
        "{} frames of up to {:.0f} particles in {}D need {:.3g} GiB for frames.npy, more than the 2 GiB allowed: fewer "
        "frames or a smaller grid",
        frames, site_bound(*this), dimension, bytes / 0x1p30));
}

int animation_frame_steps(const AnimationOptions& options) {
  if (options.mode == AnimationMode::cnj) return cnj_steps(options.cnj);
  const double steps = std::ceil(cnj_steps(options.cnj) * options.phase_step - 1e-12);
  return std::max(1, static_cast<int>(steps));
}

TraceOptions animation_trace_options(const AnimationOptions& options) {
  TraceOptions trace = cnj_trace_options(options.cnj);
  trace.policy = TracePolicy::continuous;
  // Steps of at most half the bound's transition width w, the field's finest length scale: there Eq. (13)
  // turns the noise into the boundary function and the velocity and its gradient peak. With w itself,
  // one-step traces near the cube's edges still end erratically; w / 2 costs 1.3x as much
  // (data/animation_continuity.md).
  trace.max_step_length = 0.5 * cnj_transition_width(options.cnj, LatticeSpec{options.dimension, options.grid, Protocol::fair});
  return trace;
}

std::vector<double> animation_start_sites(const AnimationOptions& options) {
  const int n = options.dimension, k = options.grid;
  std::vector<double> sites;
  std::vector<double> x(static_cast<std::size_t>(n));
  // One lattice: per axis `per_axis` coordinates (first + i) / K (the cubic one's are LatticeSpec's
  // unit protocol's (i + 1/2) / K, bit for bit, so frame 0 of a conformant cubic run is CNJ's set).
  const auto add_lattice = [&](int per_axis, double first) {
    if (per_axis <= 0) return;
    std::uint64_t count = 1;
    for (int j = 0; j < n; ++j) count *= static_cast<std::uint64_t>(per_axis);
    for (std::uint64_t index = 0; index < count; ++index) {
      std::uint64_t rest = index;
      for (int j = 0; j < n; ++j) {
        x[j] = (first + static_cast<double>(rest % per_axis)) / k;
        rest /= per_axis;
      }
      if (keeps_start_site(options, x.data())) sites.insert(sites.end(), x.begin(), x.end());
    }
  };
  for (const StartLatticePart& part : start_lattice_parts(options)) add_lattice(part.per_axis, part.first);
  return sites;
}

double AnimationResult::popping_per_100_frames() const {
  if (frames.size() < 2) return 0.0;
  double events = 0.0;
  for (std::size_t k = 1; k < frames.size(); ++k) events += static_cast<double>(frames[k].entered + frames[k].left);
  return 100.0 * events / static_cast<double>(frames.size() - 1);
}

double AnimationResult::mean_spacing() const {
  const int n = options.dimension;
  const double measure = Domain::unit(options.cnj.domain).measure(n);
  const double inside = frames.empty() ? 0.0 : static_cast<double>(frames[0].inside);
  return inside > 0.0 ? std::pow(measure / inside, 1.0 / n) : std::numeric_limits<double>::quiet_NaN();
}

PackingSummary summarise_packing(const AnimationResult& result) {
  PackingSummary s;
  if (result.frames.empty()) return s;
  // The 1% quantile in mean spacings: nn_median_scaled / nn_median is 1 / the frame's mean spacing.
  const auto q01_scaled = [](const FrameStats& f) { return f.nn_q01 * f.nn_median_scaled / f.nn_median; };
  s.median_0 = result.frames[0].nn_median_scaled;
  s.q01_0 = q01_scaled(result.frames[0]);
  s.median_min = s.q01_min = std::numeric_limits<double>::infinity();
  s.median_max = s.q01_max = -std::numeric_limits<double>::infinity();
  double sum = 0.0;
  int counted = 0;
  for (const FrameStats& f : result.frames) {
    if (std::isnan(f.nn_median_scaled)) continue;
    const double median = f.nn_median_scaled / s.median_0, q01 = q01_scaled(f) / s.q01_0;
    sum += median;
    ++counted;
    if (median < s.median_min) s.median_min = median, s.median_min_frame = f.frame;
    if (q01 < s.q01_min) s.q01_min = q01, s.q01_min_frame = f.frame;
    s.median_max = std::max(s.median_max, median);
    s.q01_max = std::max(s.q01_max, q01);
  }
  s.median_mean = counted > 0 ? sum / counted : std::numeric_limits<double>::quiet_NaN();
  return s;
}

namespace {

MoveSummary summarise_moves(const AnimationResult& a) {
  const int n = a.options.dimension;
  std::vector<double> moves;
  for (int k = 1; k < a.options.frames; ++k) {
    const double *before = a.frame(k - 1), *now = a.frame(k);
    for (std::uint64_t i = 0; i < a.particles; ++i) {
      if (std::isnan(before[i * n]) || std::isnan(now[i * n])) continue;
      double d2 = 0.0;
      for (int j = 0; j < n; ++j) d2 += (now[i * n + j] - before[i * n + j]) * (now[i * n + j] - before[i * n + j]);
      moves.push_back(std::sqrt(d2));
    }
  }
  MoveSummary s;
  s.moves = moves.size();
  if (moves.empty()) return s;
  std::sort(moves.begin(), moves.end());
  const double unit = a.mean_spacing();
  s.median = median_of_sorted(moves) / unit;
  s.p99 = quantile_of_sorted(moves, 0.99) / unit;
  s.largest = moves.back() / unit;
  return s;
}

// The packing of a frame's particles inside the domain (rows, particles x N; NaN rows skipped).
void measure_packing(const double* rows, std::uint64_t particles, int n, const Domain& domain, int threads,
                     FrameStats& stats) {
  PointSet shown{n, {}, domain};
  for (std::uint64_t i = 0; i < particles; ++i)
    if (!std::isnan(rows[i * n])) shown.coordinates.insert(shown.coordinates.end(), rows + i * n, rows + (i + 1) * n);
  if (shown.size() < 2) {
    stats.nn_min = stats.nn_q01 = stats.nn_median = stats.nn_median_scaled = std::numeric_limits<double>::quiet_NaN();
    return;
  }
  const NearestNeighbourSummary nearest = summarize_nearest_neighbours(
      nearest_neighbour_distances_in_domain(shown, KnnBackend::nanoflann, threads), shown);
  stats.nn_min = nearest.min;
  stats.nn_q01 = nearest.q01;
  stats.nn_median = nearest.median;
  stats.nn_median_scaled = nearest.median_scaled;
}

// The nearest point of the closed unit cube or its inscribed ball: a continuous map (the projection onto
// a convex set), cnj mode's fallback for a conformant trace end outside the domain.
template <int N>
void move_into(const Domain& domain, Vec<N>& x) {
  x = x.cwiseMax(0.0).cwiseMin(1.0);
  if (domain.kind != DomainKind::ball) return;
  // Onto the sphere, then towards the centre by a few ulps at a time until domain.contains agrees (the
  // rounding of the scaled point may leave it just outside).
  const Vec<N> from_centre = (x.array() - 0.5).matrix();
  const double r = from_centre.norm();
  for (double radius = 0.5; !domain.contains(x.data(), N) && r > 0.0; radius *= 1.0 - 0x1p-48)
    x = (from_centre * (std::min(radius, r) / r)).array() + 0.5;
}

template <int N>
AnimationResult run_animation(const AnimationOptions& options, std::uint64_t seed, int threads,
                              const FractionProgress& progress) {
  AnimationResult result;
  result.options = options;
  result.seed = seed;
  const CnjOptions& cnj = options.cnj;
  const bool conformant = cnj.domain_mode == DomainMode::conformant;
  const bool advect = options.mode == AnimationMode::advect;
  result.spacing = 1.0 / options.grid;
  result.trace_time = cnj.step_scale * average_neighbour_distance(N) * result.spacing;
  result.frame_time = options.phase_step * result.trace_time;
  result.frame_steps = animation_frame_steps(options);
  const Domain domain = Domain::unit(cnj.domain);
  // CNJ's field for this lattice (the torus and other field kinds are refused by validate()), turned to a phase.
  const FieldOptions field_options = cnj_field_options(cnj, result.spacing);
  const auto field_at = [&](double phase) {
    FieldOptions at = field_options;
    at.phase = phase;
    return DfvnField<N>(seed, at);
  };

  const std::vector<double> sites = animation_start_sites(options);
  std::vector<double> current = sites;
  const std::size_t count = current.size() / N;
  result.particles = count;
  result.positions.assign(static_cast<std::size_t>(options.frames) * count * N, 0.0);
  result.frames.resize(static_cast<std::size_t>(options.frames));
  std::vector<unsigned char> was_inside(count, 0), inside(count, 0);
  const auto accept = [&](const Vec<N>& x) { return !conformant || domain.contains(x.data(), N); };
  // advect: CNJ's guarded traces, a conformant end outside retraced with more steps; cnj: the continuous
  // trace map, ends outside reported (OnReject::drop writes them as traced) and moved into the domain below.
  const OnReject on_reject = advect && conformant ? OnReject::retrace : OnReject::drop;
  const TraceOptions cnj_trace = advect ? cnj_trace_options(cnj) : animation_trace_options(options);
  TraceOptions frame_trace = cnj_trace;
  frame_trace.steps = result.frame_steps;

  // alpha_0 modulo 2 pi: the same field, and a phase the steps advance (noise/noise_functions.hpp).
  const double start_phase = reduced_phase(options.start_phase);
  for (int k = 0; k < options.frames; ++k) {
    const double phase = start_phase + k * options.phase_step;
    const DfvnField<N> field = field_at(phase);
    if (k == 0) result.field_frequency = field.frequency();
    FrameStats& stats = result.frames[static_cast<std::size_t>(k)];
    stats.frame = k;
    stats.phase = phase;
    const std::vector<double> previous = current;
    // cnj: every frame is CNJ's jitter of the start sites. advect: frame 0 is, then one frame time per
    // frame from the frame before. The table is traced in place (trace_table reads each row before it
    // writes it).
    const bool from_sites = !advect || k == 0;
    const TracedPoints traced =
        trace_table<N>(field, from_sites ? cnj_trace : frame_trace, from_sites ? sites.data() : previous.data(), count,
                       current.data(), from_sites ? result.trace_time : result.frame_time, accept, on_reject, threads, {});
    stats.retraced = traced.retraced;
    stats.kept_at_start = traced.kept_at_start;
    if (!advect && conformant) {
      for (std::size_t i = 0; i < count; ++i) {
        if (traced.accepted[i]) continue;
        Eigen::Map<Vec<N>> x(current.data() + i * N);
        Vec<N> moved = x;
        move_into<N>(domain, moved);
        x = moved;
        ++stats.projected;
      }
    }
    double* out = result.positions.data() + static_cast<std::size_t>(k) * count * N;
    double sum2 = 0.0;
    std::uint64_t moved = 0;
    // In index order: the sums do not depend on the thread count.
    for (std::size_t i = 0; i < count; ++i) {
      const double* x = current.data() + i * N;
      inside[i] = domain.contains(x, N);
      if (inside[i]) {
        std::copy(x, x + N, out + i * N);
        ++stats.inside;
      } else {
        std::fill(out + i * N, out + (i + 1) * N, std::numeric_limits<double>::quiet_NaN());
      }
      if (k == 0) continue;
      if (inside[i] && !was_inside[i]) ++stats.entered;
      if (!inside[i] && was_inside[i]) ++stats.left;
      if (inside[i] && was_inside[i]) {
        double d2 = 0.0;
        for (int j = 0; j < N; ++j) d2 += (x[j] - previous[i * N + j]) * (x[j] - previous[i * N + j]);
        sum2 += d2;
        ++moved;
        stats.largest_jump = std::max(stats.largest_jump, std::sqrt(d2));
      }
    }
    stats.rms_move = moved > 0 ? std::sqrt(sum2 / static_cast<double>(moved)) : 0.0;
    measure_packing(out, count, N, domain, threads, stats);
    was_inside.swap(inside);
    if (progress) progress(static_cast<double>(k + 1) / options.frames);
  }
  result.moves = summarise_moves(result);
  return result;
}

}  // namespace

AnimationResult animate(const AnimationOptions& options, std::uint64_t seed, int threads,
                        const FractionProgress& progress) {
  options.validate();
  check_thread_count(threads);
  return dispatch_dimension(options.dimension,
                            [&]<int N>() { return run_animation<N>(options, seed, threads, progress); });
}

}  // namespace dfvn
