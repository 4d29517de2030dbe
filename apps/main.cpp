// dfvn-sample: the command line. It parses arguments, validates them and calls the library.
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <new>
#include <optional>
#include <string>
#include <unistd.h>
#include <vector>

#include "core/dimension.hpp"
#include "field/diagnose.hpp"
#include "core/message_text.hpp"
#include "core/parallel.hpp"
#include "core/progress.hpp"
#include "core/repeats.hpp"
#include "core/seeds.hpp"
#include "field/evaluate_points.hpp"
#include "io/atomic_file.hpp"
#include "io/csv.hpp"
#include "io/field_csv.hpp"
#include "experiment/json_report.hpp"
#include "io/markdown_text.hpp"
#include "io/point_file.hpp"
#include "reproduce/cnj_study.hpp"
#include "noise/noise_domain.hpp"
#include "plot/gnuplot.hpp"
#include "io/point_reader.hpp"
#include "reproduce/integration.hpp"
#include "reproduce/reproduce.hpp"
#include "experiment/experiment.hpp"
#include "stats/distance_scale.hpp"
#include "stats/point_set_statistics.hpp"
#include "experiment/realizations.hpp"
#include "stats/spectrum.hpp"

namespace {

constexpr const char* kProgram = "dfvn-sample";

// Every error is one line on stderr: escape_bytes turns any newline or control byte left in the
// message into a visible escape, so nothing reaches the terminal raw.
[[noreturn]] void fail(const std::string& message, int code = 1) {
  const std::string line = dfvn::escape_bytes(message, false);
  std::fprintf(stderr, "%s: error: %s\n", kProgram, line.c_str());
  std::exit(code);
}

// A finite number above (or, with `or_equal`, at least) `bound`. CLI11's PositiveNumber would print
// its whole range, DBL_MAX included, and accepts no NaN check.
CLI::Validator finite_number(double bound, bool or_equal, const std::string& name) {
  const std::string wanted = std::string("a finite number ") + (or_equal ? ">= " : "> ") + fmt::format("{:g}", bound);
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        double value = 0.0;
        const bool ok = CLI::detail::lexical_cast(text, value) && std::isfinite(value) &&
                        (or_equal ? value >= bound : value > bound);
        return ok ? std::string() : "must be " + wanted + ", got " + dfvn::quote_for_message(text);
      },
      name);
}
const CLI::Validator kPositiveFinite = finite_number(0.0, false, "POSITIVE");
const CLI::Validator kNonNegativeFinite = finite_number(0.0, true, "NONNEGATIVE");

// A noise frequency in the supported range (noise/noise_domain.hpp); a subnormal one gave Inf.
const CLI::Validator kNoiseFrequency(
    [](std::string& text) -> std::string {
      double value = 0.0;
      if (CLI::detail::lexical_cast(text, value) && value >= dfvn::kMinNoiseFrequency && value <= dfvn::kMaxNoiseFrequency)
        return {};
      return fmt::format("must be a number in [2^-50, 2^50] = [{:g}, {:g}], got {}", dfvn::kMinNoiseFrequency,
                         dfvn::kMaxNoiseFrequency, dfvn::quote_for_message(text));
    },
    "FREQUENCY");

// stats --domain-side: a finite side in [2^-1000, 2^1000] (stats/distance_scale.hpp says why).
const CLI::Validator kDomainSide(
    [](std::string& text) -> std::string {
      double value = 0.0;
      if (!CLI::detail::lexical_cast(text, value)) return "must be a number, got " + dfvn::quote_for_message(text);
      try {
        dfvn::check_domain_side(value, "the side");
      } catch (const std::invalid_argument& e) {
        return e.what();
      }
      return {};
    },
    "SIDE");

// CNJ's step scale: (0, 2^20] (sampling/curl_noise_jitter.hpp says why).
const CLI::Validator kStepScale(
    [](std::string& text) -> std::string {
      double value = 0.0;
      if (CLI::detail::lexical_cast(text, value) && value > 0.0 && value <= dfvn::CnjOptions::kMaxStepScale) return {};
      return "must be a number in (0, 2^20] = (0, 1048576], got " + dfvn::quote_for_message(text);
    },
    "POSITIVE");

// Digits only, read exactly: CLI11 would take "-1" and "18446744073709551616" as 2^64 - 1 and "" as 0.
bool read_unsigned(const std::string& text, std::uint64_t& value) {
  const char* end = text.data() + text.size();
  const auto [ptr, error] = std::from_chars(text.data(), end, value);
  return !text.empty() && text.find_first_not_of("0123456789") == std::string::npos && error == std::errc() &&
         ptr == end;
}

const CLI::Validator kUnsignedInteger(
    [](std::string& text) -> std::string {
      std::uint64_t value = 0;
      return read_unsigned(text, value) ? std::string()
                                        : "must be an integer in 0..18446744073709551615 (2^64 - 1), got " +
                                              dfvn::quote_for_message(text);
    },
    "UINT64");

// --threads: 0 (all cores) or 1..max_thread_count() (core/parallel.hpp).
const CLI::Validator kThreadCount(
    [](std::string& text) -> std::string {
      std::uint64_t value = 0;
      if (read_unsigned(text, value) && value <= static_cast<std::uint64_t>(dfvn::max_thread_count())) return {};
      return fmt::format("must be 0 (all cores) or 1..{} (4 x the {} cores, at most {}), got {}",
                         dfvn::max_thread_count(), dfvn::core_count(), dfvn::kMaxThreads, dfvn::quote_for_message(text));
    },
    "THREADS");

// --dim, checked against the dimensions the library instantiates.
CLI::Option* add_dimension_option(CLI::App& cmd, int& dimension, const std::string& help) {
  return cmd.add_option("-d,--dim", dimension, help)->check(CLI::Range(dfvn::kMinDimension, dfvn::kMaxDimension));
}

// --noise: the basis of the N-1 noise functions.
void add_noise_option(CLI::App& cmd, std::string& noise) {
  cmd.add_option("--noise", noise,
                 "Noise basis of the N-1 functions: turning-bands (healthy in every dimension), simplex (the\n"
                 "paper's construction; its field is nearly still in most of space from 4D on) or quintic-gradient\n"
                 "(Perlin-style lattice gradient noise, the noise of the paper's image-warping shader)")
      ->capture_default_str()
      ->check(CLI::IsMember({"simplex", "turning-bands", "quintic-gradient"}));
}

// Options that every subcommand shares.
struct CommonOptions {
  std::uint64_t seed = 1;
  int threads = 0;
};

void add_threads_option(CLI::App& app, int& threads) {
  app.add_option("--threads", threads, "Worker threads: 0 = all cores, at most 4 x the cores (output never depends on it)")
      ->capture_default_str()
      ->check(kThreadCount);
}

void add_common_options(CLI::App& app, CommonOptions& common) {
  app.add_option("-s,--seed", common.seed, "Seed of every random choice; same seed, same output")
      ->capture_default_str()
      ->check(kUnsignedInteger);
  add_threads_option(app, common.threads);
}

