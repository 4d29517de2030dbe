// dfvn-sample sample: the main job (experiment/experiment.hpp), its options and its files.
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "dfvn/core/message_text.hpp"
#include "dfvn/core/repeats.hpp"
#include "dfvn/core/seeds.hpp"
#include "dfvn/experiment/experiment.hpp"
#include "dfvn/experiment/json_report.hpp"
#include "dfvn/experiment/realizations.hpp"
#include "dfvn/experiment/streamed_sampling.hpp"
#include "dfvn/experiment/verdict.hpp"
#include "dfvn/io/atomic_file.hpp"
#include "dfvn/io/point_file.hpp"
#include "dfvn/io/point_sidecar.hpp"
#include "dfvn/sampling/method.hpp"

#include "options.hpp"

namespace dfvn_cli {
namespace {

struct SampleCommand : Subcommand {
  CommonOptions common;
  ProgressOptions progress;
  dfvn::SampleConfig config;
  std::string methods = "cnj,jitter-matched,jitter,pds,sobol";
  std::string protocol = "fair";
  CLI::Option* protocol_option = nullptr;
  CLI::Option* domain_mode_option = nullptr;
  CLI::Option* on_option = nullptr;
  bool periodic = false;
  std::string knn = "nanoflann";
  std::string integrator = "rk4";
  std::string noise{dfvn::to_string(dfvn::kDefaultNoiseBasis)};
  std::string reproject = "gauss-newton";
  CLI::Option* reproject_option = nullptr;
  std::string field_kind{dfvn::to_string(dfvn::kDefaultFieldKind)};
  std::string scramble = "owen";
  std::string stats_path = "-";
  std::string rdf_path;
  std::string points_dir;
  bool one_point_file = false;  // --points FILE.ext with one method (choose_point_file)
  std::string json_path;
  std::string report_path;
  std::string summary_path;
  std::string format = "csv";
  std::string domain{dfvn::to_string(dfvn::kDefaultDomainKind)};
  std::string domain_mode = "conformant";
  std::string bound = "eq13";
  CLI::Option* bound_options[2] = {};  // --bound, --boundary-spacings: only where CNJ meets a boundary
  CLI::Option* domain_option = nullptr;
  std::string on = "none";
  CLI::Option* methods_option = nullptr;
  std::uint64_t count = 0;
  int realizations = 1;
  bool no_stats = false;
  bool no_timing = false;
  bool stream = false;
  std::string streaming_note;  // why the run streams by itself (the sets' memory), printed once it goes ahead
  CLI::Option* stats_option = nullptr;
  CLI::Option* format_option = nullptr;
  TransformOptions transform;
  SteerOptions steer;
  BridsonOptions bridson;
  std::string rotation{dfvn::to_string(dfvn::kDefaultGradientRotation)};

