// dfvn-sample reproduce: table1, table2, cnj-study, integration, figure6-10 and constructions (reproduce/).
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "dfvn/core/dimension.hpp"
#include "dfvn/io/atomic_file.hpp"
#include "dfvn/io/markdown_text.hpp"
#include "dfvn/plot/gnuplot.hpp"
#include "dfvn/reproduce/bridson.hpp"
#include "dfvn/reproduce/cnj_study.hpp"
#include "dfvn/reproduce/constructions.hpp"
#include "dfvn/reproduce/figure8.hpp"
#include "dfvn/reproduce/integration.hpp"
#include "dfvn/reproduce/reproduce.hpp"
#include "dfvn/reproduce/surface_figures.hpp"
#include "dfvn/sampling/method.hpp"

#include "options.hpp"

namespace dfvn_cli {
namespace {

constexpr const char* kOutDirHelp = "Output directory (made if missing; its files are listed above)";

struct ReproduceCommand : Subcommand {
  CommonOptions common1, common2, common3, common4, common5, common_constructions;
  dfvn::ConstructionsConfig constructions;
  dfvn::Figure8Config figure8;
  std::string figure8_lattice = "bcc";
  dfvn::IntegrationConfig integration;
  std::string integration_dims = "3-7";
  std::string integration_methods = "cnj,jitter,pds,sobol,random,halton,lhs";
  std::string out1 = "out/table1", out2 = "out/table2";
  std::string dims = "3-7", study_dims = "3-7";
  dfvn::CnjStudyConfig study;
  std::string study_lattice = "interior";
  std::vector<std::string> study_bases = {"simplex", "turning-bands"};
  dfvn::WarpConfig warp{.width = 384, .height = 216};
  dfvn::Table2Config table2;
  std::string setting = "shader";
  double frequency = 0.0, field_magnitude = 0.0;  // 0: the setting's
  CLI::Option* second_width_option = nullptr;
  CLI::Option* height_option = nullptr;
  std::string table1_noise{dfvn::to_string(dfvn::kDefaultNoiseBasis)};
  ProgressOptions progress;
  int table1_realizations = dfvn::Table1Config{}.realizations;
  // figure6, figure7, figure9, figure10 (reproduce/surface_figures.hpp)
  CommonOptions common6, common7, common9, common10;
  dfvn::Figure6Config figure6;
  dfvn::Figure7Config figure7;
  dfvn::Figure9Config figure9, figure10{.ramp_figure = false, .out_dir = "out/figure10"};
  std::string noise6{dfvn::to_string(dfvn::kDefaultNoiseBasis)}, noise7 = noise6, noise9 = noise6, noise10 = noise6;
  // figure9: the paper's surface, a slope along x (its particles move top to bottom) with a hill in the middle;
  // figure10: the plane alone.
  std::vector<double> slope9 = {1.0, 0.0}, slope10 = {1.0, 0.5}, bump9 = {0.6, 0.25};
  // bridson (reproduce/bridson.hpp)
  CommonOptions common_bridson;
  dfvn::BridsonConfig bridson;

