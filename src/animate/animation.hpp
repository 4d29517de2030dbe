// Animated curl noise jittering (the paper's Section 5.4 and Figure 8): the field's phase turns
// (rotating gradients, FieldOptions::phase) by DA radians per frame, alpha_k = alpha_0 + k DA, and the
// particles follow. Two modes (AnimationMode, --mode):
//
// cnj (the default, issue 46): frame k is CNJ of the start lattice at phase alpha_k: every particle is
// its lattice site traced for the CNJ trace time t_cnj along the field at alpha_k. Every frame is a CNJ
// set, with CNJ's packing, and a particle's motion is the derivative of the trace map in alpha. For that
// to be small the trace map must be continuous in alpha: the traces take CNJ's fixed step count with
// TracePolicy::continuous (integrate/trace.hpp: every reprojection update taken, shortened where too
// long, so no trace switches branch between neighbouring phases) and no retrace with more steps. A
// conformant end that still lands outside the domain (an RK4 step across the boundary that the
// reprojection does not bring back) is moved to the nearest point of the domain, a continuous map
// too (FrameStats::projected counts them). In drop mode a particle is shown when its trace ends inside
// the domain: it pops only where its end crosses the boundary.
//
// advect (the mode before issue 46): frame k (k >= 1) is frame k-1 traced for one frame time along the
// field at alpha_k. A divergence-free flow keeps the density uniform but mixes the jittered lattice
// towards uniform random points: in 2D (16^2, 300 frames) the median nearest-neighbour distance falls
// from 0.93 mean spacings to 0.54 by frame 200 (uniform random points: 0.48), data/figure8_record.md.
//
// Time and phase: alpha = omega t with omega = 1 / t_cnj, t_cnj the CNJ trace time
// (sampling/curl_noise_jitter.hpp: step_scale dbar(N) spacing): over one radian of phase a point moves
// as far (RMS) as in one CNJ jitter. One frame is DA radians, so the frame time is DA t_cnj and every
// move shrinks linearly with DA (the continuity target), in both modes.
//
// What reprojection holds in advect mode: within frame k the trace is Algorithm 1 in the field at
// alpha_k, so it holds f_i(x; alpha_k) at the values f_i(x_{k-1}; alpha_k) that it reads at the frame's
// start: the iso-values move with alpha from frame to frame (a point is on different iso-surfaces of
// alpha_k and alpha_{k+1}), nothing ties a point to the iso-values of an earlier frame. The boundary
// function does not move: with a bound (conformant cube or ball), f_1 = (1 - a) G d + a f~_1(x; alpha)
// (Eq. 13) or ramp(d / w) f~_1(x; alpha), and on the boundary (a = 0, ramp 0) f_1 = 0 and grad f_1 is
// normal to it whatever alpha: the boundary is a level set of f_1 in every frame, c is tangent to it,
// and no trace of any frame leaves (advect mode retraces the rare RK4 step that jumps across with more
// steps, as CNJ does, integrate/trace_table.hpp). tests/animate/test_animation.cpp checks both.
//
// Domain modes: conformant traces the start sites inside the domain along the bounded field: every
// particle is inside in every frame. drop (the 2023 method) traces along the free field a start set
// that reaches drop_margin lattice spacings beyond the domain, and a particle outside the domain
// is not shown in that frame (a NaN row), so particles pop out (left) and in (entered).
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

#include "dfvn/core/progress.hpp"
#include "dfvn/sampling/curl_noise_jitter.hpp"

namespace dfvn {

// The start lattice: cubic, the cell-centred K^N lattice (i + 1/2) / K; bcc, the body-centred cubic
// (in 3D octahedral) lattice: the cubic one and the cell corners i / K between its points, a copy
// shifted by half a spacing along every axis (K^N + (K-1)^N points in the cube).
enum class StartLattice { cubic, bcc };
StartLattice parse_start_lattice(std::string_view name);  // "cubic" | "bcc"
std::string_view to_string(StartLattice lattice);

// How frame k is made (the comment at the top): cnj, CNJ of the start lattice at alpha_k; advect, frame
// k-1 traced on for one frame time.
enum class AnimationMode { cnj, advect };
AnimationMode parse_animation_mode(std::string_view name);  // "cnj" | "advect"
std::string_view to_string(AnimationMode mode);

struct AnimationOptions {
  AnimationMode mode = AnimationMode::cnj;
  int dimension = 2;
  int grid = 16;  // K: the cubic lattice's points per axis, spacing 1 / K
  StartLattice lattice = StartLattice::cubic;
  int frames = 300;          // F, frame 0 included
  double phase_step = 0.05;  // DA in radians per frame, in [kMinPhaseStep, 2 pi]
  double start_phase = 0.0;  // alpha_0 in radians, any finite real (the frames start from it modulo 2 pi)
  // The frames' phases reach at most pi + 10^5 x 2 pi < 2^20, whose unit in the last place is 2^-32: a step
  // of 2^-30 or more advances every frame's phase (by 4 units or more); a smaller one could leave it.
  static constexpr double kMinPhaseStep = 0x1p-30;
  // The field and the domain: noise, frequency (cycles per lattice spacing), step_scale (t_cnj),
  // domain (cube or ball; the torus has no boundary to animate against), domain_mode, bound,
  // boundary_width. cnj.phase is not used (start_phase is alpha_0).
  CnjOptions cnj = default_cnj();

