// dfvn-sample stats: statistics of a point file (stats/point_set_statistics.hpp).
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "dfvn/core/message_text.hpp"
#include "dfvn/core/point_set.hpp"
#include "dfvn/experiment/json_report.hpp"
#include "dfvn/experiment/realizations.hpp"
#include "dfvn/io/atomic_file.hpp"
#include "dfvn/io/csv.hpp"
#include "dfvn/io/point_reader.hpp"
#include "dfvn/io/point_sidecar.hpp"
#include "dfvn/plot/gnuplot.hpp"
#include "dfvn/stats/distance_scale.hpp"
#include "dfvn/stats/point_set_statistics.hpp"
#include "dfvn/stats/radial_distribution.hpp"
#include "dfvn/stats/spectrum.hpp"

#include "options.hpp"

namespace dfvn_cli {
namespace {

// Standard input's stand-in among the inputs.
constexpr const char* kStandardInput = "-";

struct StatsCommand : Subcommand {
  CommonOptions common;
  std::vector<std::string> inputs;
  std::string format;
  int dimension = 0;
  std::string rdf_path;
  dfvn::RdfOptions rdf;
  std::string output = "-";
  std::string knn = "nanoflann";
  double domain_side = 1.0;
  std::string spectrum_prefix;
  int spectrum_frequency = 0;  // 0: dfvn::default_spectrum_frequency
  std::string json_path;
  std::string summary_path;
  bool discrepancy = false;
  bool no_timing = false;
  bool periodic = false;
  std::string domain;  // empty: each input's sidecar's, else the cube
  ProgressOptions progress;
  CLI::Option* output_option = nullptr;
  CLI::Option* side_option = nullptr;