  void add_to(CLI::App& parent) {
    CLI::App* cmd = parent.add_subcommand("reproduce", "The paper's tables and figures, and the seed documents', ours beside theirs");
    cmd->require_subcommand(1);
    CLI::App* t1 = cmd->add_subcommand(
        "table1",
        "Table 1 and Figure 4: packing of CNJ, jitter, Poisson disk and Sobol in 3D-7D\n\n"
        "Table 1 and Figure 4: CNJ, jittering, Poisson disk and Sobol point sets in 3D-7D under the paper protocol.\n"
        "Writes DIR/table1.csv (a row a realization), DIR/table1_summary.csv, DIR/rdf.csv, DIR/table1.md and (with\n"
        "gnuplot) DIR/figure4.png; prints table1.md as plain text.");
    t1->add_option("--out", out1, kOutDirHelp)->capture_default_str();
    t1->add_option("--dims", dims, "Dimensions: a range or list within 3..7, e.g. 3-7 or 3,5")->capture_default_str();
    t1->add_option("--realizations", table1_realizations,
                   "Realizations R: independently seeded repeats, seeds s..s+R-1; cells are mean +- sd over them\n"
                   "(each about 100 s for 3D-7D on 2 cores)")
        ->capture_default_str()
        ->check(CLI::Range(1, 1000));
    add_noise_option(*t1, table1_noise);  // the CNJ column; the simplex column is always shown beside it
    progress.add_to(*t1);
    add_common_options(*t1, common1);
    t1->callback([this] { run_table1(); });

    CLI::App* t2 = cmd->add_subcommand(
        "table2",
        "Table 2 and Figure 5: image warping error, Euler and RK4, with and without reprojection\n\n"
        "Table 2 and Figure 5: warp a wave image along 2D DFVN for t = 0.5 with Euler and RK4, 64 and 512 steps, 0, 1\n"
        "and 10 Newton reprojection steps, against 2048 RK4 steps; RMSE from float values at two resolutions; Figure 5's\n"
        "top row at several times t with 1000 RK4 steps. Writes DIR/table2.csv, DIR/table2.md, DIR/timeline.csv, the\n"
        "images as PNG and (with gnuplot) DIR/figure5.png; prints table2.md as plain text.");
    t2->add_option("--out", out2, kOutDirHelp)->capture_default_str();
    t2->add_option("--setting", setting,
                   "shader: the paper's shader (2D quintic gradient noise, noise_scale 7, its unnormalised field\n"
                   "magnitude 7 sigma = 5.049 widths per unit time, t = 0.5, its wave-band image); ours: simplex noise,\n"
                   "3 cycles per width, RMS |c| = 1, sine stripes (the earlier default). The image is one unit wide\n"
                   "(x in [0, 1] across it): per width is per unit length")
        ->capture_default_str()
        ->check(CLI::IsMember({"shader", "ours"}));
    t2->add_option("--width", warp.width, "Image width in pixels; without --height the height keeps the 16:9 aspect")
        ->capture_default_str()
        ->check(CLI::Range(2, 20000));
    height_option = t2->add_option("--height", warp.height, "Image height in pixels")
                        ->capture_default_str()
                        ->check(CLI::Range(2, 20000));
    second_width_option = t2->add_option("--second-width", table2.second_width,
                   "Width of the second resolution (same aspect ratio) at which every RMSE is measured again; 0 = none;\n"
                   "default: half of --width (none when that is below 2 pixels a side)")
        ->check(CLI::Range(0, 20000));
    t2->add_option("--samples", warp.samples, "Samples per pixel, a perfect square (m x m sub-pixel grid, averaged)")
        ->capture_default_str()
        ->check(CLI::IsMember({1, 4, 9, 16, 25, 36, 49, 64}));
    t2->add_option("--frequency", frequency,
                   "Noise frequency F in cycles per unit length (one cycle = 2 pi / k_eff of the basis; the image is\n"
                   "one unit wide, so F cycles across it); default: the setting's (shader: 7 k_eff / (2 pi) = 4.562,\n"
                   "ours: 3)")
        ->check(kNoiseFrequency);
    t2->add_option("--field-magnitude", field_magnitude,
                   "RMS speed of the field in unit lengths (image widths) per unit time, in [1e-6, 1e6]; default: the\n"
                   "setting's\n"
                   "(shader: 5.049, ours: 1)")
        ->check(real_in(1e-6, 1e6));
    progress.add_to(*t2);
    add_common_options(*t2, common2);
    t2->callback([this] { run_table2(); });

    CLI::App* s = cmd->add_subcommand(
        "cnj-study",
        fmt::format(
            "CNJ against jitter at equal RMS displacement over frequency, step and steps\n\n"
            "CNJ (each noise basis) against random jitter over noise frequencies 0.1, 0.2, 0.35, 0.5, 1 cycles per\n"
            "spacing, step scales 0.2, 0.35, 0.5 and 1 or {} integration steps, compared at equal RMS displacement,\n"
            "neighbour disorder and lattice order (--lattice interior: interior points of a K^N lattice, nothing\n"
            "dropped; --lattice paper: Table 1's lattice, points leaving [0,1]^N dropped as the paper does). Writes\n"
            "DIR/cnj_study.csv, DIR/cnj_study_jitter.csv, DIR/cnj_study.md and (with gnuplot) DIR/cnj_study.png;\n"
            "prints the Markdown as plain text.\n"
            "The CNJ defaults come from this study's rule (data/cnj_defaults.md).",
            dfvn::kFreeFieldSteps));
    s->add_option("--out", study.out_dir, kOutDirHelp)->capture_default_str();
    s->add_option("--dims", study_dims, "Dimensions: a range or list within 3..7, e.g. 3-7 or 3,5")->capture_default_str();
    s->add_option("--realizations", study.seeds,
                  "Realizations R per cell: independently seeded repeats, seeds s..s+R-1 (--seed, --seed + 1, ...)")
        ->capture_default_str()
        ->check(CLI::Range(1, 1000));
    s->add_option("--lattice", study_lattice,
                  "Start lattice: interior (the study's cell-centred lattice, statistics over interior sites) or paper (Table 1's "
                  "lattice linspace(0.05, 0.95, K), leaving points dropped)")
        ->capture_default_str()
        ->check(CLI::IsMember({"interior", "paper"}));
    s->add_option("--noises", study_bases, "Comma list of noise bases to study")->delimiter(',')->capture_default_str();
    s->add_option("--cycles-per-spacing", study.frequencies,
                  "Comma list of CNJ noise frequencies C in cycles per lattice spacing (the field's frequency is\n"
                  "C / spacing in cycles per unit length)")
        ->delimiter(',')
        ->capture_default_str();
    s->add_option("--step-scales", study.step_scales, "Comma list of step scales C (t = C dbar(N) spacing)")
        ->delimiter(',')
        ->capture_default_str();
    s->add_option("--steps", study.steps,
                  fmt::format("Comma list of CNJ integration steps M per trace (RK4 steps of t / M, each followed by\n"
                              "the reprojection; Section 5.1 takes 1, the free field's default is {})",
                              dfvn::kFreeFieldSteps))
        ->delimiter(',')
        ->capture_default_str()
        ->check(CLI::Range(1, dfvn::CnjOptions::kMaxSteps));
    progress.add_to(*s);
    add_common_options(*s, common3);
    refuse_options(*s, {{"--seeds", "cnj-study's --seeds is now --realizations R (seeds s..s+R-1), as in every subcommand"},
                        {"--frequencies",
                         "cnj-study takes CNJ's noise frequencies per lattice spacing as --cycles-per-spacing C1,C2,... "
                         "(--frequency means cycles per unit length)"}});
    s->callback([this] { run_cnj_study(); });
    add_integration(cmd);
    add_figure8(cmd);
    add_constructions(cmd);
    add_surface_figures(cmd);
    add_bridson(cmd);
    // After the subcommands, which would otherwise inherit it.
    cmd->footer("Subcommands: table1, table2, cnj-study, integration, figure6, figure7, figure8, figure9,\n"
                "figure10, constructions, bridson; each has --help ('dfvn-sample reproduce table1\n"
                "--help'), and 'dfvn-sample --help-all' prints them all.");
  }

