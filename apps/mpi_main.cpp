// dfvn-sample-mpi: `dfvn-sample sample --stream` over MPI ranks (src/mpi/mpi_sampling.hpp). Parsing and
// glue only: the options of the streamable subset of sample, with sample's names and defaults; rank 0
// writes the CSVs and the JSON and shows the progress.
#include <mpi.h>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "dfvn/core/message_text.hpp"
#include "dfvn/core/seeds.hpp"
#include "dfvn/experiment/experiment.hpp"
#include "dfvn/experiment/json_report.hpp"
#include "dfvn/io/atomic_file.hpp"
#include "dfvn/io/point_sidecar.hpp"
#include "dfvn/io/point_file.hpp"
#include "dfvn/mpi/mpi_sampling.hpp"
#include "dfvn/sampling/method.hpp"

#include "help_format.hpp"
#include "options.hpp"

namespace {

constexpr const char* kMpiProgram = "dfvn-sample-mpi";

struct Options {
  dfvn_cli::CommonOptions common;
  dfvn_cli::ProgressOptions progress;
  dfvn::SampleConfig config;
  std::string methods = "cnj,jitter,random,sobol";
  std::string protocol = "fair";
  bool periodic = false;
  std::string knn = "nanoflann";
  std::string integrator = "rk4";
  std::string noise{dfvn::to_string(dfvn::kDefaultNoiseBasis)};
  std::string reproject = "gauss-newton";
  std::string scramble = "owen";
  std::string stats_path = "-";
  std::string rdf_path;
  std::string json_path;
  std::string points_dir;
  std::string format = "npy";
  std::string domain{dfvn::to_string(dfvn::kDefaultDomainKind)};
  std::string domain_mode = "conformant";
  std::uint64_t count = 0;
  bool no_stats = false;
  bool no_timing = false;
  CLI::Option* domain_option = nullptr;
  CLI::Option* format_option = nullptr;
  CLI::Option* stats_option = nullptr;
};

void add_options(CLI::App& app, Options& o) {
  dfvn::SampleConfig& config = o.config;
  dfvn_cli::add_dimension_option(app, config.dimension, "Dimension N (2..8)")->capture_default_str();
  CLI::Option* grid = app.add_option("--grid", config.grid, "Lattice points per axis K (>= 2); K^N points")
                          ->capture_default_str()
                          ->check(CLI::Range(2, 1 << 30));
  app.add_option("-n,--count", o.count,
                 "Points per set instead of --grid: cnj and jitter use the K whose K^N is nearest, random and sobol\n"
                 "make exactly COUNT. Not given: --grid")
      ->check(CLI::Range(std::uint64_t{2}, std::uint64_t{1} << 40))
      ->excludes(grid);
  app.add_option("--methods", o.methods,
                 "Comma list of methods, of cnj, jitter, random, sobol (the index-addressable ones; pds,\n"
                 "jitter-matched, halton and lhs are refused)")
      ->capture_default_str();
  app.add_option("--protocol", o.protocol, "fair or paper, as in 'dfvn-sample sample'")
      ->capture_default_str()
      ->check(CLI::IsMember({"fair", "paper", "unit"}));
  o.stats_option = app.add_option("-o,--output,--stats", o.stats_path,
                                  "The statistics CSV, written by rank 0 ('-' = standard output); the same bytes as\n"
                                  "'dfvn-sample sample --stream' with the same options")
                       ->capture_default_str();
  app.add_option("--points", o.points_dir,
                 "Write each method's points to DIR/<method>.<format>, one file written by every rank at once\n"
                 "(MPI-IO); not '-'. Not given: no point files");
  o.format_option = app.add_option("--format", o.format, "Point file format (of --points): npy, bin, dat or csv, as in sample")
                        ->capture_default_str()
                        ->check(CLI::IsMember({"csv", "npy", "dat", "bin"}));
  app.add_flag("--no-stats", o.no_stats, "Generate the point sets only (needs --points): no statistics and no stats CSV");
  app.add_flag("--periodic", o.periodic,
               "Measure on the torus (minimum-image distances, the halos wrapping from the last rank to the first):\n"
               "what --domain torus, the default, does; refused with --domain cube, as in sample");
  app.add_option("--rdf", o.rdf_path,
                 "Also compute radial distribution functions and write them to this CSV (dim,method,r,g), by rank 0:\n"
                 "the same bytes as 'dfvn-sample sample --stream --rdf'");
  app.add_option("--rdf-max", config.rdf.r_max, "Largest r of the RDF; 0 = 2.5 mean spacings")
      ->capture_default_str()
      ->check(dfvn_cli::kNonNegativeFinite);
  app.add_option("--rdf-bins", config.rdf.bins, "Number of RDF bins")->capture_default_str()->check(CLI::Range(1, 100000));
  app.add_option("--rdf-queries", config.rdf.max_queries, "RDF query points: a seeded subset of about this many (0 = all points)")
      ->capture_default_str()
      ->check(dfvn_cli::kUnsignedInteger);
  app.add_option("--json", o.json_path,
                 "Also write the run as JSON, by rank 0 ('-' = standard output): the same bytes as 'dfvn-sample sample\n"
                 "--stream --json' (its \"program\" is \"dfvn-sample\", the experiment's, so that the files compare\n"
                 "equal)");
  app.add_flag("--no-timing", o.no_timing,
               "Leave the seconds columns (seconds_generate, seconds_stats) empty: runs give identical files");
  app.add_option("--knn", o.knn, "KD-tree backend: nanoflann or flann (identical distances)")
      ->capture_default_str()
      ->check(CLI::IsMember({"nanoflann", "flann"}));
  app.add_option("--integrator", o.integrator, "CNJ integrator: euler or rk4")
      ->capture_default_str()
      ->check(CLI::IsMember({"euler", "rk4"}));
  app.add_option("--steps", config.cnj.trace.steps,
                 "CNJ integration steps M; 0 = the domain's (as in sample: the free field's on the torus or in drop\n"
                 "mode, 1 in the conformant cube)")
      ->capture_default_str()
      ->check(CLI::Range(0, dfvn::CnjOptions::kMaxSteps));
  app.add_option("--step-scale", config.cnj.step_scale,
                 "CNJ trace time t = C * dbar(N) * lattice spacing, as in sample")
      ->capture_default_str()
      ->check(dfvn_cli::kStepScale);
  app.add_option("--cycles-per-spacing", config.cnj.frequency, "CNJ noise frequency C in cycles per lattice spacing, as in sample")
      ->capture_default_str()
      ->check(dfvn_cli::kNoiseFrequency);
  dfvn_cli::add_noise_option(app, o.noise, false);
  app.add_option("--reproject", o.reproject, "CNJ reprojection after each step: none, newton or gauss-newton")
      ->capture_default_str()
      ->check(CLI::IsMember({"none", "newton", "gauss-newton"}));
  app.add_option("--reproject-iters", config.cnj.trace.reproject_iterations, "CNJ reprojection iterations R at most")
      ->capture_default_str()
      ->check(CLI::Range(0, 1000));
  o.domain_option = app.add_option("--domain", o.domain,
                                   "Where every method's points live and are measured: torus or cube (the ball and the\n"
                                   "sphere are refused). Not given: torus, or cube with --domain-mode drop or --protocol paper")
                        ->capture_default_str()
                        ->check(CLI::IsMember({"torus", "cube", "ball"}));
  app.add_option("--domain-mode", o.domain_mode, "conformant or drop, as in sample")
      ->capture_default_str()
      ->check(CLI::IsMember({"conformant", "drop"}));
  app.add_option("--scramble", o.scramble, "Sobol scrambling: owen or none")
      ->capture_default_str()
      ->check(CLI::IsMember({"owen", "none"}));
  app.add_option("--max-memory", config.max_memory_gib,
                 "Memory limit in GiB of one process (checked as sample --stream checks a slab); 0 = 80% of the machine's")
      ->capture_default_str()
      ->check(dfvn_cli::kNonNegativeFinite);
  app.add_option("--slabs", config.stream_slabs,
                 "Slabs, as sample --stream's (a divisor of K for cnj and jitter), rank r of P taking slabs\n"
                 "[r S / P, (r + 1) S / P): with fewer slabs than ranks some ranks make no points. 0 = the smallest\n"
                 "valid count at least the ranks and sample --stream's automatic count. The output does not depend\n"
                 "on it, nor on the ranks or threads")
      ->capture_default_str()
      ->check(CLI::Range(0, 1 << 30));
  o.progress.add_to(app);
  o.progress.program = kMpiProgram;
  dfvn_cli::add_common_options(app, o.common);
}

// Turns the parsed options into the configuration, as 'dfvn-sample sample --stream' does.
void configure(Options& o) {
  dfvn::SampleConfig& config = o.config;
  config.seed = o.common.seed;
  config.threads = o.common.threads;
  if (o.protocol == "unit")
    throw std::invalid_argument("--protocol unit is now --protocol fair (the default) with --domain cube");
  const dfvn::Protocol protocol = dfvn::parse_protocol(o.protocol);
  config.knn = dfvn::parse_knn_backend(o.knn);
  config.scramble = dfvn::parse_scramble(o.scramble);
  config.cnj.trace.integrator = dfvn::parse_integrator(o.integrator);
  config.cnj.noise = dfvn::parse_noise_basis(o.noise);
  config.cnj.trace.reprojection = dfvn::parse_reprojection(o.reproject);
  if (o.domain_option->count() == 0 && (o.domain_mode == "drop" || protocol == dfvn::Protocol::paper)) o.domain = "cube";
  if (protocol == dfvn::Protocol::paper && o.domain != "cube")
    throw std::invalid_argument("--protocol paper is Section 5.1, in the cube: --domain " + o.domain + " needs --protocol fair");
  config.cnj.domain = dfvn::parse_domain_kind(o.domain);
  config.cnj.domain_mode = dfvn::parse_domain_mode(o.domain_mode);
  if (o.periodic && config.cnj.domain != dfvn::DomainKind::torus)
    throw std::invalid_argument("--periodic measures on the torus; the " + o.domain +
                                "'s sets are measured in its own metric (drop --periodic, or use --domain torus)");
  config.use_protocol(protocol);
  config.methods.clear();
  for (const auto& name : CLI::detail::split(o.methods, ','))
    config.methods.push_back(dfvn::parse_method(CLI::detail::trim_copy(name)));
  if (o.count > 0) {
    config.count = o.count;
    config.grid = dfvn::grid_for_count(config.dimension, o.count);
  }
  config.compute_statistics = !o.no_stats;
  config.compute_rdf = !o.rdf_path.empty();
  config.stream = true;
  if (o.format_option->count() > 0 && o.points_dir.empty())
    throw std::invalid_argument("--format " + o.format + " applies to --points, which is not given");
  if (o.no_stats && o.points_dir.empty()) throw std::invalid_argument("--no-stats writes only point sets: give --points DIR");
  if (o.no_stats && (o.stats_option->count() > 0 || !o.rdf_path.empty()))
    throw std::invalid_argument("--no-stats computes no statistics: drop --output and --rdf");
  if (o.points_dir == "-")
    throw std::invalid_argument("--points -: every rank writes its part of one file (MPI-IO), which needs a directory");
}

std::string point_file(const Options& o, dfvn::Method m) {
  return (std::filesystem::path(o.points_dir) / (std::string(dfvn::to_string(m)) + "." + o.format)).string();
}

int run(Options& o, int rank, MPI_Comm comm) {
  // The options first (alike on every rank: rank 0 reports), then the outputs (and --points' folder,
  // made) by rank 0, before any work.
  int ranks = 1;
  MPI_Comm_size(comm, &ranks);
  try {
    dfvn::check_mpi_run(o.config, o.config.stream_slabs, ranks);
  } catch (const std::exception&) {
    if (rank == 0) throw;
    throw dfvn::ReportedElsewhere();
  }
  std::string problem;
  if (rank == 0) {
    try {
      std::vector<std::pair<std::string, std::string>> outputs;
      if (!o.no_stats) outputs.emplace_back("--output", o.stats_path);
      if (!o.rdf_path.empty()) outputs.emplace_back("--rdf", o.rdf_path);
      if (!o.json_path.empty()) outputs.emplace_back("--json", o.json_path);
      if (!o.points_dir.empty())
        for (dfvn::Method m : o.config.methods) {
          outputs.emplace_back("--points", point_file(o, m));
          outputs.emplace_back("--points (sidecar)", dfvn::point_sidecar_path(point_file(o, m)));
        }
      dfvn::check_outputs(outputs, o.points_dir.empty() ? std::vector<std::string>{} : std::vector<std::string>{o.points_dir});
    } catch (const std::exception& e) {
      problem = e.what();
    }
  }
  int bad = !problem.empty();
  MPI_Bcast(&bad, 1, MPI_INT, 0, comm);
  if (bad) {
    if (rank == 0) throw std::runtime_error(problem);
    throw dfvn::ReportedElsewhere();
  }
  std::function<std::string(dfvn::Method)> path;
  if (!o.points_dir.empty()) path = [&o](dfvn::Method m) { return point_file(o, m); };
  int fail_rank = -1;
  if (const char* f = std::getenv("DFVN_MPI_FAIL_RANK")) fail_rank = std::atoi(f);
  // Progress from rank 0 (its share of the work), with sample --stream's stages.
  dfvn::ProgressReporter* reporter = nullptr;
  if (rank == 0) reporter = o.progress.make(dfvn::sampling_stage_weights(o.config));
  const auto results = dfvn::run_mpi_sampling(comm, o.config, o.config.stream_slabs, path,
                                              dfvn::parse_point_format(o.format),
                                              reporter ? reporter->callback() : dfvn::StageProgress{}, fail_rank);
  if (rank == 0) {
    reporter->complete();
    // sample --stream's files, in its order.
    std::string stats = dfvn::stats_csv_header();
    std::string rdf = dfvn::rdf_csv_header();
    for (const auto& r : results) {
      stats += dfvn::stats_csv_row(o.config, r, !o.no_timing);
      rdf += dfvn::rdf_csv_rows(o.config, r);
    }
    if (!o.json_path.empty())
      dfvn::write_file_atomically(o.json_path, dfvn::sampling_json(o.config, {{o.config.seed, results}}, !o.no_timing));
    if (!o.rdf_path.empty()) dfvn::write_file_atomically(o.rdf_path, rdf);
    if (!o.no_stats) dfvn::write_file_atomically(o.stats_path, stats);
    // Each point file's sidecar, as sample --stream writes it.
    if (!o.points_dir.empty())
      for (const auto& r : results)
        dfvn::write_file_atomically(dfvn::point_sidecar_path(point_file(o, r.plan.method)),
                                    dfvn::point_sidecar_json(r.plan.domain, o.config.dimension, {r.point_count},
                                                             dfvn::point_set_made_by_json(o.config, r, {o.config.seed})));
  }
  return 0;
}

// One line on stderr, as dfvn-sample's fail(): control bytes and newlines (CLI11 echoes values as given)
// escaped.
void report_error(const std::string& message) {
  std::fprintf(stderr, "%s: error: %s\n", kMpiProgram, dfvn::escape_bytes(message, false).c_str());
}

}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  CLI::App app{"dfvn-sample-mpi: 'dfvn-sample sample --stream' over MPI ranks (mpirun -np P dfvn-sample-mpi ...):\n"
               "cnj, jitter, random and sobol in slabs of the lattice's last axis, contiguous slabs per rank, one\n"
               "point file written by all ranks (MPI-IO), and the one-process run's point files, statistics CSV,\n"
               "--rdf CSV and --json byte for byte (in the box and, with --periodic, on the torus), whatever the\n"
               "number of ranks or threads.",
               kMpiProgram};
  dfvn_cli::use_help_format(app);
  app.set_version_flag("--version", std::string(kMpiProgram) + " " + DFVN_VERSION);
  Options options;
  add_options(app, options);
  dfvn::remove_temporaries_on_signals();
  int status = 0;
  bool configured = false;
  try {  // alike on every rank: rank 0 reports
    app.parse(argc, argv);
    configure(options);
    configured = true;
  } catch (const CLI::CallForHelp& e) {
    if (rank == 0) status = app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    if (rank == 0) status = app.exit(e);
  } catch (const CLI::ParseError& e) {
    if (rank == 0) report_error(std::string(e.what()) + " (run with --help for the options)");
    status = 2;
  } catch (const std::exception& e) {
    if (rank == 0) report_error(e.what());
    status = 1;
  }
  if (configured) {
    try {  // the run's errors reach one rank (the lowest that failed), the others ReportedElsewhere
      status = run(options, rank, MPI_COMM_WORLD);
    } catch (const dfvn::ReportedElsewhere&) {
      status = 1;
    } catch (const std::exception& e) {
      report_error(e.what());
      status = 1;
    }
  }
  MPI_Finalize();
  return status;
}
