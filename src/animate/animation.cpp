#include "dfvn/animate/animation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include <fmt/format.h>

#include "dfvn/core/message_text.hpp"
#include "dfvn/core/parallel.hpp"
#include "dfvn/integrate/trace_table.hpp"
#include "dfvn/noise/noise_functions.hpp"

namespace dfvn {

StartLattice parse_start_lattice(std::string_view name) {
  if (name == "cubic") return StartLattice::cubic;
  if (name == "bcc") return StartLattice::bcc;
  throw std::invalid_argument("unknown lattice " + quote_for_message(name) + " (allowed: cubic, bcc)");
}

std::string_view to_string(StartLattice lattice) { return lattice == StartLattice::cubic ? "cubic" : "bcc"; }

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
  const double steps = std::ceil(cnj_steps(options.cnj) * options.phase_step - 1e-12);
  return std::max(1, static_cast<int>(steps));
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

namespace {

template <int N>
AnimationResult run_animation(const AnimationOptions& options, std::uint64_t seed, int threads,
                              const FractionProgress& progress) {
  AnimationResult result;
  result.options = options;
  result.seed = seed;
  const CnjOptions& cnj = options.cnj;
  const bool conformant = cnj.domain_mode == DomainMode::conformant;
  const bool ball = cnj.domain == DomainKind::ball;
  result.spacing = 1.0 / options.grid;
  result.trace_time = cnj.step_scale * average_neighbour_distance(N) * result.spacing;
  result.frame_time = options.phase_step * result.trace_time;
  result.frame_steps = animation_frame_steps(options);
  const Domain domain = Domain::unit(ball ? DomainKind::ball : DomainKind::cube);
  // CNJ's field for this lattice (the torus and other field kinds are refused by validate()), turned to a phase.
  const FieldOptions field_options = cnj_field_options(cnj, result.spacing);
  const auto field_at = [&](double phase) {
    FieldOptions at = field_options;
    at.phase = phase;
    return DfvnField<N>(seed, at);
  };

  std::vector<double> current = animation_start_sites(options);
  const std::size_t count = current.size() / N;
  result.particles = count;
  result.positions.assign(static_cast<std::size_t>(options.frames) * count * N, 0.0);
  result.frames.resize(static_cast<std::size_t>(options.frames));
  std::vector<unsigned char> was_inside(count, 0), inside(count, 0);
  const auto accept = [&](const Vec<N>& x) { return !conformant || domain.contains(x.data(), N); };
  const OnReject on_reject = conformant ? OnReject::retrace : OnReject::drop;

  // alpha_0 modulo 2 pi: the same field, and a phase the steps advance (noise/noise_functions.hpp).
  const double start_phase = reduced_phase(options.start_phase);
  for (int k = 0; k < options.frames; ++k) {
    const double phase = start_phase + k * options.phase_step;
    const DfvnField<N> field = field_at(phase);
    if (k == 0) result.field_frequency = field.frequency();
    TraceOptions trace = cnj_trace_options(cnj);
    if (k > 0) trace.steps = result.frame_steps;
    // Frame 0: CNJ's jitter of the start sites; then one frame time per frame. The table is traced in
    // place (trace_table reads each row before it writes it).
    const std::vector<double> previous = current;
    const TracedPoints traced = trace_table<N>(field, trace, previous.data(), count, current.data(),
                                               k == 0 ? result.trace_time : result.frame_time, accept, on_reject,
                                               threads, {});
    FrameStats& stats = result.frames[static_cast<std::size_t>(k)];
    stats.frame = k;
    stats.phase = phase;
    stats.retraced = traced.retraced;
    stats.kept_at_start = traced.kept_at_start;
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
    was_inside.swap(inside);
    if (progress) progress(static_cast<double>(k + 1) / options.frames);
  }
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