  void add_bridson(CLI::App* cmd) {
    CLI::App* b = cmd->add_subcommand(
        "bridson",
        "Bridson et al. 2007's Figure 2: a wake and a vortex ring, 3D curl noise with its toolbox\n\n"
        "Bridson et al. 2007's Figure 2 with --octaves, --amplitude, --body, --vortex and --viscous: a wake\n"
        "behind a moving sphere and a vortex ring pushing fluid past a sphere before turbulent mixing, 3D curl noise in\n"
        "the unit cube, traced particles drawn from the side; and the checks from the field itself (divergence, c . n on\n"
        "the walls and the sphere, the moving body's normal velocity, no-slip with --viscous, energy per octave). Writes\n"
        "DIR/bridson.md, DIR/bridson_checks.csv, DIR/bridson_octaves.csv, DIR/wake.png, DIR/ring.png, DIR/wake_traces.csv\n"
        "and DIR/ring_traces.csv; prints bridson.md as plain text. The defaults take well under a minute.");
    b->add_option("--out", bridson.out_dir, kOutDirHelp)->capture_default_str();
    b->add_option("--frequency", bridson.frequency, "Noise frequency F of octave 0 in cycles per unit length, at most 64")
        ->capture_default_str()
        ->check(kNoiseFrequency);
    b->add_option("--octaves", bridson.octaves,
                  "Octaves K of the noise (Bridson et al. 2007, Section 2.2), in [1, 10], as field --octaves; 1 is the field\n"
                  "without octaves")
        ->capture_default_str();
    b->add_option("--octave-gain", bridson.octave_gain,
                  "With --octaves: the velocity ratio g from one octave to the next, any finite g > 0; default\n"
                  "Kolmogorov's 2^(-1/3)")
        ->capture_default_str();
    b->add_option("--boundary-width", bridson.boundary_width,
                  "The solids' transition width in length units (octave o: W / 2^o), in (0, 0.07]")
        ->capture_default_str();
    b->add_option("--grid", bridson.grid, "Lattice points per axis K of each scene's start lattice (K x K particles)")
        ->capture_default_str();
    b->add_option("--trace-steps", bridson.steps, "RK4 steps per particle trace (no reprojection: curl noise has none)")
        ->capture_default_str();
    b->add_option("--image", bridson.image, "Side of the PNG in pixels")->capture_default_str();
    b->add_option("--check-points", bridson.check_points,
                  "Random points of each divergence check and of each checked surface (the octaves' energies: 4x)")
        ->capture_default_str();
    progress.add_to(*b);
    add_common_options(*b, common_bridson);
    b->callback([this] { run_bridson(); });
  }