  void add_to(CLI::App& parent) {
    CLI::App* cmd = parent.add_subcommand(
        "sample",
        "The main job: point sets of every method and their nearest-neighbour statistics\n\n"
        "Jitter a K^N lattice along the DFVN field (curl noise jittering, Section 5.1) and compare it with\n"
        "random jitter, Poisson disk sampling and Sobol points by nearest-neighbour statistics (CSV).\n"
        "This is the main job: 'dfvn-sample --dim 7 --grid 6' (any options) runs it. Other subcommands:\n"
        "field, stats, reproduce, animate ('dfvn-sample --help'); each has --help.\n"
        "Methods: " + dfvn::method_names() + ".");
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
                        "Comma list of methods, of " + dfvn::method_names() +
                            ". jitter-matched: jitter moved as far as CNJ (its RMS displacement, on CNJ's lattice and\n"
                            "domain); jitter: the protocol's fixed half-width; halton: scrambled unless --scramble none;\n"
                            "with --on sphere: cnj,random")
            ->capture_default_str();
    protocol_option =
        cmd->add_option("--protocol", protocol,
                        "fair: every method in the run's --domain at one count (the K^N sites of the cell-centred\n"
                        "lattice, spacing 1/K; Sobol and Halton exactly that many), stratified jitter +-1/(2K), Poisson\n"
                        "disk at the largest radius that reaches the count, every set measured in the domain's metric.\n"
                        "paper: Section 5.1 as the paper ran it, CNJ included: in the cube, lattice\n"
                        "linspace(0.05, 0.95, K), jitter +-0.05, CNJ one RK4 step with the points that leave dropped,\n"
                        "PDS radius 0.1 and Sobol on [0, 0.1K]^N (Sobol count 2^round(log2 K^N)), Euclidean distances;\n"
                        "its 6D and 7D sets differ in density (reproduce table1 says by how much)")
            ->capture_default_str()
            ->check(CLI::IsMember({"fair", "paper", "unit"}));
    stats_option = cmd->add_option("-o,--output,--stats", stats_path,
                                   "Main output: the statistics CSV ('-' = standard output); --stats is its second name.\n"
                                   "Point sets go to --points")
                       ->capture_default_str();
    cmd->add_option("--rdf", rdf_path, "Also compute radial distribution functions and write them to this CSV (dim,method,r,g)");
    cmd->add_option("--rdf-max", config.rdf.r_max, "Largest r of the RDF; 0 = 2.5 mean spacings")
        ->capture_default_str()
        ->check(kNonNegativeFinite);
    cmd->add_option("--rdf-bins", config.rdf.bins, "Number of RDF bins")->capture_default_str()->check(CLI::Range(1, 100000));
    cmd->add_option("--rdf-queries", config.rdf.max_queries,
                    "RDF query points: a seeded subset of about this many (0 = all points)")
        ->capture_default_str()
        ->check(kUnsignedInteger);
    cmd->add_option("--points", points_dir,
                    "Write the point sets: with one method to FILE when its name ends in a point format's extension\n"
                    "(.csv, .npy, .dat, .bin; .txt and .pts are dat), in that format; otherwise each method's to\n"
                    "DIR/<method>.<format>. The M sets of --sets M go into one file; each file gets its sidecar\n"
                    "FILE.json. '-' = standard output (one method; no statistics there unless -o names a file)");
    format_option = cmd->add_option("--format", format,
                                    "Point file format (of --points): csv (header x0..x{N-1}; one set only), npy (float64,\n"
                                    "(points, N); M sets: (M, points, N), sets of one size), dat (coordinates separated by\n"
                                    "spaces, no header, a line '#' between sets: UTK's and pbrt's pspec text format) or bin\n"
                                    "(UTK's binary: per set a uint32 point count, then the float64 coordinates)")
                        ->capture_default_str()
                        ->check(CLI::IsMember({"csv", "npy", "dat", "bin"}));
    cmd->add_flag("--no-stats", no_stats, "Generate the point sets only (needs --points): no statistics and no stats CSV");
    cmd->add_option("--json", json_path,
                    "Also write the run as JSON: parameters, every method's statistics and derived values ('-' = standard\n"
                    "output)");
    cmd->add_option("--summary", summary_path,
                    "Also write the summary over the realizations as CSV ('-' = standard output): per method and\n"
                    "statistic the mean, sd and standard error over the R sets of --realizations R >= 2 (a column\n"
                    "constant over them, a setting, is not summarised); the JSON holds them too");
    cmd->add_option("--report", report_path,
                    "Also write the verdict as Markdown: per statistic (nn_min, nn_q01, nn_median_scaled) the methods\n"
                    "ranked, each against jitter-matched and Poisson disk as a ratio, and with --realizations R the\n"
                    "mean +- standard error and whether a difference exceeds two standard errors ('-' = standard\n"
                    "output). Its summary goes to standard error unless -q");
    cmd->add_flag("--no-timing", no_timing,
                  "Leave the seconds columns (seconds_generate, seconds_stats) empty (and out of --json): two runs with the same seed give identical files");
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
    cmd->add_option("--cycles-per-spacing", config.cnj.frequency,
                    "CNJ noise frequency C in cycles per lattice spacing (one cycle = 2 pi / k_eff of the basis); the\n"
                    "field's frequency, C / spacing in cycles per unit length, must be in [2^-50, 2^50]")
        ->capture_default_str()
        ->check(kNoiseFrequency);
    add_noise_option(*cmd, noise, true);
    steer.add_to(*cmd);
    add_field_kind_option(*cmd, field_kind,
                          "CNJ traces along it; with curl:\n--reproject none (its default), --domain torus or "
                          "--domain-mode drop, no --on");
    reproject_option = cmd->add_option("--reproject", reproject,
                    "CNJ reprojection after each step: none, newton (Eq. 12), gauss-newton (Eq. 10-11); with --field\n"
                    "curl only none, its default")
        ->capture_default_str()
        ->check(CLI::IsMember({"none", "newton", "gauss-newton"}));
    add_phase_option(*cmd, config.cnj.phase);
    add_rotation_option(*cmd, rotation);
    transform.add_to(*cmd);
    bridson.add_to(*cmd);
    domain_option = cmd->add_option("--domain", domain,
                                    "Where every method's points live and are measured: torus ([0,1)^N with opposite faces\n"
                                    "identified: minimum-image distances; CNJ along a periodic field with wrapped traces; Poisson\n"
                                    "disk toroidal), cube ([0,1]^N, Euclidean distances), ball (its inscribed ball: the lattice's\n"
                                    "sites in it, sequences by rejection; not jitter-matched or lhs) or sphere (S^{N-1}, N >= 3:\n"
                                    "cnj and random, geodesic distances). Not given: torus; cube when --domain-mode drop,\n"
                                    "--bound, --boundary-spacings or --protocol paper asks for it; sphere with --on sphere")
                        ->capture_default_str()
                        ->check(CLI::IsMember({"torus", "cube", "ball", "sphere"}));
    bound_options[0] = cmd->add_option("--bound", bound,
                                       "How CNJ's field meets the boundary of --domain cube or ball (conformant): eq13\n"
                                       "(the paper's Eq. 13) or ramp (Bridson et al. 2007's ramp of the noise)")
                           ->capture_default_str()
                           ->check(CLI::IsMember({"eq13", "ramp"}));
    bound_options[1] =
        cmd->add_option("--boundary-spacings", config.cnj.boundary_width,
                        "The bound's transition width in lattice spacings (Eq. 13's alpha goes from 0 to 1 over it, the\n"
                        "ramp's d0), at most a quarter of the cube's side")
            ->capture_default_str()
            ->check(kPositiveFinite);
    cmd->add_flag("--periodic", periodic,
                  "Measure on the torus (minimum-image distances): what --domain torus, the default, does; refused\n"
                  "with another domain, whose metric is its own");
    domain_mode_option = cmd->add_option("--domain-mode", domain_mode,
                    "conformant: CNJ along the field bounded by the domain (Eq. 13), no point leaves; drop: the\n"
                    "free field, points that leave are dropped (the paper's protocol; reproduce table1 uses it)")
        ->capture_default_str()
        ->check(CLI::IsMember({"conformant", "drop"}));
    on_option = cmd->add_option("--on", on,
                    "sphere: the same as --domain sphere: methods cnj (traced with f_1 = |x|^2) and random on the\n"
                    "unit sphere S^{N-1}, N >= 3, from the K^N lattice on [-1,1]^N within half a spacing of it,\n"
                    "projected; geodesic statistics")
        ->capture_default_str()
        ->check(CLI::IsMember({"none", "sphere"}));
    cmd->add_option("--reproject-iters", config.cnj.trace.reproject_iterations, "CNJ reprojection iterations R at most")
        ->capture_default_str()
        ->check(CLI::Range(0, 1000));
    cmd->add_option("--pds-radius", config.pds_radius,
                    "Poisson disk radius, stopping at the count; 0 = the protocol's: fair, the largest radius found to\n"
                    "reach the count (reported in the radius column); paper, 0.1")
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
    cmd->add_flag("--stream", stream,
                  "Make and measure the sets in slabs (cnj, jitter, random, sobol): the lattice cut along its last\n"
                  "axis (the slowest in the point order) into --slabs slabs, each generated, appended to --points\n"
                  "and measured with a halo from its neighbours; memory O(slab + halo), temporaries in $TMPDIR; the\n"
                  "same bytes, statistics and --rdf as in memory (--periodic: the halo wraps around the torus).\n"
                  "Chosen by itself (with a note) when the sets would exceed --max-memory and the run can stream.\n"
                  "Not with pds, jitter-matched, halton, lhs, --domain ball, --on or --sets > 1");
    cmd->add_option("--slabs", config.stream_slabs,
                    "Slabs of --stream: a divisor of K for the lattice methods; 0 = the fewest whose slabs hold at most\n"
                    "2^22 points and fit --max-memory")
        ->capture_default_str()
        ->check(CLI::Range(0, 1 << 30));
    cmd->add_option("-m,--sets,--realizations", realizations,
                    "Realizations R: independently seeded repeats, seeds s..s+R-1 (-m/--sets M as in UTK): one row\n"
                    "a set; --summary and --json add their mean, sd and standard error; --points writes a method's R\n"
                    "sets into one file")
        ->capture_default_str()
        ->check(CLI::Range(1, 100000));
    progress.add_to(*cmd);
    add_common_options(*cmd, common);
    refuse_options(*cmd, {{"--frequency",
                           "sample takes CNJ's noise frequency per lattice spacing as --cycles-per-spacing C (--frequency "
                           "means cycles per unit length, as in field and reproduce table2)"},
                          {"--boundary-width",
                           "sample takes the bound's transition width in lattice spacings as --boundary-spacings W "
                           "(--boundary-width is in length units, as in field)"}});
    cmd->callback([this] { run(); });
  }

