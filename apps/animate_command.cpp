// dfvn-sample animate: curl noise jittering animated as the field's phase turns (animate/).
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <cstdio>
#include <string>

#include "dfvn/animate/animation.hpp"
#include "dfvn/animate/animation_files.hpp"
#include "dfvn/io/atomic_file.hpp"
#include "dfvn/plot/gnuplot.hpp"

#include "options.hpp"

namespace dfvn_cli {
namespace {

struct AnimateCommand : Subcommand {
  CommonOptions common;
  dfvn::AnimationOptions options;
  std::string mode = "cnj", lattice = "cubic", noise{dfvn::to_string(dfvn::kDefaultNoiseBasis)};
  SteerOptions steer;
  std::string domain = "cube", domain_mode = "conformant", bound = "eq13";
  std::string out = "out/animate";
  ProgressOptions progress;

  void add_to(CLI::App& parent) {
    CLI::App* cmd = parent.add_subcommand(
        "animate",
        "CNJ animated as the field's phase turns: frames, their counts, a strip figure\n\n"
        "Curl noise jittering animated (the paper's Section 5.4): the field's phase turns by DA per frame,\n"
        "alpha_k = alpha_0 + k DA (rotating gradients). --mode cnj: frame k is CNJ's jitter of the start lattice\n"
        "at phase alpha_k, so every frame packs as CNJ does; --mode advect: frame k is frame k-1 traced on for\n"
        "one frame time. One radian of phase is one CNJ trace time t, so every move shrinks with DA.\n"
        "conformant: the field bounded by the domain keeps every particle inside; drop (the 2023 method): the\n"
        "free field, particles outside are not shown and pop in and out. Writes DIR/frames.npy (F x particles\n"
        "x N, NaN rows for particles outside), DIR/frames.csv (per frame: inside, entered, left, largest jump,\n"
        "RMS move, retraced, kept at start, projected, and the packing nn_min, nn_q01, nn_median,\n"
        "nn_median_scaled) and, in 2D and 3D, DIR/trails.csv and (with gnuplot) DIR/animation.png, a strip of\n"
        "frames with short trails.");
    cmd->add_option("--mode", mode,
                    "cnj: frame k is CNJ of the start lattice at phase alpha_k (a trace map continuous in alpha);\n"
                    "advect: frame k-1 traced on along the field at alpha_k, which mixes the lattice towards\n"
                    "uniform random points (2D 16^2: the median nearest-neighbour distance falls from 0.93 to 0.54\n"
                    "mean spacings in 200 frames; uniform random points have 0.48)")
        ->capture_default_str()
        ->check(CLI::IsMember({"cnj", "advect"}));
    add_dimension_option(*cmd, options.dimension, "Dimension N (2..8)")->capture_default_str();
    cmd->add_option("--grid", options.grid,
                    "Lattice points per axis K (>= 2); K^N points: the cell-centred lattice (i + 1/2) / K, spacing 1 / K")
        ->capture_default_str()
        ->check(CLI::Range(2, 1 << 20));
    cmd->add_option("--lattice", lattice,
                    "Start lattice: cubic (the K^N lattice) or bcc (body-centred cubic, in 3D the paper's octahedral\n"
                    "lattice: the cubic one and the (K-1)^N cell corners between its points)")
        ->capture_default_str()
        ->check(CLI::IsMember({"cubic", "bcc"}));
    cmd->add_option("--frames", options.frames,
                    fmt::format("Frames F, frame 0 included, in [1, {}]; frames.npy (F x particles x N doubles) may\n"
                                "take at most 2 GiB",
                                dfvn::AnimationOptions::kMaxFrames))
        ->capture_default_str();
    cmd->add_option("--phase-step", options.phase_step,
                    "Phase step DA in radians per frame, in [2^-30, 2 pi]: the field turns by DA per frame, and a frame\n"
                    "lasts DA times the CNJ trace time")
        ->capture_default_str();
    add_phase_option(*cmd, options.start_phase);
    cmd->add_option("--domain", domain,
                    "Where the particles live: cube ([0,1]^N) or ball (its inscribed ball; the lattice clipped to it);\n"
                    "the torus ([0,1)^N, no boundary) is not offered: nothing could leave it")
        ->capture_default_str()
        ->check(CLI::IsMember({"cube", "ball"}));
    cmd->add_option("--domain-mode", domain_mode,
                    "conformant: CNJ along the field bounded by the domain (Eq. 13), no point leaves; drop: the\n"
                    "free field, points that leave are dropped (the 2023 method: the start set reaches --drop-margin\n"
                    "spacings beyond the domain, and particles outside are NaN rows in that frame)")
        ->capture_default_str()
        ->check(CLI::IsMember({"conformant", "drop"}));
    cmd->add_option("--drop-margin", options.drop_margin,
                    "Drop mode: how far the start set reaches beyond the domain, in whole lattice spacings (particles\n"
                    "enter from there; the cost grows as ((K + 2 margin) / K)^N)")
        ->capture_default_str()
        ->check(CLI::Range(0, dfvn::AnimationOptions::kMaxDropMargin));
    cmd->add_option("--bound", bound,
                    "How the field meets the boundary of --domain cube or ball (conformant): eq13 (the paper's Eq. 13)\n"
                    "or ramp (Bridson et al. 2007's ramp of the noise)")
        ->capture_default_str()
        ->check(CLI::IsMember({"eq13", "ramp"}));
    cmd->add_option("--boundary-spacings", options.cnj.boundary_width,
                    "The bound's transition width in lattice spacings (Eq. 13's alpha goes from 0 to 1 over it, the\n"
                    "ramp's d0), at most a quarter of the cube's side")
        ->capture_default_str()
        ->check(kPositiveFinite);
    add_noise_option(*cmd, noise, true);
    steer.add_to(*cmd);
    cmd->add_option("--cycles-per-spacing", options.cnj.frequency,
                    "CNJ noise frequency C in cycles per lattice spacing (one cycle = 2 pi / k_eff of the basis); the\n"
                    "field's frequency, C / spacing in cycles per unit length, must be in [2^-50, 2^50]")
        ->capture_default_str()
        ->check(kNoiseFrequency);
    cmd->add_option("--step-scale", options.cnj.step_scale,
                    "CNJ trace time t = C * dbar(N) * lattice spacing, dbar the mean distance to the 3^N-1 lattice\n"
                    "neighbours (Section 5.1): frame 0's jitter; a frame lasts DA t; at most 2^20")
        ->capture_default_str()
        ->check(kStepScale);
    cmd->add_option("--out", out, "Output directory (made if missing; its files are listed above)")->capture_default_str();
    progress.add_to(*cmd);
    add_common_options(*cmd, common);
    cmd->callback([this] { run(); });
  }