  void run_bridson() {
    bridson.seed = common_bridson.seed;
    bridson.threads = common_bridson.threads;
    bridson.validate();
    dfvn::check_figure_prerequisites();  // before the output folder is made
    dfvn::check_outputs(files_in(bridson.out_dir, dfvn::bridson_output_files()), {bridson.out_dir});
    dfvn::ProgressReporter* reporter = progress.make(dfvn::bridson_stage_weights(bridson));
    const auto result = dfvn::run_bridson(bridson, reporter->callback());
    reporter->complete();
    std::fputs(dfvn::markdown_as_plain_text(dfvn::write_bridson(result, log)).c_str(), stdout);
  }

  void run_cnj_study() {
    study.dimensions = dfvn::parse_dimension_list(study_dims);
    study.lattice = dfvn::parse_study_lattice(study_lattice);
    study.bases.clear();
    for (const std::string& name : study_bases) study.bases.push_back(dfvn::parse_noise_basis(name));
    study.seed = common3.seed;
    study.threads = common3.threads;
    study.validate();
    dfvn::check_figure_prerequisites();  // before the output folder is made
    dfvn::check_outputs(files_in(study.out_dir, dfvn::cnj_study_output_files()), {study.out_dir});
    dfvn::ProgressReporter* reporter = progress.make(dfvn::cnj_study_stage_weights(study));
    const auto result = dfvn::run_cnj_study(study, reporter->callback());
    reporter->complete();
    std::fputs(dfvn::markdown_as_plain_text(dfvn::write_cnj_study(result, log)).c_str(), stdout);
  }

  void add_integration(CLI::App* cmd) {
    CLI::App* t3 = cmd->add_subcommand(
        "integration",
        "Integration error of every method on Genz's six families, 3D-7D\n\n"
        "Section 6.1's open question: integrate Genz's six test families with every method's point sets in 3D-7D, at\n"
        "several sizes, over R realizations. Writes DIR/integration.csv, DIR/integration_slopes.csv, DIR/integration.md\n"
        "(tables and a reading) and (with gnuplot) DIR/integration_<N>d.png; prints integration.md as plain text.");
    t3->add_option("--out", integration.out_dir, kOutDirHelp)->capture_default_str();
    t3->add_option("--dims", integration_dims, "Dimensions: a range or list within 3..7")->capture_default_str();
    t3->add_option("--realizations", integration.realizations,
                   "Realizations R: independently seeded repeats, seeds s..s+R-1; at least 16 for the reading")
        ->capture_default_str()
        ->check(CLI::Range(2, 100000));
    t3->add_option("--max-points", integration.max_points, "Largest lattice K^N per dimension")
        ->capture_default_str()
        ->check(CLI::Range(64, 1 << 24));
    t3->add_option("--methods", integration_methods, "Comma list of methods, of " + dfvn::method_names())
        ->capture_default_str();
    progress.add_to(*t3);
    add_common_options(*t3, common4);
    t3->callback([this] { run_integration(); });
  }

  void run_integration() {
    integration.dimensions = dfvn::parse_dimension_list(integration_dims);
    integration.seed = common4.seed;
    integration.threads = common4.threads;
    integration.methods.clear();
    for (const auto& name : CLI::detail::split(integration_methods, ','))
      integration.methods.push_back(dfvn::parse_method(CLI::detail::trim_copy(name)));
    integration.validate();
    dfvn::check_figure_prerequisites();  // before the output folder is made
    dfvn::check_outputs(files_in(integration.out_dir, dfvn::integration_output_files(integration)), {integration.out_dir});
    dfvn::ProgressReporter* reporter = progress.make(dfvn::integration_stage_weights(integration));
    const auto result = dfvn::run_integration(integration, reporter->callback());
    reporter->complete();
    std::fputs(dfvn::markdown_as_plain_text(dfvn::write_integration(result, log)).c_str(), stdout);
  }