  void add_to(CLI::App& parent) {
    CLI::App* cmd = parent.add_subcommand(
        "stats",
        "Statistics of any point set: CSV, NPY, dat (UTK, pbrt) or UTK's .bin\n\n"
        "Statistics of any point set in [0,S]^N, N = 1..8: nearest-neighbour summary and, with --discrepancy, the\n"
        "CD, WD, MD and L2-star discrepancies (as scipy.stats.qmc.discrepancy). One CSV row per set of every\n"
        "input (columns input, set); --summary writes the mean, sd and standard error over each input's sets.");
    // A file or '-' (standard input): one that cannot be read is bad data (exit 1), said by the reader.
    cmd->add_option("-i,--input,inputs", inputs,
                    "Point file to read, as -i/--input FILE (repeatable) and/or positional FILE...; '-' = standard input (once;\n"
                    "needs --format). CSV (optional header), NPY float64/float32 (points, N) or (sets, points, N),\n"
                    "dat (whitespace-separated, '#' lines between sets) or UTK's binary .bin (one record a set)")
        ->required()
        ->type_name("FILE|-");
    cmd->add_option("--format", format,
                    "Point file format (of --input): csv, npy, dat or bin, for every input; default: each file's extension (.txt = dat); required\n"
                    "with '-'")
        ->check(CLI::IsMember({"csv", "npy", "dat", "bin"}));
    cmd->add_option("-d,--dim", dimension,
                    "Dimension N of the points (1..8); every input must have it. Needed only for a .bin file that reads\n"
                    "whole in several dimensions (UTK's .bin does not store N); default: each file's own")
        ->check(CLI::Range(dfvn::kMinInputDimension, dfvn::kMaxInputDimension));
    cmd->add_option("--rdf", rdf_path,
                    "Also write the radial distribution function g(r) of every set here (CSV: input,set,dim,r,g; one\n"
                    "curve a set; 2D..8D; with --periodic on the torus)");
    cmd->add_option("--rdf-max", rdf.r_max, "Largest r of the RDF; 0 = 2.5 mean spacings")
        ->capture_default_str()
        ->check(kNonNegativeFinite);
    cmd->add_option("--rdf-bins", rdf.bins, "Number of RDF bins")->capture_default_str()->check(CLI::Range(1, 100000));
    cmd->add_option("--rdf-queries", rdf.max_queries,
                    "RDF query points: a subset of about this many, drawn with seed 1 in every set (0 = all points)")
        ->capture_default_str()
        ->check(kUnsignedInteger);
    side_option = cmd->add_option("--domain-side", domain_side,
                                  "The points lie in [0, S]^N (or the ball or sphere inscribed in it), S in [2^-1000,\n"
                                  "2^1000]. Default: the side the input's sidecar (FILE.json, written beside the point\n"
                                  "files of dfvn-sample) gives, else 1")
                      ->capture_default_str()
                      ->check(kDomainSide);
    cmd->add_option("--domain", domain,
                    "Where the points live and how they are measured: torus ([0,1)^N, [0,S)^N with --domain-side:\n"
                    "minimum-image distances), cube ([0,1]^N or [0,S]^N: Euclidean; the RDF edge-corrected), ball\n"
                    "(its inscribed ball) or sphere (S^{N-1} centred at the origin: the unit sphere, or of radius S/2\n"
                    "with --domain-side; geodesic distances).\n"
                    "Default: the input's sidecar's domain, else cube (with a warning when the points fill less\n"
                    "than 90% of the cube's volume)")
        ->check(CLI::IsMember({"torus", "cube", "ball", "sphere"}));
    cmd->add_flag("--discrepancy", discrepancy, "Also compute the four L2 discrepancies (O(points^2) work)");
    cmd->add_option("--knn", knn, "KD-tree backend: nanoflann or flann (not used with --periodic)")
        ->capture_default_str()
        ->check(CLI::IsMember({"nanoflann", "flann"}));
    cmd->add_flag("--periodic", periodic,
                  "Measure on the torus [0,S)^N: minimum-image nearest-neighbour distances (opposite faces\n"
                  "identified), as for sets made periodic (UTK's periodic samplers); the same as --domain torus");
    output_option = cmd->add_option("-o,--output", output, "Main output: the statistics CSV ('-' = standard output)")
                        ->capture_default_str();
    cmd->add_option("--json", json_path,
                    "Also write the statistics as JSON: every set's values and, for a file of several sets, their mean,\n"
                    "sd and standard error ('-' = standard output)");
    cmd->add_option("--summary", summary_path,
                    "Also write the summary over each input's sets as CSV ('-' = standard output): per input and\n"
                    "statistic the mean, sd and standard error over the sets (a column constant over them is not\n"
                    "summarised); for inputs of several sets");
    cmd->add_flag("--no-timing", no_timing,
                  "Leave the seconds column (seconds_stats) empty (and out of --json): identical files for identical input");
    cmd->add_option("--spectrum", spectrum_prefix,
                    "2D/3D sets: also write the power spectrum averaged over the file's sets: PREFIX.csv (k0..,power),\n"
                    "PREFIX_radial.csv (frequency,power,anisotropy_db,frequencies) and, with gnuplot, PREFIX.png");
    cmd->add_option("--spectrum-frequency", spectrum_frequency,
                    fmt::format("Largest integer frequency K of the spectrum ([-K,K]^N, cycles per domain side);\n"
                                "default: twice the lattice peak n^(1/N) of the sets' mean count n, rounded up (at most\n"
                                "{} in 2D, {} in 3D)",
                                dfvn::kMaxDefaultFrequency2d, dfvn::kMaxDefaultFrequency3d))
        ->check(CLI::Range(1, 512));
    progress.add_to(*cmd);
    add_threads_option(*cmd, common.threads);
    cmd->callback([this] { run(); });
  }

  // The sets of one input, each checked to lie in the domain; `owner` gets the input's index per set.
  void read_input(std::size_t index, dfvn::InputFormat input_format, std::vector<dfvn::PointSet>& sets,
                  std::vector<std::size_t>& owner, std::vector<std::string>& warnings) const {
    const std::string& input = inputs[index];
    const std::size_t first = sets.size();
    try {
      for (auto& table : dfvn::read_point_sets(input, input_format, dimension)) {
        if (dimension != 0 && table.dimension != dimension)
          throw dfvn::InputError(fmt::format("{}D points, not the {}D of --dim", table.dimension, dimension));
        sets.push_back(dfvn::PointSet{table.dimension, std::move(table.coordinates), domain_of(input, table.dimension)});
        owner.push_back(index);
        dfvn::check_point_set(sets.back());
        const bool chosen = !domain.empty() || periodic || side_option->count() > 0;
        if (!chosen && (input == kStandardInput || !dfvn::read_point_sidecar_domain(input)))
          if (std::string warning = sparse_warning(input, sets.back()); !warning.empty()) warnings.push_back(warning);
      }
    } catch (const std::exception& e) {
      fail(input_name(input) + (sets.size() == first ? ", " : fmt::format(", set {}: ", sets.size() - 1 - first)) + e.what());
    }
  }