// Progress on stderr: --progress and -q/--quiet, shared by the subcommands that run long.
struct ProgressOptions {
  std::string mode = "auto";
  bool quiet = false;

  void add_to(CLI::App& app) {
    app.add_option("--progress", mode,
                   "Progress on stderr: auto (a live line on a terminal, otherwise a plain line every 5 s of long\n"
                   "work), always (also a line as each stage starts) or never")
        ->capture_default_str()
        ->check(CLI::IsMember({"auto", "always", "never"}));
    app.add_flag("-q,--quiet", quiet, "No progress on stderr (same as --progress never)");
  }
  // A reporter on stderr; `stages`: how many stages the run reports (0: unknown).
  dfvn::ProgressReporter* make(int stages = 0) {
    reporter_.emplace(quiet ? dfvn::ProgressMode::never : dfvn::parse_progress_mode(mode), stderr,
                      ::isatty(STDERR_FILENO) == 1, kProgram);
    reporter_->set_stage_count(stages);
    return &*reporter_;
  }

 private:
  std::optional<dfvn::ProgressReporter> reporter_;
};

struct FieldCommand {
  CommonOptions common;
  int dimension = 0;  // 0: the input's column count (3 with --diagnose)
  double frequency = 1.0;
  std::string noise{dfvn::to_string(dfvn::kDefaultNoiseBasis)};
  std::string domain = "free";
  std::string bound = "eq13";
  double boundary_width = 0.1;
  CLI::Option* bound_options[2] = {};  // --bound, --boundary-width: only with a bounded domain
  std::string input;
  std::string output = "-";
  bool diagnose = false;
  dfvn::DiagnosisOptions diagnosis;

  void add_to(CLI::App& parent) {
    CLI::App* cmd = parent.add_subcommand(
        "field",
        "Evaluate the divergence-free field at points read as text: comma-separated (optional header) or\n"
        "whitespace-separated (numpy.savetxt's default; '#' lines are comments), one point a line.\n"
        "Writes x0..x{N-1},c0..c{N-1},f1..f{N-1}: the point, the field vector c = cross(grad f_1..f_{N-1})\n"
        "(Eq. 8, RMS |c| = 1) and the N-1 noise values, with 17 significant digits.");
    add_dimension_option(*cmd, dimension,
                         "Dimension N of the points (2..8); default: the column count of the input's first line\n"
                         "(3 with --diagnose)");
    cmd->add_option("--frequency", frequency,
                    "Noise frequency F in cycles per unit length (one cycle = 2 pi / k_eff of the basis):\n"
                    "f_i(x) = (A/s) n_i(s x) with s = 2 pi F / k_eff; in [2^-50, 2^50], and every |F x_j| must be\n"
                    "below 2^50")
        ->capture_default_str()
        ->check(kNoiseFrequency);
    add_noise_option(*cmd, noise);
    cmd->add_option("--domain", domain,
                    "free (R^N), torus ([0,1)^N: the basis's periodic form, period 1 along every axis, at about F\n"
                    "cycles per unit length), cube ([0,1]^N) or ball (its inscribed ball): f_1 turned into the\n"
                    "boundary function by --bound, so c is tangent to the boundary (outside: the continuation)")
        ->capture_default_str()
        ->check(CLI::IsMember({"free", "torus", "cube", "ball"}));
    bound_options[0] =
        cmd->add_option("--bound", bound, "With --domain cube or ball: eq13 (the paper's Eq. 13) or ramp (Bridson et al. 2007)")
            ->capture_default_str()
            ->check(CLI::IsMember({"eq13", "ramp"}));
    bound_options[1] = cmd->add_option("--boundary-width", boundary_width,
                    "With --domain cube or ball: the bound's transition width in length units, in (0, 1/4]")
        ->capture_default_str()
        ->check(CLI::Range(std::nextafter(0.0, 1.0), 0.25));
    CLI::Option* input_option =
        cmd->add_option("--input", input, "Point file, CSV or whitespace-separated (default: standard input)")
            ->check(CLI::ExistingFile);
    CLI::Option* diagnose_flag = cmd->add_flag(
        "--diagnose", diagnose,
        "Instead of reading points, measure the field on uniform random points and write one CSV row: RMS |c|,\n"
        "median/RMS, q10/RMS, fraction of points below 1% of the RMS, |div c|/|Dc| by central differences\n"
        "(median, p95, max) and the measured k_eff against 2 pi F");
    diagnose_flag->excludes(input_option);
    cmd->add_option("--diagnose-points", diagnosis.points, "With --diagnose: number of uniform random points")
        ->capture_default_str()
        ->check(CLI::Range(std::uint64_t{10}, std::uint64_t{100000000}));
    cmd->add_option("--periods", diagnosis.periods, "With --diagnose: the points fill [0, periods / F]^N")
        ->capture_default_str()
        ->check(CLI::Range(1e-3, 1e9));
    cmd->add_option("-o,--output", output, "Output CSV file, written whole or not at all ('-' = standard output)")
        ->capture_default_str();
    add_common_options(*cmd, common);
    cmd->callback([this] { run(); });
  }

  std::string input_name() const {
    return input.empty() ? std::string("standard input") : dfvn::quote_for_message(input, dfvn::kMaxPathEchoChars);
  }

  dfvn::FieldOptions field_options() const {
    dfvn::FieldOptions o{dfvn::parse_noise_basis(noise), frequency};
    o.periodic = domain == "torus";
    if (domain == "cube" || domain == "ball") {
      o.constraint = domain == "cube" ? dfvn::FieldConstraint::inside_cube : dfvn::FieldConstraint::inside_ball;
      o.transition_width = boundary_width;
      o.bound = dfvn::parse_bound(bound);
    }
    return o;
  }