  static constexpr int kMaxFrames = 100000;
  // frames.npy is held in memory: F x particles x N doubles, at most 2^31 bytes.
  static constexpr double kMaxFrameBytes = 0x1p31;
  // drop: how far beyond the domain the start set reaches, in whole lattice spacings (--drop-margin).
  // Particles enter from there, so the margin must exceed how far a particle wanders over the run: the
  // outer edge of the margin has nothing beyond it to refill it. The cost grows with the margin as
  // ((K + 2 margin) / K)^N (data/figure8_record.md measures the inside count's trend against it).
  int drop_margin = kDefaultDropMargin;
  static constexpr int kDefaultDropMargin = 3;
  static constexpr int kMaxDropMargin = 1000;

  static CnjOptions default_cnj() {
    CnjOptions cnj;
    cnj.domain = DomainKind::cube;
    return cnj;
  }
  void validate() const;  // throws std::invalid_argument naming the option
};

// The start sites: particles x N, row-major, in lattice order (cubic sites, then the bcc centres).
// conformant: the sites inside the domain; drop: the sites within drop_margin spacings of it
// (the cube grown by that margin on every side; for the ball, the sites of that box within the margin
// of the ball).
std::vector<double> animation_start_sites(const AnimationOptions& options);

struct FrameStats {
  int frame = 0;
  double phase = 0.0;              // alpha_k, from alpha_0 modulo 2 pi (reduced_phase)
  std::uint64_t inside = 0;        // particles in the domain in this frame
  std::uint64_t entered = 0;       // outside in frame k-1, inside in frame k (0 in frame 0)
  std::uint64_t left = 0;          // inside in frame k-1, outside in frame k (0 in frame 0)
  double largest_jump = 0.0;       // max |x_k - x_{k-1}| over particles inside in both frames (0 in frame 0)
  double rms_move = 0.0;           // RMS of the same moves
  std::uint64_t retraced = 0;      // advect, conformant: traces of this frame that ended outside and were traced again
  std::uint64_t kept_at_start = 0; // advect, conformant: of those, particles no refinement kept inside (they stay)
  std::uint64_t projected = 0;     // cnj, conformant: trace ends outside, moved to the nearest point of the domain
  // The packing of the particles shown (stats/nearest_neighbour.hpp, in the domain's metric): the smallest,
  // 1% quantile and median nearest-neighbour distance (length units), and the median in mean spacings
  // (measure / inside)^(1/N). NaN when fewer than 2 particles are inside.
  double nn_min = 0.0, nn_q01 = 0.0, nn_median = 0.0, nn_median_scaled = 0.0;
};

// The per-frame moves |x_k - x_{k-1}| over frames 1..F-1 and the particles inside in both frames, in
// units of frame 0's mean spacing (measure / inside)^(1/N): their median, 99th percentile and largest
// (numpy.quantile's linear interpolation). All 0 with fewer than 2 frames.
struct MoveSummary {
  std::uint64_t moves = 0;
  double median = 0.0, p99 = 0.0, largest = 0.0;
};

struct AnimationResult {
  AnimationOptions options;
  std::uint64_t seed = 0;
  std::uint64_t particles = 0;
  double spacing = 0.0;          // 1 / K
  double trace_time = 0.0;       // t_cnj: frame 0's jitter
  double frame_time = 0.0;       // DA t_cnj: how far (RMS) the phase moves a particle per frame, both modes
  int frame_steps = 1;           // RK4 steps M per trace (cnj: CNJ's, each at most t_cnj / M and half the
                                 // transition width long; advect: over DA t_cnj)
  double field_frequency = 0.0;  // cycles per unit length
  // frames x particles x N, row-major; a particle outside the domain in a frame is a row of NaN.
  std::vector<double> positions;
  std::vector<FrameStats> frames;

  const double* frame(int k) const { return positions.data() + static_cast<std::size_t>(k) * particles * options.dimension; }
  MoveSummary moves;

  // Popping events (entered + left) over frames 1..F-1, per 100 frame steps.
  double popping_per_100_frames() const;
  // Frame 0's mean spacing (measure / inside)^(1/N), the unit of MoveSummary.
  double mean_spacing() const;
};

// How stationary the packing is over the frames (FrameStats' nearest-neighbour columns, in each frame's
// mean spacings): frame 0's median and 1% quantile, and every frame's over frame 0's, smallest, mean and
// largest. NaN frames (fewer than 2 particles inside) are skipped.
struct PackingSummary {
  double median_0 = 0.0, q01_0 = 0.0;                          // frame 0, in mean spacings
  double median_min = 0.0, median_mean = 0.0, median_max = 0.0;  // frame k's median / frame 0's
  double q01_min = 0.0, q01_max = 0.0;                          // frame k's 1% quantile / frame 0's
  int median_min_frame = 0, q01_min_frame = 0;
};
PackingSummary summarise_packing(const AnimationResult& result);

// Runs the animation; the result depends on the options and the seed only, never on `threads`.
// `progress` gets the fraction of frames done. Throws std::invalid_argument for bad options.
AnimationResult animate(const AnimationOptions& options, std::uint64_t seed, int threads,
                        const FractionProgress& progress = {});

// The RK4 steps of one frame's trace. cnj: CNJ's step count (cnj_steps). advect: that count scaled by
// the frame's share of the CNJ trace time, ceil(steps DA), at least 1: a frame never takes longer steps
// than CNJ's jitter does.
int animation_frame_steps(const AnimationOptions& options);

// The trace options of cnj mode's frames: CNJ's (cnj_trace_options) with TracePolicy::continuous and
// steps of at most half the bound's transition width.
TraceOptions animation_trace_options(const AnimationOptions& options);

}  // namespace dfvn