  static std::string input_name(const std::string& input) { return input == kStandardInput ? "standard input" : input; }

  // Where an input's points live: the options' domain where given (--domain or --periodic, --domain-side),
  // the rest from the input's sidecar (io/point_sidecar.hpp), else the cube [0, 1]^N.
  dfvn::Domain domain_of(const std::string& input, int n) const {
    std::optional<dfvn::Domain> described;
    if (input != kStandardInput) described = dfvn::read_point_sidecar_domain(input, n);
    dfvn::Domain d = described.value_or(dfvn::Domain{dfvn::DomainKind::cube, 0.0, 1.0});
    if (!domain.empty()) {
      const dfvn::DomainKind kind = dfvn::parse_domain_kind(domain);
      if (!described || described->kind != kind) d = dfvn::Domain::unit(kind);
    }
    if (periodic) d.kind = dfvn::DomainKind::torus;
    if (side_option->count() > 0) {
      d.side = domain_side;
      d.lo = d.kind == dfvn::DomainKind::sphere ? -0.5 * domain_side : 0.0;
    }
    return d;
  }

  // A set measured in [0, 1]^N by default whose points fill little of it was probably made in another
  // box: its density-scaled statistics would mislead without a word.
  static std::string sparse_warning(const std::string& input, const dfvn::PointSet& set) {
    const int n = set.dimension;
    std::vector<double> lo(n, std::numeric_limits<double>::infinity()), hi(n, -std::numeric_limits<double>::infinity());
    for (std::size_t i = 0; i < set.size(); ++i)
      for (int j = 0; j < n; ++j) {
        lo[j] = std::min(lo[j], set.point(i)[j]);
        hi[j] = std::max(hi[j], set.point(i)[j]);
      }
    double fraction = 1.0;
    for (int j = 0; j < n; ++j) fraction *= (hi[j] - lo[j]) / set.domain.side;
    if (!(fraction < 0.9)) return {};
    return fmt::format("{} has no sidecar and its points span {:.0f}% of the volume of {}, where they are measured; give "
                       "--domain and --domain-side if they live elsewhere",
                       dfvn::quote_for_message(input_name(input), dfvn::kMaxPathEchoChars), 100.0 * fraction,
                       set.domain.describe(n));
  }