  void run() {
    dfvn::check_outputs({{"--output", output}});
    if (diagnose && (domain == "cube" || domain == "ball"))
      fail("--diagnose measures on uniform random points in R^N or on the torus: --domain free or torus");
    for (const CLI::Option* option : bound_options)
      if (option->count() > 0 && domain != "cube" && domain != "ball")
        fail(option->get_name() + " applies to --domain cube or ball, not " + domain);
    if (diagnose) {
      diagnosis.dimension = dimension > 0 ? dimension : 3;
      diagnosis.field = field_options();
      diagnosis.seed = common.seed;
      diagnosis.threads = common.threads;
      const dfvn::FieldDiagnosis d = dfvn::diagnose_field(diagnosis);
      dfvn::write_file_atomically(output, dfvn::diagnosis_csv_header() + dfvn::diagnosis_csv_row(d));
      return;
    }
    dfvn::PointTable points;
    try {
      if (input.empty()) {
        points = dfvn::read_points_text(std::cin, dimension);
      } else {
        std::ifstream in(input);
        if (!in) fail("cannot read " + input_name());
        points = dfvn::read_points_text(in, dimension);
      }
    } catch (const dfvn::InputError& e) {
      fail(input_name() + ", " + e.what());
    }
    if (points.dimension < dfvn::kMinDimension || points.dimension > dfvn::kMaxDimension)
      fail(fmt::format("{}: the first line has {} columns; the field is defined in {}..{} dimensions", input_name(),
                       points.dimension, dfvn::kMinDimension, dfvn::kMaxDimension));
    dfvn::FieldQuery query;
    query.dimension = points.dimension;
    query.seed = common.seed;
    query.field = field_options();
    query.threads = common.threads;
    try {
      std::vector<double> velocity(points.rows() * points.dimension), values(points.rows() * (points.dimension - 1));
      dfvn::evaluate_field(query, points.coordinates.data(), points.rows(), velocity.data(), values.data());
      dfvn::write_file_atomically(output, dfvn::field_csv(points, velocity.data(), values.data(), query.threads));
    } catch (const std::invalid_argument& e) {
      fail(input_name() + ", " + e.what());
    }
  }
};


// The outputs of a reproduction: its files in `dir`, each named as "--out (table1.csv)" in messages.
std::vector<std::pair<std::string, std::string>> files_in(const std::string& dir, const std::vector<std::string>& names) {
  std::vector<std::pair<std::string, std::string>> outputs;
  for (const std::string& name : names) outputs.emplace_back("--out (" + name + ")", (std::filesystem::path(dir) / name).string());
  return outputs;
}

struct SampleCommand {
  CommonOptions common;
  ProgressOptions progress;
  dfvn::SampleConfig config;
  std::string methods = "cnj,jitter-matched,jitter,pds,sobol";
  std::string protocol = "paper";
  std::string knn = "nanoflann";
  std::string integrator = "rk4";
  std::string noise{dfvn::to_string(dfvn::kDefaultNoiseBasis)};
  std::string reproject = "gauss-newton";
  std::string scramble = "owen";
  std::string stats_path = "-";
  std::string rdf_path;
  std::string points_dir;
  std::string json_path;
  std::string format = "csv";
  std::string domain{dfvn::to_string(dfvn::kDefaultCnjDomain)};
  std::string domain_mode = "conformant";
  std::string bound = "eq13";
  CLI::Option* bound_options[2] = {};  // --bound, --boundary-width: only where CNJ meets a boundary
  CLI::Option* domain_option = nullptr;
  std::string on = "none";
  CLI::Option* methods_option = nullptr;
  std::uint64_t count = 0;
  int realizations = 1;
  bool no_stats = false;
  bool no_timing = false;
  CLI::Option* stats_option = nullptr;
  CLI::Option* format_option = nullptr;