  void add_figure8(CLI::App* cmd) {
    CLI::App* f = cmd->add_subcommand(
        "figure8",
        "Figure 8: animated CNJ, drop mode against the conformant field\n\n"
        "Figure 8 (Section 5.4): curl noise jittering animated over F frames in the unit square and cube, drop mode\n"
        "(the 2023 method: the free field, particles pop in and out of the domain) against the conformant field\n"
        "(Eq. 13: every particle stays inside), as 'dfvn-sample animate' runs them. Writes DIR/figure8_frames.csv\n"
        "(animate's frames.csv per dimension and mode), DIR/figure8_tracks.csv (2D tracks near the boundary),\n"
        "DIR/figure8.md (popping events per 100 frames, count ranges) and (with gnuplot) DIR/figure8.png; prints\n"
        "figure8.md as plain text.");
    f->add_option("--out", figure8.out_dir, kOutDirHelp)->capture_default_str();
    f->add_option("--frames", figure8.frames,
                  fmt::format("Frames F, frame 0 included, in [2, {}]", dfvn::AnimationOptions::kMaxFrames))
        ->capture_default_str();
    f->add_option("--phase-step", figure8.phase_step,
                  "Phase step DA in radians per frame, in [2^-30, 2 pi]: the field turns by DA per frame, and a frame\n"
                  "lasts DA times the CNJ trace time")
        ->capture_default_str();
    f->add_option("--grid-2d", figure8.grid_2d, "2D: lattice points per axis K of the cubic start lattice")
        ->capture_default_str()
        ->check(CLI::Range(2, 4096));
    f->add_option("--grid-3d", figure8.grid_3d, "3D: lattice points per axis K of the start lattice")
        ->capture_default_str()
        ->check(CLI::Range(2, 256));
    f->add_option("--lattice-3d", figure8_lattice,
                  "3D start lattice: bcc (the paper's octahedral lattice, K^3 + (K-1)^3 points) or cubic")
        ->capture_default_str()
        ->check(CLI::IsMember({"cubic", "bcc"}));
    f->add_option("--drop-margin", figure8.drop_margin,
                  "Drop mode: how far the start set reaches beyond the domain, in whole lattice spacings (particles\n"
                  "enter from there; the cost grows as ((K + 2 margin) / K)^N)")
        ->capture_default_str()
        ->check(CLI::Range(0, dfvn::AnimationOptions::kMaxDropMargin));
    progress.add_to(*f);
    add_common_options(*f, common5);
    f->callback([this] { run_figure8(); });
  }

  void run_figure8() {
    figure8.lattice_3d = dfvn::parse_start_lattice(figure8_lattice);
    figure8.seed = common5.seed;
    figure8.threads = common5.threads;
    figure8.validate();
    dfvn::check_figure_prerequisites();  // before the output folder is made
    dfvn::check_outputs(files_in(figure8.out_dir, dfvn::figure8_output_files()), {figure8.out_dir});
    dfvn::ProgressReporter* reporter = progress.make(dfvn::figure8_stage_weights(figure8));
    const auto result = dfvn::run_figure8(figure8, reporter->callback());
    reporter->complete();
    std::fputs(dfvn::markdown_as_plain_text(dfvn::write_figure8(result, log)).c_str(), stdout);
  }

  void add_constructions(CLI::App* cmd) {
    CLI::App* c = cmd->add_subcommand(
        "constructions",
        "Curl, bitangent and DFVN noise side by side: divergence, speed, tracing error\n\n"
        "The divergence-free constructions side by side in 2D and 3D on every noise basis at one frequency:\n"
        "curl noise (Bridson et al. 2007; no reprojection exists for it), bitangent noise (the 3D cross\n"
        "product of simplex gradients, fused 'simplex' and separate 'simplex-separate') and DFVN. Per field: |div c|/|Dc|\n"
        "on uniform random points, ns per evaluation, RMS |c| and its quantiles, the end-point RMSE of Euler and RK4 with\n"
        "64 and 512 steps against 2048 RK4 steps (with and without Gauss-Newton reprojection where it exists), and the\n"
        "escape fraction from the cube and into a sphere obstacle (Bridson's ramp). Writes DIR/constructions.csv,\n"
        "DIR/constructions.md (tables and a reading, with the verdict on the claim that reprojected DFVN beats curl\n"
        "noise at equal steps), DIR/curl_obstacle.csv and (with gnuplot) DIR/curl_obstacle.png (Bridson's Figure 1:\n"
        "streamlines around a disc); prints constructions.md as plain text. The defaults take well under a minute.");
    c->add_option("--out", constructions.out_dir, kOutDirHelp)->capture_default_str();
    c->add_option("--frequency", constructions.frequency, "Noise frequency F of every field in cycles per unit length")
        ->capture_default_str()
        ->check(kNoiseFrequency);
    c->add_option("--trace-time", constructions.trace_time,
                  "Trace time t of every trace (accuracy and escapes), in (0, 100] (RMS |c| = 1: unit lengths)")
        ->capture_default_str()
        ->check(real_in(1e-12, 100.0));
    c->add_option("--divergence-points", constructions.divergence_points,
                  "Uniform random points per field for |div c|/|Dc| (the targets are stated for 100000)")
        ->capture_default_str()
        ->check(CLI::Range(100, 100000000));
    c->add_option("--speed-points", constructions.speed_points,
                  "Uniform random points per field for ns per evaluation and the |c| quantiles (one thread)")
        ->capture_default_str()
        ->check(CLI::Range(100, 100000000));
    c->add_option("--trace-starts", constructions.trace_starts,
                  "Uniform starts in [0,1]^N per field for the end-point RMSE (each also traced with 2048 RK4 steps)")
        ->capture_default_str()
        ->check(CLI::Range(1, 10000000));
    c->add_option("--escape-starts", constructions.escape_starts,
                  "Uniform starts in the cube outside the obstacle, per field and 64-step variant, for the escape fractions")
        ->capture_default_str()
        ->check(CLI::Range(1, 10000000));
    progress.add_to(*c);
    add_common_options(*c, common_constructions);
    c->callback([this] { run_constructions(); });
  }