  static void log(const std::string& line) { std::fprintf(stderr, "%s: %s\n", kProgram, line.c_str()); }

  void run() {
    options.mode = dfvn::parse_animation_mode(mode);
    options.lattice = dfvn::parse_start_lattice(lattice);
    options.cnj.noise = dfvn::parse_noise_basis(noise);
    options.cnj.transform.steer = steer.spec(noise, options.dimension);
    options.cnj.domain = dfvn::parse_domain_kind(domain);
    options.cnj.domain_mode = dfvn::parse_domain_mode(domain_mode);
    options.cnj.bound = dfvn::parse_bound(bound);
    options.validate();
    if (options.dimension <= 3) dfvn::check_figure_prerequisites();  // before the output folder is made
    dfvn::check_outputs(files_in(out, dfvn::animation_output_files(options)), {out});
    dfvn::ProgressReporter* reporter = progress.make(1);
    const auto progress_callback = reporter->callback();
    const dfvn::AnimationResult result =
        dfvn::animate(options, common.seed, common.threads, [&](double f) { if (progress_callback) progress_callback("frames", f); });
    reporter->complete();
    dfvn::write_animation(out, result, log);
    std::fputs(dfvn::animation_summary(result).c_str(), stdout);
  }
};

}  // namespace

std::unique_ptr<Subcommand> add_animate_command(CLI::App& app) { return registered<AnimateCommand>(app); }

}  // namespace dfvn_cli