  void add_to(CLI::App& parent) {
    CLI::App* cmd = parent.add_subcommand(
        "sample",
        "Jitter a K^N lattice along the DFVN field (curl noise jittering, Section 5.1) and compare it with\n"
        "random jitter, Poisson disk sampling and Sobol points by nearest-neighbour statistics (CSV).\n"
        "This is the main job: 'dfvn-sample --dim 7 --grid 6' (any options) runs it. Other subcommands:\n"
        "field, stats, reproduce ('dfvn-sample --help'); each has --help.");
    add_dimension_option(*cmd, config.dimension, "Dimension N (2..8)")->capture_default_str();
    CLI::Option* grid_option = cmd->add_option("--grid", config.grid, "Lattice points per axis K (>= 2); K^N points")
                                   ->capture_default_str()
                                   ->check(CLI::Range(2, 1 << 30));
    cmd->add_option("-n,--count", count,
                    "Points per set instead of --grid: the lattice methods (cnj, jitter) use the K whose K^N is\n"
                    "nearest (the grid column says which), the others make exactly COUNT (Sobol warns unless it is a\n"
                    "power of 2; PDS reports when it saturates first)")
        ->check(CLI::Range(std::uint64_t{2}, std::uint64_t{1} << 40))
        ->excludes(grid_option);
    methods_option =
        cmd->add_option("--methods", methods,
                        "Comma list of cnj, jitter-matched (jitter moved as far as CNJ: its RMS displacement, on CNJ's\n"
                        "lattice and domain), jitter (the protocol's fixed half-width), pds, sobol, random, halton\n"
                        "(scrambled unless --scramble none), lhs; with --on sphere: cnj,random")
            ->capture_default_str();
    cmd->add_option("--protocol", protocol,
                    "paper: Section 5.1 as the paper ran it (lattice linspace(0.05, 0.95, K), jitter +-0.05, PDS\n"
                    "radius 0.1 and Sobol on [0, 0.1K]^N, Sobol count 2^round(log2 K^N)); unit: every method in\n"
                    "[0,1]^N at the density of a cell-centred K^N lattice (jitter +-1/(2K), PDS radius 1/K)")
        ->capture_default_str()
        ->check(CLI::IsMember({"paper", "unit"}));
    stats_option = cmd->add_option("-o,--stats", stats_path, "Statistics CSV ('-' = standard output)")->capture_default_str();
    cmd->add_option("--rdf", rdf_path, "Also compute radial distribution functions and write them here (CSV: dim,method,r,g)");
    cmd->add_option("--rdf-max", config.rdf.r_max, "Largest r of the RDF; 0 = 2.5 mean spacings")
        ->capture_default_str()
        ->check(kNonNegativeFinite);
    cmd->add_option("--rdf-bins", config.rdf.bins, "Number of RDF bins")->capture_default_str()->check(CLI::Range(1, 100000));
    cmd->add_option("--rdf-queries", config.rdf.max_queries,
                    "RDF query points: a seeded subset of about this many (0 = all points)")
        ->capture_default_str()
        ->check(kUnsignedInteger);
    cmd->add_option("--points", points_dir,
                    "Write each point set to DIR/<method>.<format>; '-' = standard output (one method only)");
    format_option = cmd->add_option("--format", format,
                                    "Point file format (with --points): csv (header x0..x{N-1}), npy (float64, (points, N))\n"
                                    "or dat (coordinates separated by spaces, no header: UTK's and pbrt's pspec text format)")
                        ->capture_default_str()
                        ->check(CLI::IsMember({"csv", "npy", "dat"}));
    cmd->add_flag("--no-stats", no_stats, "Generate the point sets only (needs --points): no statistics and no stats CSV");
    cmd->add_option("--json", json_path,
                    "Also write the run as JSON: parameters, every method's statistics and derived values ('-' = standard\n"
                    "output)");
    cmd->add_flag("--no-timing", no_timing,
                  "Leave the seconds columns empty (and out of --json): two runs with the same seed give identical files");
    cmd->add_option("--knn", knn, "KD-tree backend: nanoflann or flann (identical distances)")
        ->capture_default_str()
        ->check(CLI::IsMember({"nanoflann", "flann"}));
    cmd->add_option("--integrator", integrator, "CNJ integrator: euler or rk4")
        ->capture_default_str()
        ->check(CLI::IsMember({"euler", "rk4"}));
    cmd->add_option("--steps", config.cnj.trace.steps,
                    fmt::format("CNJ integration steps M (steps of t / M, each followed by the reprojection); 0 = the\n"
                                "domain's: {} in the free field (--domain torus, --domain-mode drop), 1 in the bounded\n"
                                "one (conformant cube or ball, and --on sphere) (data/cnj_defaults.md,\n"
                                "data/cnj_steps_main_job.md)",
                                dfvn::kFreeFieldSteps))
        ->capture_default_str()
        ->check(CLI::Range(0, dfvn::CnjOptions::kMaxSteps));
    cmd->add_option("--step-scale", config.cnj.step_scale,
                    "CNJ trace time t = C * dbar(N) * lattice spacing, dbar the mean distance to the 3^N-1 "
                    "lattice neighbours (Section 5.1); RMS |c| = 1, so t is the RMS move; at most 2^20")
        ->capture_default_str()
        ->check(kStepScale);
    cmd->add_option("--frequency", config.cnj.frequency,
                    "CNJ noise frequency in cycles per lattice spacing (one cycle = 2 pi / k_eff of the basis); the\n"
                    "field's, this / spacing, must be in [2^-50, 2^50]")
        ->capture_default_str()
        ->check(kNoiseFrequency);
    add_noise_option(*cmd, noise);
    cmd->add_option("--reproject", reproject, "CNJ reprojection after each step: none, newton (Eq. 12), gauss-newton (Eq. 10-11)")
        ->capture_default_str()
        ->check(CLI::IsMember({"none", "newton", "gauss-newton"}));
    domain_option = cmd->add_option("--domain", domain,
                                    "Where CNJ's points stay: torus ([0,1)^N with opposite faces identified: a periodic\n"
                                    "field, wrapped traces, the cell-centred lattice; no boundary at all), cube ([0,1]^N)\n"
                                    "or ball (its inscribed ball; the lattice clipped to it). Not given: torus, or cube\n"
                                    "when --domain-mode drop, --bound or --boundary-width asks for a boundary")
                        ->capture_default_str()
                        ->check(CLI::IsMember({"torus", "cube", "ball"}));
    bound_options[0] = cmd->add_option("--bound", bound,
                                       "How CNJ's field meets the boundary of --domain cube or ball (conformant): eq13\n"
                                       "(the paper's Eq. 13) or ramp (Bridson et al. 2007's ramp of the noise)")
                           ->capture_default_str()
                           ->check(CLI::IsMember({"eq13", "ramp"}));
    bound_options[1] =
        cmd->add_option("--boundary-width", config.cnj.boundary_width,
                        "The bound's transition width in lattice spacings (Eq. 13's alpha goes from 0 to 1 over it, the\n"
                        "ramp's d0), at most a quarter of the cube's side")
            ->capture_default_str()
            ->check(finite_number(0.0, false, "POSITIVE"));
    cmd->add_flag("--periodic", config.periodic_statistics,
                  "Measure every set on the torus of its box: minimum-image nearest-neighbour distances and RDF\n"
                  "(off: Euclidean distances in the box, as the paper measures)");
    cmd->add_option("--domain-mode", domain_mode,
                    "conformant: CNJ along the field bounded by the domain (Eq. 13), no point leaves; drop: the\n"
                    "free field, points that leave are dropped (the paper's protocol; reproduce table1 uses it)")
        ->capture_default_str()
        ->check(CLI::IsMember({"conformant", "drop"}));
    cmd->add_option("--on", on,
                    "sphere: methods cnj (traced with f_1 = |x|^2) and random on the unit sphere S^{N-1}, N >= 3,\n"
                    "from the K^N lattice on [-1,1]^N within half a spacing of it, projected; geodesic statistics")
        ->capture_default_str()
        ->check(CLI::IsMember({"none", "sphere"}));
    cmd->add_option("--reproject-iters", config.cnj.trace.reproject_iterations, "CNJ reprojection iterations R at most")
        ->capture_default_str()
        ->check(CLI::Range(0, 1000));
    cmd->add_option("--pds-radius", config.pds_radius, "Poisson disk radius; 0 = the protocol's (paper 0.1, unit 1/K)")
        ->capture_default_str()
        ->check(kNonNegativeFinite);
    cmd->add_option("--pds-candidates", config.pds_candidates, "Poisson disk candidates per active point (Bridson's k)")
        ->capture_default_str()
        ->check(CLI::Range(1, 100000));
    cmd->add_option("--scramble", scramble, "Sobol scrambling: owen (hash-based, keyed by the seed) or none; halton: digit permutations or none")
        ->capture_default_str()
        ->check(CLI::IsMember({"owen", "none"}));
    cmd->add_option("--max-memory", config.max_memory_gib, "Memory limit in GiB for the point sets; 0 = 80% of the machine's")
        ->capture_default_str()
        ->check(kNonNegativeFinite);
    cmd->add_option("--realizations", realizations,
                    "Run seeds s..s+R-1 and add per method the mean and sd of every statistic (rows seed = mean, sd)")
        ->capture_default_str()
        ->check(CLI::Range(1, 100000));
    progress.add_to(*cmd);
    add_common_options(*cmd, common);
    cmd->callback([this] { run(); });
  }