  void run_constructions() {
    constructions.seed = common_constructions.seed;
    constructions.threads = common_constructions.threads;
    constructions.validate();
    dfvn::check_figure_prerequisites();  // before the output folder is made
    dfvn::check_outputs(files_in(constructions.out_dir, dfvn::constructions_output_files()), {constructions.out_dir});
    dfvn::ProgressReporter* reporter = progress.make(dfvn::constructions_stage_weights(constructions));
    const auto result = dfvn::run_constructions(constructions, reporter->callback());
    reporter->complete();
    std::fputs(dfvn::markdown_as_plain_text(dfvn::write_constructions(result, log)).c_str(), stdout);
  }

  void add_surface_figures(CLI::App* cmd) {
    CLI::App* f6 = cmd->add_subcommand(
        "figure6",
        "Figure 6: a texture on the sphere warped with and without projection\n\n"
        "Figure 6 (Section 5.3): a texture on the unit sphere warped along the 3D field tangent to the sphere (f_1 = |x|^2\n"
        "up to a constant): RK4 at 32 and 128 steps, without and with projection (Gauss-Newton reprojection), against\n"
        "2048 RK4 steps. Writes DIR/figure6.csv (RMSE and the drift of |x| from 1 per setting), DIR/figure6.md, and\n"
        "DIR/source.png, DIR/reference.png, DIR/rk4-<steps>[-projected].png (equirectangular maps); prints figure6.md\n"
        "as plain text.");
    f6->add_option("--out", figure6.out_dir, kOutDirHelp)->capture_default_str();
    f6->add_option("--width", figure6.width, "Image width in pixels of the equirectangular map (even; its height is half)")
        ->capture_default_str();
    f6->add_option("--trace-time", figure6.time, "Trace time t of every pixel, in (0, 100] (RMS |c| = 1: unit lengths)")
        ->capture_default_str();
    f6->add_option("--frequency", figure6.frequency, "Noise frequency F in cycles per unit length (the sphere's radius is 1)")
        ->capture_default_str()
        ->check(kNoiseFrequency);
    add_noise_option(*f6, noise6);
    progress.add_to(*f6);
    add_common_options(*f6, common6);
    f6->callback([this] { run_figure6(); });

    CLI::App* f7 = cmd->add_subcommand(
        "figure7",
        "Figure 7: a pattern warped inside a disc and a ball that no trace leaves\n\n"
        "Figure 7 (Section 5.4): a ring pattern in the unit square warped along 2D DFVN bounded by the disc of radius 1/2\n"
        "(Eq. 13), its 3D half (the ball of radius 1/2, central slices) and the paper's own construction beside Eq. 13.\n"
        "Writes DIR/figure7.csv (the samples that leave the disc, the change outside it), DIR/figure7_profile.csv (the\n"
        "radial profile), DIR/figure7.md, DIR/source.png, DIR/warped.png, DIR/warped_paper.png, DIR/slices_3d.png and\n"
        "DIR/figure7_constructions_3d.csv; prints figure7.md as plain text.");
    f7->add_option("--out", figure7.out_dir, kOutDirHelp)->capture_default_str();
    f7->add_option("--width", figure7.width, "Image width in pixels of the unit square (square image)")->capture_default_str();
    f7->add_option("--trace-time", figure7.time, "Trace time t of every pixel, in (0, 100] (RMS |c| = 1: unit lengths)")
        ->capture_default_str();
    f7->add_option("--rk4-steps", figure7.steps, "RK4 steps per trace, each followed by Gauss-Newton reprojection")
        ->capture_default_str();
    f7->add_option("--frequency", figure7.frequency, "Noise frequency F in cycles per unit length")
        ->capture_default_str()
        ->check(kNoiseFrequency);
    f7->add_option("--boundary-width", figure7.transition_width,
                   "Eq. 13's transition width in length units, in (0, 0.25] (the disc's radius is 0.5)")
        ->capture_default_str();
    f7->add_option("--rings", figure7.rings, "Rings of the pattern 0.5 + 0.5 cos(2 pi K r / 0.5) inside the disc")
        ->capture_default_str();
    f7->add_option("--bins", figure7.bins, "Radial profile bins over r in [0, sqrt(2)/2]")->capture_default_str();
    f7->add_option("--width-3d", figure7.width3d,
                   "The 3D half: each central slice of the unit cube (through the ball) in pixels, square")
        ->capture_default_str();
    add_noise_option(*f7, noise7);
    progress.add_to(*f7);
    add_common_options(*f7, common7);
    f7->callback([this] { run_figure7(); });

    add_slope_figure(cmd, figure9, slope9, noise9, common9);
    add_slope_figure(cmd, figure10, slope10, noise10, common10);
  }