  void run() {
    if (periodic && !domain.empty() && domain != "torus")
      fail("--periodic measures on the torus; it contradicts --domain " + domain);
    if (std::count(inputs.begin(), inputs.end(), std::string(kStandardInput)) > 1)
      fail("standard input ('-') can be read once; it is named twice among the inputs");
    if (format.empty() && std::find(inputs.begin(), inputs.end(), kStandardInput) != inputs.end())
      fail("standard input ('-') has no extension to tell its format: give --format csv|npy|dat|bin");
    if (!json_path.empty() && inputs.size() > 1)
      fail(fmt::format("--json describes one input; {} are given", inputs.size()));
    std::vector<dfvn::InputFormat> input_formats;
    for (const std::string& input : inputs) {
      try {
        input_formats.push_back(format.empty() ? dfvn::input_format_from_path(input) : dfvn::parse_input_format(format));
      } catch (const std::exception& e) {
        fail(e.what());
      }
    }
    std::vector<dfvn::PointSet> sets;
    std::vector<std::size_t> owner;  // the input of each set
    std::vector<std::string> warnings;  // printed once the run has succeeded (an error stays one line)
    for (std::size_t i = 0; i < inputs.size(); ++i) read_input(i, input_formats[i], sets, owner, warnings);
    for (std::size_t s = 1; s < sets.size(); ++s)
      if (!spectrum_prefix.empty() && sets[s].dimension != sets.front().dimension)
        fail(fmt::format("--spectrum averages sets of one dimension; '{}' holds {}D points, '{}' {}D", inputs[owner.front()],
                         sets.front().dimension, inputs[owner[s]], sets[s].dimension));
    if (!spectrum_prefix.empty() && sets.front().dimension != 2 && sets.front().dimension != 3)
      fail(fmt::format("--spectrum needs 2D or 3D points; '{}' holds {}D points", inputs.front(), sets.front().dimension));
    if (!rdf_path.empty()) check_rdf(sets, owner);
    // Every output, checked together before the work: --output, --json, --rdf and the spectrum's three files.
    std::vector<std::pair<std::string, std::string>> outputs = {
        {output_option->count() > 0 ? "--output" : "the statistics (default --output -)", output}};
    if (!json_path.empty()) outputs.emplace_back("--json", json_path);
    if (!summary_path.empty()) outputs.emplace_back("--summary", summary_path);
    if (!rdf_path.empty()) outputs.emplace_back("--rdf", rdf_path);
    if (!spectrum_prefix.empty())
      for (const std::string& suffix : dfvn::spectrum_file_suffixes())
        outputs.emplace_back("--spectrum (" + std::filesystem::path(spectrum_prefix + suffix).filename().string() + ")",
                             spectrum_prefix + suffix);
    std::vector<std::pair<std::string, std::string>> input_files;
    for (const std::string& input : inputs) input_files.emplace_back("the input", input);
    dfvn::check_outputs(outputs, {}, input_files);
    if (!spectrum_prefix.empty()) dfvn::check_figure_prerequisites();
    dfvn::PointSetStatisticsOptions options;
    options.discrepancy = discrepancy;
    options.knn = dfvn::parse_knn_backend(knn);
    options.threads = common.threads;
    double mean_count = 0.0;
    for (const dfvn::PointSet& set : sets) mean_count += static_cast<double>(set.size()) / static_cast<double>(sets.size());
    const int spectrum_k = spectrum_frequency > 0 ? spectrum_frequency
                                                  : dfvn::default_spectrum_frequency(mean_count, sets.front().dimension);
    // The [k/n] counter: each set's statistics, then the spectrum, weighted by their expected costs.
    std::vector<double> stage_weights;
    for (const dfvn::PointSet& set : sets) {
      const std::vector<double> weights = dfvn::point_statistics_stage_weights(options, set.size(), set.dimension);
      stage_weights.insert(stage_weights.end(), weights.begin(), weights.end());
      // The set's RDF follows its statistics, weighed against their nearest-neighbour stage (the first).
      if (!rdf_path.empty()) stage_weights.push_back(weights.front() * dfvn::kRdfCostOverStatistics);
    }
    if (!spectrum_prefix.empty())
      stage_weights.push_back(dfvn::expected_spectrum_cost(sets, spectrum_k));
    dfvn::ProgressReporter* reporter = progress.make(std::move(stage_weights));
    std::string csv = dfvn::point_statistics_csv_header();
    std::string rdf_csv = "input,set,dim,r,g\n";
    std::vector<std::string> rows;
    dfvn::PointStatisticsRun run{inputs.front(), std::string(dfvn::to_string(input_formats.front())), domain_side, options, {}, {},
                                 !no_timing};
    for (std::size_t s = 0, in_input = 0; s < sets.size(); ++s, ++in_input) {
      if (s > 0 && owner[s] != owner[s - 1]) in_input = 0;  // sets are numbered within their input
      const std::string& input = inputs[owner[s]];
      // Each set's stages get its number, so that the [k/n] counter moves on between sets.
      const std::string set_label =
          sets.size() > 1 ? (inputs.size() > 1 ? fmt::format("{} set {} ", input, in_input) : fmt::format("set {} ", in_input))
                          : std::string();
      run.sets.push_back(dfvn::measure_point_set(sets[s], options, [&](std::string_view stage, double f) {
        reporter->report(set_label + std::string(stage), f);
      }));
      run.dimensions.push_back(sets[s].dimension);
      rows.push_back(dfvn::point_statistics_csv_row(input, std::to_string(in_input), sets[s], run.sets.back(), !no_timing));
      csv += rows.back();
      rows.back().pop_back();
      if (!rdf_path.empty()) {
        const auto curve = dfvn::radial_distribution(sets[s], rdf, kRdfSeed, common.threads,
                                                     [&](double f) { reporter->report(set_label + "rdf", f); });
        for (std::size_t k = 0; k < curve.r.size(); ++k)
          rdf_csv += fmt::format("{},{},{},{},{}\n", dfvn::csv_quoted(input), in_input, sets[s].dimension,
                                 dfvn::format_real(curve.r[k]), dfvn::format_real(curve.g[k]));
      }
    }
    // --summary: mean, sd and standard error over the sets of each input of several sets.
    std::vector<std::string> summarised;
    for (std::size_t s = 0; s < sets.size(); ++s)
      if (std::count(owner.begin(), owner.end(), owner[s]) > 1) summarised.push_back(rows[s]);
    const std::string summary =
        dfvn::realization_summary_csv(csv.substr(0, csv.find('\n')), summarised, {"input", "dim"}, "set");
    if (!spectrum_prefix.empty()) {
      const auto spectrum = dfvn::power_spectrum(sets, spectrum_k, common.threads,
                                                 [&](double f) { reporter->report("spectrum", f); });
      reporter->finish();
      std::string what;
      for (const std::string& input : inputs) what += (what.empty() ? "" : ", ") + (input == kStandardInput ? "standard input" : input);
      std::size_t points = 0;
      for (const dfvn::PointSet& set : sets) points += set.size();
      what += fmt::format(" ({} set{}, {} points)", sets.size(), sets.size() == 1 ? "" : "s", points);
      dfvn::write_spectrum_files(spectrum_prefix, spectrum,
                                 [](const std::string& line) { std::fprintf(stderr, "%s: %s\n", kProgram, line.c_str()); },
                                 what);
    }
    reporter->complete();
    for (const std::string& warning : warnings) std::fprintf(stderr, "%s: warning: %s\n", kProgram, warning.c_str());
    if (!json_path.empty()) dfvn::write_file_atomically(json_path, dfvn::point_statistics_json(run));
    if (!summary_path.empty()) dfvn::write_file_atomically(summary_path, summary);
    if (!rdf_path.empty()) dfvn::write_file_atomically(rdf_path, rdf_csv);
    dfvn::write_file_atomically(output, csv);
  }