  void run() {
    config.seed = common.seed;
    config.threads = common.threads;
    config.protocol = dfvn::parse_protocol(protocol);
    config.knn = dfvn::parse_knn_backend(knn);
    config.scramble = dfvn::parse_scramble(scramble);
    config.cnj.trace.integrator = dfvn::parse_integrator(integrator);
    config.cnj.noise = dfvn::parse_noise_basis(noise);
    config.cnj.trace.reprojection = dfvn::parse_reprojection(reproject);
    // Options that only mean something at a boundary put CNJ in the cube when no domain is named.
    const bool asks_for_a_boundary =
        domain_mode == "drop" || bound_options[0]->count() > 0 || bound_options[1]->count() > 0;
    if (domain_option->count() == 0 && asks_for_a_boundary) domain = "cube";
    config.cnj.domain = dfvn::parse_cnj_domain(domain);
    config.cnj.domain_mode = dfvn::parse_domain_mode(domain_mode);
    config.cnj.bound = dfvn::parse_bound(bound);
    for (const CLI::Option* option : bound_options)
      if (option->count() > 0 &&
          (config.cnj.domain == dfvn::CnjDomain::torus || config.cnj.domain_mode == dfvn::DomainMode::drop))
        throw std::invalid_argument(option->get_name() + " applies to conformant CNJ in --domain cube or ball; " +
                                    (config.cnj.domain == dfvn::CnjDomain::torus ? "the torus has no boundary"
                                                                                  : "drop mode traces the free field"));
    config.on = dfvn::parse_surface(on);
    if (config.on == dfvn::Surface::sphere && methods_option->count() == 0) methods = "cnj,random";
    config.methods.clear();
    for (const auto& name : CLI::detail::split(methods, ',')) {
      config.methods.push_back(dfvn::parse_method(CLI::detail::trim_copy(name)));
      if (const auto repeat = dfvn::first_repeat(config.methods))  // before the next name is parsed, as it is read
        throw std::invalid_argument("--methods names '" + std::string(dfvn::to_string(*repeat)) + "' twice");
    }
    if (count > 0) {
      config.count = count;
      config.grid = dfvn::grid_for_count(config.dimension, count);
    }
    config.compute_statistics = !no_stats;
    config.compute_rdf = !rdf_path.empty();
    config.validate();
    dfvn::check_seed_range(common.seed, static_cast<std::uint64_t>(realizations), "--seed", "--realizations");
    check_output_options();

    // Check every destination before the work starts; each file is then written whole or not at all.
    std::vector<std::pair<std::string, std::string>> outputs;
    if (!no_stats)
      outputs.emplace_back(stats_option->count() > 0 ? "--stats" : "the statistics (default --stats -)", stats_path);
    if (!rdf_path.empty()) outputs.emplace_back("--rdf", rdf_path);
    if (!json_path.empty()) outputs.emplace_back("--json", json_path);
    if (points_dir == "-") outputs.emplace_back("--points", points_dir);
    const bool points_to_files = !points_dir.empty() && points_dir != "-";
    if (points_to_files)
      for (dfvn::Method m : config.methods) outputs.emplace_back("--points (" + point_file_name(m) + ")", point_file(m));
    dfvn::check_outputs(outputs, points_to_files ? std::vector<std::string>{points_dir} : std::vector<std::string>{});
    for (const std::string& warning : dfvn::sampling_warnings(config)) std::fprintf(stderr, "%s: warning: %s\n", kProgram, warning.c_str());

    const dfvn::PointFormat point_format = dfvn::parse_point_format(format);
    dfvn::ProgressReporter* reporter = progress.make(realizations * dfvn::sampling_stage_count(config));
    std::string stats = dfvn::stats_csv_header();
    std::string rdf = dfvn::rdf_csv_header();
    std::vector<std::string> realization_rows;
    std::vector<dfvn::SamplingRealization> runs;
    // Realization r uses seed s + r; every statistic is then summarised as mean and sd per method.
    for (int realization = 0; realization < realizations; ++realization) {
      config.seed = common.seed + static_cast<std::uint64_t>(realization);
      auto results = dfvn::run_sampling(config, false, reporter->callback(), [&](const dfvn::MethodResult& r) {
        if (!points_dir.empty()) {
          reporter->finish();  // the live line stays off standard output's terminal
          dfvn::write_point_file(point_file(r.plan.method), r.points, point_format);
        }
      });
      for (const auto& r : results) {
        realization_rows.push_back(dfvn::stats_csv_row(config, r, !no_timing));
        stats += realization_rows.back();
        realization_rows.back().pop_back();
        rdf += dfvn::rdf_csv_rows(config, r);
        if (config.count > 0) {
          reporter->finish();  // a warning starts on a line of its own
          report_saturation(r);
        }
      }
      runs.push_back({config.seed, std::move(results)});
    }
    reporter->complete();
    if (realizations > 1)
      stats += dfvn::realization_summary_rows(stats.substr(0, stats.find('\n')), realization_rows, {"dim", "grid", "method"}, "seed");
    config.seed = common.seed;
    if (!json_path.empty()) dfvn::write_file_atomically(json_path, dfvn::sampling_json(config, runs, !no_timing));
    if (!rdf_path.empty()) dfvn::write_file_atomically(rdf_path, rdf);
    if (!no_stats) dfvn::write_file_atomically(stats_path, stats);
  }

  // Options that only make sense together (the outputs themselves: dfvn::check_outputs).
  void check_output_options() const {
    if (format_option->count() > 0 && points_dir.empty())
      throw std::invalid_argument("--format " + format + " applies to --points, which is not given");
    if (no_stats && points_dir.empty()) throw std::invalid_argument("--no-stats writes only point sets: give --points DIR (or -)");
    if (no_stats && (stats_option->count() > 0 || !rdf_path.empty() || realizations > 1))
      throw std::invalid_argument("--no-stats computes no statistics: drop --stats, --rdf and --realizations");
    if (realizations > 1 && (!points_dir.empty() || !rdf_path.empty()))
      throw std::invalid_argument("--points and --rdf take one realization; drop them or --realizations");
    if (points_dir == "-" && config.methods.size() != 1)
      throw std::invalid_argument(fmt::format("--points - writes one point set to standard output; --methods names {}",
                                              config.methods.size()));
  }

  // With -n, PDS that saturated before the count: say so (the saturated column has it in every run).
  static void report_saturation(const dfvn::MethodResult& r) {
    if (r.facts.saturated && *r.facts.saturated)
      std::fprintf(stderr, "%s: warning: pds saturated at %llu of %llu points (radius %g): the domain holds no more\n",
                   kProgram, static_cast<unsigned long long>(r.point_count),
                   static_cast<unsigned long long>(r.plan.requested), *r.facts.radius);
  }

  std::string point_file_name(dfvn::Method m) const { return std::string(dfvn::to_string(m)) + "." + format; }
  std::string point_file(dfvn::Method m) const {
    return points_dir == "-" ? points_dir : (std::filesystem::path(points_dir) / point_file_name(m)).string();
  }
};


struct ReproduceCommand {
  CommonOptions common1, common2, common3, common4;
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
  std::string table1_noise{dfvn::to_string(dfvn::kDefaultNoiseBasis)};
  ProgressOptions progress;
  int table1_realizations = dfvn::Table1Config{}.realizations;