  void add_slope_figure(CLI::App* cmd, dfvn::Figure9Config& config, std::vector<double>& slope, std::string& noise,
                        CommonOptions& common) {
    const bool ramp = config.ramp_figure;
    CLI::App* f = cmd->add_subcommand(
        config.name(),
        fmt::format("{}: particles traced over a lifted slope{}\n\n"
                    "{} (Section 5.5): particle traces over the sloped surface h = SX x + SY y (the 2D field lifted onto\n"
                    "it, --lift plane:SX,SY; figure9 with a hill in the middle, --bump), {} the vertical ramp (--lift-ramp);\n"
                    "the displacement covariance's\n"
                    "principal direction against the slope direction. Writes DIR/{}.csv, DIR/{}_traces.csv, DIR/{}.md and\n"
                    "DIR/{}.png; prints {}.md as plain text.",
                    ramp ? "Figure 9" : "Figure 10", ramp ? " with a hill and the vertical ramp" : " without the ramp",
                    ramp ? "Figure 9" : "Figure 10", ramp ? "with" : "without", config.name(), config.name(),
                    config.name(), config.name(), config.name()));
    f->add_option("--out", config.out_dir, kOutDirHelp)->capture_default_str();
    f->add_option("--slope", slope, "Slope SX,SY of the plane h = SX x + SY y (length units per length unit; not 0,0)")
        ->delimiter(',')
        ->expected(2)
        ->capture_default_str();
    if (ramp)
      f->add_option("--lift-ramp", config.ramp,
                    "BETA of --lift-ramp (sample, field; README calls it the vertical ramp of the paper's Figure 9):\n"
                    "F(x, z) + BETA z adds BETA perp(grad h) to c, in RMS-speed units")
          ->capture_default_str()
          ->type_name("BETA");
    if (ramp)
      f->add_option("--bump", bump9,
                    "The hill H,R on the slope, the paper's surface with its central vortex: h = SX x + SY y +\n"
                    "H (1 - r^2 / R^2)^3 within R of the square's centre (--lift bump:H,R,0.5,0.5,SX,SY); H = 0: the\n"
                    "plane alone")
          ->delimiter(',')
          ->expected(2)
          ->capture_default_str();
    f->add_option("--grid", config.grid, "Lattice points per axis K of the start lattice (cell centres of the unit square)")
        ->capture_default_str();
    f->add_option("--trace-time", config.time, "Trace time t of every particle, in (0, 100] (RMS |c| = 1: unit lengths)")
        ->capture_default_str();
    f->add_option("--rk4-steps", config.steps,
                  "RK4 steps per trace, each followed by Gauss-Newton reprojection (a multiple of --segments)")
        ->capture_default_str();
    f->add_option("--segments", config.segments, "Trace points drawn and written after the start")->capture_default_str();
    f->add_option("--frequency", config.frequency, "Noise frequency F in cycles per unit length")
        ->capture_default_str()
        ->check(kNoiseFrequency);
    f->add_option("--image", config.image, "Side of the PNG in pixels")->capture_default_str();
    add_noise_option(*f, noise);
    progress.add_to(*f);
    add_common_options(*f, common);
    f->callback([this, &config, &slope, &noise, &common] { run_slope_figure(config, slope, noise, common); });
  }

  void run_figure6() {
    figure6.noise = dfvn::parse_noise_basis(noise6);
    figure6.seed = common6.seed;
    figure6.threads = common6.threads;
    figure6.validate();
    dfvn::check_figure_prerequisites();  // before the output folder is made
    dfvn::check_outputs(files_in(figure6.out_dir, dfvn::figure6_output_files(figure6)), {figure6.out_dir});
    dfvn::ProgressReporter* reporter = progress.make(dfvn::figure6_stage_weights(figure6));
    const auto result = dfvn::run_figure6(figure6, reporter->callback());
    reporter->complete();
    std::fputs(dfvn::markdown_as_plain_text(dfvn::write_figure6(result, log)).c_str(), stdout);
  }