  void run() {
    config.seed = common.seed;
    config.threads = common.threads;
    if (protocol == "unit")
      throw std::invalid_argument("--protocol unit is now --protocol fair (the default) with --domain cube: every method "
                                  "in [0,1]^N at the lattice's count, Euclidean distances");
    const dfvn::Protocol chosen_protocol = dfvn::parse_protocol(protocol);
    config.knn = dfvn::parse_knn_backend(knn);
    config.scramble = dfvn::parse_scramble(scramble);
    config.cnj.trace.integrator = dfvn::parse_integrator(integrator);
    config.cnj.noise = dfvn::parse_noise_basis(noise);
    config.cnj.field = dfvn::parse_field_kind(field_kind);
    if (config.cnj.field == dfvn::FieldKind::curl && reproject_option->count() == 0) reproject = "none";
    config.cnj.trace.reprojection = dfvn::parse_reprojection(reproject);
    if (config.cnj.field == dfvn::FieldKind::curl && config.dimension > 3)
      throw std::invalid_argument(fmt::format(
          "--field curl is Bridson's curl noise in 2D and 3D; --dim {} needs --field dfvn", config.dimension));
    if (config.cnj.field == dfvn::FieldKind::curl && config.cnj.trace.reprojection != dfvn::Reprojection::none)
      throw std::invalid_argument("--field curl has no reprojection (its streamlines are not intersections of "
                                  "iso-surfaces): --reproject " + reproject + " needs --field dfvn");
    choose_domain(chosen_protocol);
    for (const CLI::Option* option : bound_options)
      if (option->count() > 0 &&
          ((config.cnj.domain != dfvn::DomainKind::cube && config.cnj.domain != dfvn::DomainKind::ball) ||
           config.cnj.domain_mode == dfvn::DomainMode::drop))
        throw std::invalid_argument(option->get_name() + " applies to conformant CNJ in --domain cube or ball; " +
                                    (config.cnj.domain == dfvn::DomainKind::torus    ? "the torus has no boundary"
                                     : config.cnj.domain == dfvn::DomainKind::sphere ? "the sphere has no boundary"
                                     : config.protocol == dfvn::Protocol::paper      ? "--protocol paper drops the points that leave"
                                                                                     : "drop mode traces the free field"));
    if (config.cnj.field == dfvn::FieldKind::curl && config.cnj.domain == dfvn::DomainKind::sphere)
      throw std::invalid_argument("--field curl has no surface form: --domain sphere needs --field dfvn");
    if (methods_option->count() == 0 && config.cnj.domain == dfvn::DomainKind::sphere) methods = "cnj,random";
    if (methods_option->count() == 0 && config.cnj.domain == dfvn::DomainKind::ball) methods = "cnj,jitter,pds,sobol";
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
    check_boundary_spacings();
    config.cnj.transform = transform.transform();
    config.cnj.transform.steer = steer.spec(noise, config.dimension);
    config.cnj.flow = bridson.flow();
    config.cnj.transform.rotation = dfvn::parse_gradient_rotation(rotation);
    if (config.cnj.transform.active())
      dfvn::check_transform_available(config.cnj.transform, config.dimension, config.cnj.domain == dfvn::DomainKind::torus);
    choose_point_file();
    config.compute_statistics = !no_stats;
    config.compute_rdf = !rdf_path.empty();
    choose_streaming();
    config.validate();
    dfvn::check_seed_range(common.seed, static_cast<std::uint64_t>(realizations), "--seed", "--realizations");
    check_output_options();
    check_streaming_space();

    // Check every destination before the work starts; each file is then written whole or not at all.
    std::vector<std::pair<std::string, std::string>> outputs;
    if (!no_stats && !stats_path.empty())
      outputs.emplace_back(stats_option->count() > 0 ? "--output" : "the statistics (default --output -)", stats_path);
    if (!rdf_path.empty()) outputs.emplace_back("--rdf", rdf_path);
    if (!json_path.empty()) outputs.emplace_back("--json", json_path);
    if (!report_path.empty()) outputs.emplace_back("--report", report_path);
    if (!summary_path.empty()) outputs.emplace_back("--summary", summary_path);
    if (points_dir == "-") outputs.emplace_back("--points", points_dir);
    const bool points_to_files = !points_dir.empty() && points_dir != "-";
    const bool points_folder = points_to_files && !one_point_file;
    if (points_to_files)
      for (dfvn::Method m : config.methods) {
        outputs.emplace_back("--points (" + point_file_name(m) + ")", point_file(m));
        outputs.emplace_back("--points (" + point_file_name(m) + ".json)", dfvn::point_sidecar_path(point_file(m)));
      }
    dfvn::check_outputs(outputs, points_folder ? std::vector<std::string>{points_dir} : std::vector<std::string>{},
                        transform.input_files());
    for (const std::string& warning : dfvn::sampling_warnings(config))
      if (config.count > 0 || !progress.quiet)  // a count the user chose deserves its warning even with -q
        std::fprintf(stderr, "%s: %s: %s\n", kProgram, config.count > 0 ? "warning" : "note", warning.c_str());

    const dfvn::PointFormat point_format = dfvn::parse_point_format(format);
    if (config.stream) return run_streamed(point_format);
    std::vector<double> stage_weights;  // every realization runs the same stages
    for (int r = 0; r < realizations; ++r)
      for (double w : dfvn::sampling_stage_weights(config)) stage_weights.push_back(w);
    dfvn::ProgressReporter* reporter = progress.make(std::move(stage_weights));
    std::string stats = dfvn::stats_csv_header();
    std::string rdf = dfvn::rdf_csv_header();
    std::vector<std::string> realization_rows;
    std::vector<dfvn::SamplingRealization> runs;
    // --sets M > 1 with --points: each method's M sets, written into one file once all are made.
    std::vector<std::vector<dfvn::PointSet>> sets_of(config.methods.size());
    std::vector<dfvn::MethodResult> first_results;  // with --sets M > 1: what the sidecars describe
    const bool one_file_of_sets = !points_dir.empty() && realizations > 1;
    // Realization r uses seed s + r; every statistic is then summarised as mean and sd per method.
    for (int realization = 0; realization < realizations; ++realization) {
      config.seed = common.seed + static_cast<std::uint64_t>(realization);
      auto results = dfvn::run_sampling(config, false, reporter->callback(), [&](const dfvn::MethodResult& r) {
        if (one_file_of_sets) {
          sets_of[method_index(r.plan.method)].push_back(r.points);
        } else if (!points_dir.empty()) {
          reporter->finish();  // the live line stays off standard output's terminal
          dfvn::write_point_file(point_file(r.plan.method), r.points, point_format);
          write_sidecar(r, {config.seed}, {r.point_count});
        }
      });
      for (const auto& r : results) {
        if (one_file_of_sets && realization == 0) first_results.push_back(r);
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
    if (one_file_of_sets) {
      // Every file's sets are checked (npy: one size) before the first file is written.
      for (std::size_t m = 0; m < sets_of.size(); ++m) {
        try {
          dfvn::check_point_sets_fit(sets_of[m], point_format);
        } catch (const std::invalid_argument& e) {
          throw std::invalid_argument(fmt::format("--points: {}'s {} sets: {}", dfvn::to_string(config.methods[m]),
                                                  sets_of[m].size(), e.what()));
        }
      }
      std::vector<std::uint64_t> seeds;
      for (int r = 0; r < realizations; ++r) seeds.push_back(common.seed + static_cast<std::uint64_t>(r));
      config.seed = common.seed;
      for (std::size_t m = 0; m < sets_of.size(); ++m) {
        dfvn::write_point_sets_file(point_file(config.methods[m]), sets_of[m], point_format);
        std::vector<std::uint64_t> counts;
        for (const dfvn::PointSet& set : sets_of[m]) counts.push_back(set.size());
        write_sidecar(first_results[m], seeds, counts);
      }
    }
    const std::string summary =
        dfvn::realization_summary_csv(stats.substr(0, stats.find('\n')), realization_rows, {"dim", "grid", "method"}, "seed");
    if (!summary_path.empty()) dfvn::write_file_atomically(summary_path, summary);
    config.seed = common.seed;
    if (!json_path.empty()) dfvn::write_file_atomically(json_path, dfvn::sampling_json(config, runs, !no_timing));
    if (!rdf_path.empty()) dfvn::write_file_atomically(rdf_path, rdf);
    if (!no_stats && !stats_path.empty()) dfvn::write_file_atomically(stats_path, stats);
    report_verdict(runs);
  }

  // --report's Markdown, and its summary on standard error unless -q.
  void report_verdict(const std::vector<dfvn::SamplingRealization>& runs) const {
    if (no_stats) return;
    if (!report_path.empty()) dfvn::write_file_atomically(report_path, dfvn::verdict_markdown(config, runs));
    if (!progress.quiet)
      for (const std::string& line : dfvn::verdict_summary(config, runs)) std::fprintf(stderr, "%s: %s\n", kProgram, line.c_str());
  }

  // The run's one domain (--domain, --on sphere, and what the boundary options and the paper protocol imply),
  // then the protocol and what it fixes (SampleConfig::use_protocol).
  void choose_domain(dfvn::Protocol chosen_protocol) {
    const bool paper = chosen_protocol == dfvn::Protocol::paper;
    if (on_option->count() > 0 && on == "sphere") {
      if (domain_option->count() > 0 && domain != "sphere")
        throw std::invalid_argument("--on sphere is --domain sphere; it contradicts --domain " + domain);
      domain = "sphere";
    } else if (domain_option->count() == 0) {
      // Options that only mean something at a boundary, and the paper's protocol, put the run in the cube.
      const bool asks_for_a_boundary =
          domain_mode == "drop" || bound_options[0]->count() > 0 || bound_options[1]->count() > 0 || paper;
      if (asks_for_a_boundary) domain = "cube";
    }
    if (paper && domain != "cube")
      throw std::invalid_argument("--protocol paper is Section 5.1, in the cube: --domain " + domain + " needs --protocol fair");
    if (paper && domain_mode_option->count() > 0 && domain_mode != "drop")
      throw std::invalid_argument("--protocol paper drops the CNJ points that leave the cube: --domain-mode " + domain_mode +
                                  " needs --protocol fair");
    config.cnj.domain = dfvn::parse_domain_kind(domain);
    config.cnj.domain_mode = dfvn::parse_domain_mode(domain_mode);
    config.cnj.bound = dfvn::parse_bound(bound);
    if (periodic && config.cnj.domain != dfvn::DomainKind::torus)
      throw std::invalid_argument("--periodic measures on the torus; the " + domain +
                                  "'s sets are measured in its own metric (drop --periodic, or use --domain torus)");
    config.use_protocol(chosen_protocol);
  }

  // --stream when asked, or when the in-memory sets would exceed the memory limit and the run can stream.
  void choose_streaming() {
    if (!stream && config.stream_slabs > 0) throw std::invalid_argument("--slabs applies to --stream, which is not given");
    if (stream || realizations > 1 || !dfvn::stream_refusal(config).empty()) {
      config.stream = stream;
      if (stream && realizations > 1)
        throw std::invalid_argument(fmt::format("--stream makes one realization; drop --sets {}", realizations));
      return;
    }
    double need = 0.0, limit = 0.0;
    try {  // a size no lattice holds: validate() says so in its own words
      need = dfvn::estimated_peak_bytes(config);
      limit = dfvn::memory_limit_bytes(config);
      // Only when the slabs fit: otherwise validate() gives the in-memory refusal, which names -n or --grid.
      if (need <= limit || dfvn::streamed_peak_bytes(config, dfvn::stream_slab_count(config, 0)) > limit) return;
    } catch (const std::invalid_argument&) {
      return;
    }
    config.stream = true;
    streaming_note = fmt::format("the point sets need about {} of memory (limit {})", dfvn::byte_size(need),
                                 dfvn::byte_size(limit));
  }

  // --boundary-spacings W: the help's "at most a quarter of the cube's side" (the field clamped a wider width
  // to a quarter silently). Only where it applies (conformant cube or ball; refused above elsewhere).
  void check_boundary_spacings() const {
    if (bound_options[1]->count() == 0) return;
    const double spacing = dfvn::cnj_lattice(config.lattice(), config.cnj.domain).spacing();
    if (config.cnj.boundary_width * spacing > 0.25)
      throw std::invalid_argument(fmt::format("--boundary-spacings {:g}: {:g} spacings of {:g} is {:g} of the side, more than "
                                              "a quarter: at most {:g} spacings with --grid {}",
                                              config.cnj.boundary_width, config.cnj.boundary_width, spacing,
                                              config.cnj.boundary_width * spacing, 0.25 / spacing, config.grid));
  }

  // A streamed run's temporary files must fit in $TMPDIR (and its open files in the limit): refused up front,
  // before any output is made; the note of the automatic switch comes after, when the run goes ahead.
  void check_streaming_space() const {
    if (!config.stream) return;
    const std::string why = dfvn::stream_temporaries_refusal(config, dfvn::stream_slab_count(config, config.stream_slabs));
    if (!why.empty()) throw std::invalid_argument(streaming_note.empty() ? why : streaming_note + ", and " + why);
    if (!streaming_note.empty())
      std::fprintf(stderr, "%s: note: %s: streaming them in slabs (--stream)\n", kProgram, streaming_note.c_str());
  }

  void run_streamed(dfvn::PointFormat point_format) {
    std::vector<double> stage_weights;
    for (double w : dfvn::sampling_stage_weights(config)) stage_weights.push_back(w);
    dfvn::ProgressReporter* reporter = progress.make(std::move(stage_weights));
    std::function<std::string(dfvn::Method)> path;
    if (!points_dir.empty()) path = [this](dfvn::Method m) { return point_file(m); };
    const auto results = dfvn::run_streamed_sampling(config, config.stream_slabs, path, point_format, reporter->callback());
    reporter->complete();
    if (!points_dir.empty() && points_dir != "-")
      for (const auto& r : results) write_sidecar(r, {config.seed}, {r.point_count});
    std::string stats = dfvn::stats_csv_header();
    std::string rdf = dfvn::rdf_csv_header();
    for (const auto& r : results) {
      stats += dfvn::stats_csv_row(config, r, !no_timing);
      rdf += dfvn::rdf_csv_rows(config, r);
    }
    if (!json_path.empty())
      dfvn::write_file_atomically(json_path, dfvn::sampling_json(config, {{config.seed, results}}, !no_timing));
    if (!rdf_path.empty()) dfvn::write_file_atomically(rdf_path, rdf);
    if (!no_stats && !stats_path.empty()) dfvn::write_file_atomically(stats_path, stats);
    report_verdict({{config.seed, results}});
  }

  // Options that only make sense together (the outputs themselves: dfvn::check_outputs).
  void check_output_options() const {
    if (format_option->count() > 0 && points_dir.empty())
      throw std::invalid_argument("--format " + format + " applies to --points, which is not given");
    if (no_stats && points_dir.empty()) throw std::invalid_argument("--no-stats writes only point sets: give --points DIR (or -)");
    if (no_stats && (stats_option->count() > 0 || !rdf_path.empty() || !report_path.empty()))
      throw std::invalid_argument("--no-stats computes no statistics: drop --output, --rdf and --report");
    // -o is the statistics CSV: a point file's name there is the old mistake of writing statistics
    // where points were meant to go (issue 24).
    if (stats_option->count() > 0 && looks_like_point_file(stats_path))
      throw std::invalid_argument("-o/--output is the statistics CSV, not a point file (" +
                                  dfvn::quote_for_message(stats_path, dfvn::kMaxPathEchoChars) +
                                  "); write point sets with --points");
    if (config.stream && points_dir == "-" && config.cnj.domain_mode == dfvn::DomainMode::drop &&
        (format == "npy" || format == "bin") &&
        std::find(config.methods.begin(), config.methods.end(), dfvn::Method::cnj) != config.methods.end())
      throw std::invalid_argument("--stream --points - --format " + format + ": drop mode's point count is known only at "
                                  "the end and goes first in the file, which needs a regular file (or --format dat, csv)");
    if (!summary_path.empty() && realizations < 2)
      throw std::invalid_argument("--summary summarises the sets of --realizations R: give R >= 2");
    if (!summary_path.empty() && no_stats) throw std::invalid_argument("--no-stats computes no statistics to summarise");
    if (realizations > 1 && !rdf_path.empty())
      throw std::invalid_argument("--rdf takes one realization; drop it or --sets");
    if (realizations > 1 && !points_dir.empty() && format == "csv")
      throw std::invalid_argument(fmt::format("--points writes the {} sets of --sets into one file: --format dat, npy or bin "
                                              "(csv holds one set)",
                                              realizations));
    if (realizations > 1 && !points_dir.empty() && format == "npy" &&
        std::find(config.methods.begin(), config.methods.end(), dfvn::Method::pds) != config.methods.end())
      throw std::invalid_argument("--format npy holds the sets of --sets as one array (sets, points, N), but pds's sets "
                                  "differ in size from seed to seed: use dat or bin");
    if (points_dir == "-" && config.methods.size() != 1)
      throw std::invalid_argument(fmt::format("--points - writes one point set to standard output; --methods names {}",
                                              config.methods.size()));
  }

  // The point file's sidecar (io/point_sidecar.hpp): its domain and what made it, for `stats` to measure it
  // again the same way. None for standard output.
  void write_sidecar(const dfvn::MethodResult& r, const std::vector<std::uint64_t>& seeds,
                     const std::vector<std::uint64_t>& points_per_set) const {
    const std::string path = dfvn::point_sidecar_path(point_file(r.plan.method));
    if (path.empty()) return;
    dfvn::write_file_atomically(path, dfvn::point_sidecar_json(r.plan.domain, config.dimension, points_per_set,
                                                               dfvn::point_set_made_by_json(config, r, seeds)));
  }

  // With -n, PDS that saturated before the count: say so (the saturated column has it in every run).
  static void report_saturation(const dfvn::MethodResult& r) {
    if (r.facts.saturated && *r.facts.saturated)
      std::fprintf(stderr, "%s: warning: pds saturated at %llu of %llu points (radius %g): the domain holds no more\n",
                   kProgram, static_cast<unsigned long long>(r.point_count),
                   static_cast<unsigned long long>(r.plan.requested), *r.facts.radius);
  }

  std::size_t method_index(dfvn::Method m) const {
    return static_cast<std::size_t>(std::find(config.methods.begin(), config.methods.end(), m) - config.methods.begin());
  }

  // The extensions of point files (UTK's .pts and .bin included), matched without regard to case.
  static bool looks_like_point_file(const std::string& path) {
    std::string extension = std::filesystem::path(path).extension().string();
    for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    for (const char* point_extension : {".dat", ".npy", ".bin", ".txt", ".pts"})
      if (extension == point_extension) return true;
    return false;
  }

  std::string point_file_name(dfvn::Method m) const {
    return one_point_file ? std::filesystem::path(points_dir).filename().string()
                          : std::string(dfvn::to_string(m)) + "." + format;
  }
  std::string point_file(dfvn::Method m) const {
    return points_dir == "-" || one_point_file ? points_dir
                                               : (std::filesystem::path(points_dir) / point_file_name(m)).string();
  }

  // The point format an extension names, as UTK's tools read them (.txt and .pts are its text format);
  // empty for any other name, which is a folder.
  static std::string point_format_of(const std::string& path) {
    std::string extension = std::filesystem::path(path).extension().string();
    for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (extension == ".csv" || extension == ".npy" || extension == ".dat" || extension == ".bin") return extension.substr(1);
    if (extension == ".txt" || extension == ".pts") return "dat";
    return {};
  }

  // --points FILE.ext with one method: that file, in the extension's format (UTK's -o habit); with
  // several methods such a name is refused, since a folder named like a file is what nobody means.
  // '-' (standard output) without -o: the statistics are not written there.
  void choose_point_file() {
    if (points_dir == "-" && stats_option->count() == 0) {
      if (json_path.empty() && rdf_path.empty() && report_path.empty()) no_stats = true;
      stats_path.clear();
    }
    const std::string extension_format = point_format_of(points_dir);
    if (points_dir.empty() || points_dir == "-" || extension_format.empty()) return;
    if (config.methods.size() != 1)
      throw std::invalid_argument(fmt::format("--points {} names one file, but --methods names {} methods: give one method, "
                                              "or a folder for one file each",
                                              dfvn::quote_for_message(points_dir, dfvn::kMaxPathEchoChars),
                                              config.methods.size()));
    if (format_option->count() > 0 && format != extension_format)
      throw std::invalid_argument("--format " + format + " contradicts the extension of --points " +
                                  dfvn::quote_for_message(points_dir, dfvn::kMaxPathEchoChars) + " (" + extension_format + ")");
    format = extension_format;
    one_point_file = true;
  }
};

}  // namespace

std::unique_ptr<Subcommand> add_sample_command(CLI::App& app) { return registered<SampleCommand>(app); }

}  // namespace dfvn_cli