  void add_to(CLI::App& parent) {
    CLI::App* cmd = parent.add_subcommand("reproduce", "Regenerate the paper's tables and figures, ours beside the paper's.");
    cmd->require_subcommand(1);
    cmd->footer("Subcommands: table1, table2 ('dfvn-sample reproduce table1 --help').");
    CLI::App* t1 = cmd->add_subcommand(
        "table1",
        "Table 1 and Figure 4: CNJ, jittering, Poisson disk and Sobol point sets in 3D-7D under the paper protocol.\n"
        "Writes DIR/table1.csv, DIR/rdf.csv, DIR/table1.md and (with gnuplot) DIR/figure4.png; prints table1.md as plain text.");
    t1->add_option("--out", out1, "Output directory")->capture_default_str();
    t1->add_option("--dims", dims, "Dimensions: a range or list within 3..7, e.g. 3-7 or 3,5")->capture_default_str();
    t1->add_option("--realizations", table1_realizations,
                   "Realizations R (seeds s..s+R-1); cells are mean +- sd over them (each about 100 s for 3D-7D on 2 cores)")
        ->capture_default_str()
        ->check(CLI::Range(1, 1000));
    add_noise_option(*t1, table1_noise);  // the CNJ column; the simplex column is always shown beside it
    progress.add_to(*t1);
    add_common_options(*t1, common1);
    t1->callback([this] { run_table1(); });

    CLI::App* t2 = cmd->add_subcommand(
        "table2",
        "Table 2 and Figure 5: warp a wave image along 2D DFVN for t = 0.5 with Euler and RK4, 64 and 512 steps, 0, 1\n"
        "and 10 Newton reprojection steps, against 2048 RK4 steps; RMSE from float values at two resolutions; Figure 5's\n"
        "top row at several times t with 1000 RK4 steps. Writes DIR/table2.csv, DIR/table2.md, DIR/timeline.csv, the\n"
        "images as PNG and (with gnuplot) DIR/figure5.png; prints table2.md as plain text.");
    t2->add_option("--out", out2, "Output directory")->capture_default_str();
    t2->add_option("--setting", setting,
                   "shader: the paper's shader (2D quintic gradient noise, noise_scale 7, its unnormalised field\n"
                   "magnitude 7 sigma = 5.049 widths per unit time, t = 0.5, its wave-band image); ours: simplex noise,\n"
                   "3 cycles per width, RMS |c| = 1, sine stripes (the earlier default)")
        ->capture_default_str()
        ->check(CLI::IsMember({"shader", "ours"}));
    t2->add_option("--width", warp.width, "Image width in pixels")->capture_default_str()->check(CLI::Range(2, 20000));
    t2->add_option("--height", warp.height, "Image height in pixels")->capture_default_str()->check(CLI::Range(2, 20000));
    second_width_option = t2->add_option("--second-width", table2.second_width,
                   "Width of the second resolution (same aspect ratio) at which every RMSE is measured again; 0 = none;\n"
                   "default: half of --width (none when that is below 2 pixels a side)")
        ->check(CLI::Range(0, 20000));
    t2->add_option("--samples", warp.samples, "Samples per pixel, a perfect square (m x m sub-pixel grid, averaged)")
        ->capture_default_str()
        ->check(CLI::IsMember({1, 4, 9, 16, 25, 36, 49, 64}));
    t2->add_option("--frequency", frequency,
                   "Noise frequency in cycles per image width (one cycle = 2 pi / k_eff); default: the setting's\n"
                   "(shader: 7 k_eff / (2 pi) = 4.562, ours: 3)")
        ->check(kNoiseFrequency);
    t2->add_option("--field-magnitude", field_magnitude,
                   "RMS speed of the field in image widths per unit time, in [1e-6, 1e6]; default: the setting's\n"
                   "(shader: 5.049, ours: 1)")
        ->check(CLI::Range(1e-6, 1e6));
    progress.add_to(*t2);
    add_common_options(*t2, common2);
    t2->callback([this] { run_table2(); });

    CLI::App* s = cmd->add_subcommand(
        "cnj-study",
        fmt::format(
            "CNJ (each noise basis) against random jitter over noise frequencies 0.1, 0.2, 0.35, 0.5, 1 cycles per\n"
            "spacing, step scales 0.2, 0.35, 0.5 and 1 or {} integration steps, compared at equal RMS displacement,\n"
            "neighbour disorder and lattice order (--lattice interior: interior points of a K^N lattice, nothing\n"
            "dropped; --lattice paper: Table 1's lattice, points leaving [0,1]^N dropped as the paper does). Writes\n"
            "DIR/cnj_study.csv, DIR/cnj_study_jitter.csv, DIR/cnj_study.md and (with gnuplot) DIR/cnj_study.png;\n"
            "prints the Markdown as plain text.\n"
            "The CNJ defaults come from this study's rule (data/cnj_defaults.md).",
            dfvn::kFreeFieldSteps));
    s->add_option("--out", study.out_dir, "Output directory")->capture_default_str();
    s->add_option("--dims", study_dims, "Dimensions: a range or list within 3..7, e.g. 3-7 or 3,5")->capture_default_str();
    s->add_option("--seeds", study.seeds, "Seeds per cell (--seed, --seed + 1, ...)")
        ->capture_default_str()
        ->check(CLI::Range(1, 1000));
    s->add_option("--lattice", study_lattice,
                  "interior (the study's cell-centred lattice, statistics over interior sites) or paper (Table 1's "
                  "lattice linspace(0.05, 0.95, K), leaving points dropped)")
        ->capture_default_str()
        ->check(CLI::IsMember({"interior", "paper"}));
    s->add_option("--noises", study_bases, "Comma list of noise bases to study")->delimiter(',')->capture_default_str();
    s->add_option("--frequencies", study.frequencies, "Comma list of noise frequencies, cycles per lattice spacing")
        ->delimiter(',')
        ->capture_default_str();
    s->add_option("--step-scales", study.step_scales, "Comma list of step scales C (t = C dbar(N) spacing)")
        ->delimiter(',')
        ->capture_default_str();
    s->add_option("--steps", study.steps,
                  fmt::format("Comma list of integration steps M per trace (RK4 steps of t / M, each followed by\n"
                              "the reprojection; Section 5.1 takes 1, the free field's default is {})",
                              dfvn::kFreeFieldSteps))
        ->delimiter(',')
        ->capture_default_str()
        ->check(CLI::Range(1, dfvn::CnjOptions::kMaxSteps));
    progress.add_to(*s);
    add_common_options(*s, common3);
    s->callback([this] { run_cnj_study(); });
    add_integration(cmd);
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
    dfvn::ProgressReporter* reporter = progress.make();
    const auto result = dfvn::run_cnj_study(study, reporter->callback());
    reporter->complete();
    std::fputs(dfvn::markdown_as_plain_text(dfvn::write_cnj_study(result, log)).c_str(), stdout);
  }

  void add_integration(CLI::App* cmd) {
    CLI::App* t3 = cmd->add_subcommand(
        "integration",
        "Section 6.1's open question: integrate Genz's six test families with every method's point sets in 3D-7D, at\n"
        "several sizes, over R realizations. Writes DIR/integration.csv, DIR/integration_slopes.csv, DIR/integration.md\n"
        "(tables and a reading) and (with gnuplot) DIR/integration_<N>d.png; prints integration.md as plain text.");
    t3->add_option("--out", integration.out_dir, "Output directory")->capture_default_str();
    t3->add_option("--dims", integration_dims, "Dimensions: a range or list within 3..7")->capture_default_str();
    t3->add_option("--realizations", integration.realizations, "Realizations R (seeds s..s+R-1); at least 16 for the reading")
        ->capture_default_str()
        ->check(CLI::Range(2, 100000));
    t3->add_option("--max-points", integration.max_points, "Largest lattice K^N per dimension")
        ->capture_default_str()
        ->check(CLI::Range(64, 1 << 24));
    t3->add_option("--methods", integration_methods, "Comma list of methods")->capture_default_str();
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
    dfvn::ProgressReporter* reporter = progress.make();
    const auto result = dfvn::run_integration(integration, reporter->callback());
    reporter->complete();
    std::fputs(dfvn::markdown_as_plain_text(dfvn::write_integration(result, log)).c_str(), stdout);
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
    dfvn::ProgressReporter* reporter = progress.make();
    const auto result = dfvn::run_table1(config, reporter->callback());
    reporter->complete();
    std::fputs(dfvn::markdown_as_plain_text(dfvn::write_table1(config, result, log)).c_str(), stdout);
  }