  void run_figure7() {
    figure7.noise = dfvn::parse_noise_basis(noise7);
    figure7.seed = common7.seed;
    figure7.threads = common7.threads;
    figure7.validate();
    dfvn::check_figure_prerequisites();  // before the output folder is made
    dfvn::check_outputs(files_in(figure7.out_dir, dfvn::figure7_output_files()), {figure7.out_dir});
    dfvn::ProgressReporter* reporter = progress.make(1);
    const dfvn::StageProgress stage = reporter->callback();
    const auto result = dfvn::run_figure7(figure7, [&](double f) { if (stage) stage("figure7", f); });
    reporter->complete();
    std::fputs(dfvn::markdown_as_plain_text(dfvn::write_figure7(result, log)).c_str(), stdout);
  }

  void run_slope_figure(dfvn::Figure9Config& config, const std::vector<double>& slope, const std::string& noise,
                        const CommonOptions& common) {
    config.slope_x = slope.at(0);
    config.slope_y = slope.at(1);
    if (config.ramp_figure) config.bump_height = bump9.at(0), config.bump_radius = bump9.at(1);
    config.noise = dfvn::parse_noise_basis(noise);
    config.seed = common.seed;
    config.threads = common.threads;
    config.validate();
    dfvn::check_figure_prerequisites();  // before the output folder is made
    dfvn::check_outputs(files_in(config.out_dir, dfvn::figure9_output_files(config)), {config.out_dir});
    dfvn::ProgressReporter* reporter = progress.make(1);
    const dfvn::StageProgress stage = reporter->callback();
    const std::string name = config.name();
    const auto result = dfvn::run_figure9(config, [&](double f) { if (stage) stage(name, f); });
    reporter->complete();
    std::fputs(dfvn::markdown_as_plain_text(dfvn::write_figure9(result, log)).c_str(), stdout);
  }

  static void log(const std::string& line) { std::fprintf(stderr, "%s: %s\n", kProgram, line.c_str()); }

  void run_table1() {
    dfvn::Table1Config config;
    config.dimensions = dfvn::parse_dimension_list(dims);
    config.cnj.noise = dfvn::parse_noise_basis(table1_noise);
    config.seed = common1.seed;
    config.threads = common1.threads;
    config.out_dir = out1;
    config.realizations = table1_realizations;
    config.validate();
    dfvn::check_figure_prerequisites();  // before the output folder is made
    dfvn::check_outputs(files_in(out1, dfvn::table1_output_files()), {out1});
    dfvn::ProgressReporter* reporter = progress.make(dfvn::table1_stage_weights(config));
    const auto result = dfvn::run_table1(config, reporter->callback());
    reporter->complete();
    std::fputs(dfvn::markdown_as_plain_text(dfvn::write_table1(config, result, log)).c_str(), stdout);
  }

  void run_table2() {
    table2.setting = dfvn::parse_warp_setting(setting);
    dfvn::WarpConfig& config = table2.warp;
    config = dfvn::warp_config(table2.setting);
    config.width = warp.width;
    // --width alone keeps the default image's aspect (384 x 216), rounded to whole pixels, at least 2.
    const dfvn::WarpConfig default_size;
    config.height = height_option->count() > 0
                        ? warp.height
                        : std::max(2, static_cast<int>(std::lround(static_cast<double>(warp.width) * default_size.height /
                                                                    default_size.width)));
    config.samples = warp.samples;
    if (frequency > 0.0) config.frequency = frequency;
    if (field_magnitude > 0.0) config.field_magnitude = field_magnitude;
    if (second_width_option->count() == 0) {
      const int half = config.width / 2;
      table2.second_width = (half >= 2 && static_cast<long long>(half) * config.height / config.width >= 2) ? half : 0;
    }
    config.seed = common2.seed;
    config.threads = common2.threads;
    table2.validate();
    dfvn::check_figure_prerequisites();  // before the output folder is made
    dfvn::check_outputs(files_in(out2, dfvn::table2_output_files(table2)), {out2});
    dfvn::ProgressReporter* reporter = progress.make(dfvn::table2_stage_weights(table2));
    const auto result = dfvn::run_table2(table2, reporter->callback());
    reporter->complete();
    std::fputs(dfvn::markdown_as_plain_text(dfvn::write_table2(out2, result, log)).c_str(), stdout);
  }
};

}  // namespace

std::unique_ptr<Subcommand> add_reproduce_command(CLI::App& app) { return registered<ReproduceCommand>(app); }

}  // namespace dfvn_cli