  // The seed of the RDF's query subset (--rdf-queries), the same for every set.
  static constexpr std::uint64_t kRdfSeed = 1;

  // --rdf's limits, checked for every set before the work: 2D..8D, r_max below half the side on the
  // torus, bins wide enough for a finite g(r).
  void check_rdf(const std::vector<dfvn::PointSet>& sets, const std::vector<std::size_t>& owner) const {
    for (std::size_t s = 0; s < sets.size(); ++s) {
      const int n = sets[s].dimension;
      if (n < 2) fail(fmt::format("--rdf needs 2D..8D points; '{}' holds {}D points", inputs[owner[s]], n));
      const dfvn::Domain& d = sets[s].domain;
      if (d.kind == dfvn::DomainKind::sphere) fail("--rdf is for points in a torus, cube or ball, not on the sphere");
      if (d.periodic() && rdf.r_max >= 0.5 * d.side)
        fail(fmt::format("--rdf-max {:g} on the torus must be below half its side ({:g})", rdf.r_max, 0.5 * d.side));
      if (rdf.r_max > 0.0) {
        try {
          dfvn::check_rdf_resolution(n, d.side, std::min(rdf.r_max, 0.999 * d.side), rdf.bins);
        } catch (const std::invalid_argument&) {
          fail(fmt::format("--rdf-max {:g} with --rdf-bins {} gives bins {:.3g} wide, too narrow for a finite g(r) in {}D; raise "
                           "--rdf-max or lower --rdf-bins",
                           rdf.r_max, rdf.bins, rdf.r_max / rdf.bins, n));
        }
      }
    }
  }
};

}  // namespace

std::unique_ptr<Subcommand> add_stats_command(CLI::App& app) { return registered<StatsCommand>(app); }

}  // namespace dfvn_cli