  void run_table2() {
    table2.setting = dfvn::parse_warp_setting(setting);
    dfvn::WarpConfig& config = table2.warp;
    config = dfvn::warp_config(table2.setting);
    config.width = warp.width;
    config.height = warp.height;
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
    dfvn::ProgressReporter* reporter = progress.make();
    const auto result = dfvn::run_table2(table2, reporter->callback());
    reporter->complete();
    std::fputs(dfvn::markdown_as_plain_text(dfvn::write_table2(out2, result, log)).c_str(), stdout);
  }
};

struct StatsCommand {
  CommonOptions common;
  std::string input;
  std::string format;
  std::string output = "-";
  std::string knn = "nanoflann";
  double domain_side = 1.0;
  std::string spectrum_prefix;
  int spectrum_frequency = 32;
  std::string json_path;
  bool discrepancy = false;
  bool no_timing = false;
  bool periodic = false;
  ProgressOptions progress;
  CLI::Option* output_option = nullptr;

  void add_to(CLI::App& parent) {
    CLI::App* cmd = parent.add_subcommand(
        "stats",
        "Statistics of any point set in [0,S]^N, N = 1..8: nearest-neighbour summary and, with --discrepancy, the\n"
        "CD, WD, MD and L2-star discrepancies (as scipy.stats.qmc.discrepancy). One CSV row per set; a dat file\n"
        "with several sets also gets their mean and sd rows (set = mean, sd).");
    cmd->add_option("--input", input, "Point file: CSV (optional header), NPY float64/float32 (points, N), or dat\n"
                                      "(whitespace-separated, '#' lines between sets)")
        ->required()
        ->check(CLI::ExistingFile);
    cmd->add_option("--format", format, "csv, npy or dat; default: from the extension (.txt = dat)")
        ->check(CLI::IsMember({"csv", "npy", "dat"}));
    cmd->add_option("--domain-side", domain_side, "The points lie in [0, S]^N, S in [2^-1000, 2^1000]")
        ->capture_default_str()
        ->check(kDomainSide);
    cmd->add_flag("--discrepancy", discrepancy, "Also compute the four L2 discrepancies (O(points^2) work)");
    cmd->add_option("--knn", knn, "KD-tree backend: nanoflann or flann (not used with --periodic)")
        ->capture_default_str()
        ->check(CLI::IsMember({"nanoflann", "flann"}));
    cmd->add_flag("--periodic", periodic,
                  "Measure on the torus [0,S)^N: minimum-image nearest-neighbour distances (opposite faces\n"
                  "identified), as for sets made periodic (dfvn-sample --domain torus, UTK's periodic samplers)");
    output_option = cmd->add_option("-o,--output", output, "Statistics CSV ('-' = standard output)")->capture_default_str();
    cmd->add_option("--json", json_path, "Also write the statistics as JSON ('-' = standard output)");
    cmd->add_flag("--no-timing", no_timing, "Leave seconds_stats empty (and out of --json): identical files for identical input");
    cmd->add_option("--spectrum", spectrum_prefix,
                    "2D/3D sets: also write the power spectrum averaged over the file's sets: PREFIX.csv (k0..,power),\n"
                    "PREFIX_radial.csv (frequency,power,anisotropy_db,frequencies) and, with gnuplot, PREFIX.png");
    cmd->add_option("--spectrum-frequency", spectrum_frequency, "Largest integer frequency K of the spectrum ([-K,K]^N)")
        ->capture_default_str()
        ->check(CLI::Range(1, 512));
    progress.add_to(*cmd);
    add_threads_option(*cmd, common.threads);
    cmd->callback([this] { run(); });
  }

  void run() {
    const dfvn::InputFormat input_format =
        format.empty() ? dfvn::input_format_from_path(input) : dfvn::parse_input_format(format);
    std::vector<dfvn::PointSet> sets;
    try {
      for (auto& table : dfvn::read_point_sets(input, input_format)) {
        sets.push_back(dfvn::PointSet{table.dimension, std::move(table.coordinates), dfvn::Box{0.0, domain_side}});
        dfvn::check_point_set(sets.back());
      }
    } catch (const std::exception& e) {
      fail(input + (sets.empty() ? ", " : fmt::format(", set {}: ", sets.size() - 1)) + e.what());
    }
    if (!spectrum_prefix.empty() && sets.front().dimension != 2 && sets.front().dimension != 3)
      fail(fmt::format("--spectrum needs 2D or 3D points; '{}' holds {}D points", input, sets.front().dimension));
    // Every output, checked together before the work: --output, --json and the spectrum's three files.
    std::vector<std::pair<std::string, std::string>> outputs = {
        {output_option->count() > 0 ? "--output" : "the statistics (default --output -)", output}};
    if (!json_path.empty()) outputs.emplace_back("--json", json_path);
    if (!spectrum_prefix.empty())
      for (const std::string& suffix : dfvn::spectrum_file_suffixes())
        outputs.emplace_back("--spectrum (" + std::filesystem::path(spectrum_prefix + suffix).filename().string() + ")",
                             spectrum_prefix + suffix);
    dfvn::check_outputs(outputs);
    if (!spectrum_prefix.empty()) dfvn::check_figure_prerequisites();
    dfvn::PointSetStatisticsOptions options;
    options.discrepancy = discrepancy;
    options.knn = dfvn::parse_knn_backend(knn);
    options.threads = common.threads;
    options.periodic = periodic;
    dfvn::ProgressReporter* reporter =
        progress.make(static_cast<int>(sets.size()) * dfvn::point_statistics_stage_count(options) + (spectrum_prefix.empty() ? 0 : 1));
    std::string csv = dfvn::point_statistics_csv_header();
    std::vector<std::string> rows;
    dfvn::PointStatisticsRun run{input, std::string(dfvn::to_string(input_format)), domain_side, options, {}, {}, !no_timing};
    for (std::size_t s = 0; s < sets.size(); ++s) {
      // Each set's stages get its number, so that the [k/n] counter moves on between sets.
      const std::string set_label = sets.size() > 1 ? fmt::format("set {} ", s) : std::string();
      run.sets.push_back(dfvn::measure_point_set(sets[s], options, [&](std::string_view stage, double f) {
        reporter->report(set_label + std::string(stage), f);
      }));
      run.dimensions.push_back(sets[s].dimension);
      rows.push_back(dfvn::point_statistics_csv_row(input, std::to_string(s), sets[s], run.sets.back(), !no_timing));
      csv += rows.back();
      rows.back().pop_back();
    }
    if (sets.size() > 1) csv += dfvn::realization_summary_rows(csv.substr(0, csv.find('\n')), rows, {"input", "dim"}, "set");
    if (!spectrum_prefix.empty()) {
      reporter->report("spectrum", 0.0);
      const auto spectrum = dfvn::power_spectrum(sets, spectrum_frequency, common.threads);
      reporter->finish();
      dfvn::write_spectrum_files(spectrum_prefix, spectrum,
                                 [](const std::string& line) { std::fprintf(stderr, "%s: %s\n", kProgram, line.c_str()); });
    }
    reporter->complete();
    if (!json_path.empty()) dfvn::write_file_atomically(json_path, dfvn::point_statistics_json(run));
    dfvn::write_file_atomically(output, csv);
  }
};

const std::vector<std::string> kSubcommands = {"sample", "field", "reproduce", "stats"};

// CLI11 echoes arguments verbatim in its messages: shorten and escape each one that is long or holds
// bytes that are not printable ASCII (core/message_text.hpp).
std::string with_safe_echoes(std::string message, std::vector<std::string> args) {
  std::sort(args.begin(), args.end(), [](const std::string& a, const std::string& b) { return a.size() > b.size(); });
  for (const std::string& arg : args) {
    const bool printable = std::all_of(arg.begin(), arg.end(), [](char c) { return c >= 0x20 && c < 0x7F; });
    if (arg.empty() || (printable && arg.size() <= dfvn::kMaxEchoChars)) continue;
    const std::string safe = dfvn::quote_for_message(arg);
    for (std::size_t at = message.find(arg); at != std::string::npos; at = message.find(arg, at + safe.size()))
      message.replace(at, arg.size(), safe);
  }
  return message;
}

// The deepest subcommand on the command line, e.g. 'reproduce' in "reproduce table3".
CLI::App* deepest_subcommand(CLI::App& app) {
  CLI::App* deepest = &app;
  while (!deepest->get_subcommands().empty()) deepest = deepest->get_subcommands().front();
  return deepest;
}

// A parse error as the tool's own line: unexpected arguments in the order given, and a missing
// subcommand with the names it could have been.
std::string parse_error_message(CLI::App& app, const CLI::ParseError& error) {
  CLI::App* deepest = deepest_subcommand(app);
  const std::vector<std::string> unexpected = app.remaining(true);
  if (deepest->get_require_subcommand_min() > 0 && deepest->get_subcommands().empty()) {
    std::string names;
    for (const CLI::App* sub : deepest->get_subcommands([](CLI::App*) { return true; }))
      names += (names.empty() ? "" : " or ") + sub->get_name();
    return fmt::format("'{}' needs a subcommand: {}{}", deepest->get_name(), names,
                       unexpected.empty() ? std::string() : ", got " + dfvn::quote_for_message(unexpected.front()));
  }
  if (dynamic_cast<const CLI::ExtrasError*>(&error) && !unexpected.empty()) {
    std::string list;
    for (const std::string& arg : unexpected) list += (list.empty() ? "" : " ") + dfvn::quote_for_message(arg);
    return fmt::format("unexpected argument{}: {}", unexpected.size() > 1 ? "s" : "", list);
  }
  return error.what();
}

// 'sample' is the default: insert it when the first argument names no subcommand and is not one of
// the program's own flags (--help, --help-all, --version).
std::vector<std::string> with_default_subcommand(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  const bool names_subcommand = !args.empty() && std::find(kSubcommands.begin(), kSubcommands.end(), args[0]) != kSubcommands.end();
  const bool top_level_flag =
      !args.empty() && (args[0] == "--version" || args[0] == "--help-all" || args[0] == "--help" || args[0] == "-h");
  if (!names_subcommand && !top_level_flag) args.insert(args.begin(), "sample");
  std::reverse(args.begin(), args.end());  // CLI11 parses a reversed vector
  return args;
}

// Without arguments: what the tool does and how to start, instead of starting a long job.
constexpr const char* kUsage =
    "dfvn-sample: divergence-free vector noise (DFVN) in 2..8 dimensions, curl noise jittering of lattices\n"
    "and the point-set statistics of 'Improving Curl Noise' (SIGGRAPH Asia 2025).\n"
    "\n"
    "The main job: CNJ, jittered lattice, Poisson disk and Sobol point sets and one CSV row of\n"
    "nearest-neighbour statistics per method (any options run it, as does 'dfvn-sample sample ...'):\n"
    "  dfvn-sample --dim 7 --grid 6              the paper's 7D sets (about a minute on 2 cores)\n"
    "  dfvn-sample -d 3 -n 4096 -o stats.csv     3D, 4096 points per set\n"
    "\n"
    "Subcommands:\n"
    "  sample      the main job (the default)\n"
    "  field       evaluate the field at points read as text\n"
    "  stats       statistics of any point set (CSV, NPY or dat)\n"
    "  reproduce   the paper's tables and figures: table1, table2, cnj-study, integration\n"
    "\n"
    "'dfvn-sample SUBCOMMAND --help' lists a subcommand's options and defaults; --help-all lists every one;\n"
    "--version prints the version.\n";

}  // namespace

int main(int argc, char** argv) {
  if (argc == 1) {
    std::fputs(kUsage, stdout);
    return 0;
  }
  CLI::App app{"dfvn-sample: divergence-free vector noise (DFVN) in 2..8 dimensions: the field, curl-noise\n"
               "jittering of lattices, and the point-set statistics of 'Improving Curl Noise' (SIGGRAPH Asia 2025).",
               kProgram};
  app.set_version_flag("--version", std::string(kProgram) + " " + DFVN_VERSION);
  app.set_help_all_flag("--help-all", "Print the help of every subcommand and exit");
  app.require_subcommand(1);
  app.footer("Without a subcommand, 'sample' runs (the main job): 'dfvn-sample --dim 7 --grid 6'.\n"
             "Each subcommand has --help: 'dfvn-sample sample --help', 'dfvn-sample reproduce table1 --help'.");
  SampleCommand sample;
  sample.add_to(app);
  FieldCommand field;
  field.add_to(app);
  ReproduceCommand reproduce;
  reproduce.add_to(app);
  StatsCommand stats;
  stats.add_to(app);

  dfvn::remove_temporaries_on_signals();
  const std::vector<std::string> given(argv + 1, argv + argc);
  try {
    std::vector<std::string> args = with_default_subcommand(argc, argv);
    app.parse(args);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    fail(with_safe_echoes(parse_error_message(app, e), given) + " (run with --help for the options)", 2);
  } catch (const std::bad_alloc&) {  // the library names what it allocates where it can; this is the rest
    fail("out of memory; try a smaller problem");
  } catch (const std::exception& e) {
    fail(e.what());
  }
  return 0;
}
