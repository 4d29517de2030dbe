// dfvn-sample stats: statistics of a point file (stats/point_set_statistics.hpp).
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <cstdio>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "core/point_set.hpp"
#include "experiment/json_report.hpp"
#include "experiment/realizations.hpp"
#include "io/atomic_file.hpp"
#include "io/point_reader.hpp"
#include "plot/gnuplot.hpp"
#include "stats/distance_scale.hpp"
#include "stats/point_set_statistics.hpp"
#include "stats/spectrum.hpp"

#include "options.hpp"

namespace dfvn_cli {
namespace {

struct StatsCommand : Subcommand {
  CommonOptions common;
  std::string input;
  std::string format;
  std::string output = "-";
  std::string knn = "nanoflann";
  double domain_side = 1.0;
  std::string spectrum_prefix;
  int spectrum_frequency = 0;  // 0: dfvn::default_spectrum_frequency
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
    double mean_count = 0.0;
    for (const dfvn::PointSet& set : sets) mean_count += static_cast<double>(set.size()) / static_cast<double>(sets.size());
    const int dimension = sets.front().dimension;
    const int spectrum_k = spectrum_frequency > 0 ? spectrum_frequency : dfvn::default_spectrum_frequency(mean_count, dimension);
    // The [k/n] counter: each set's statistics, then the spectrum, weighted by their expected costs.
    std::vector<double> stage_weights;
    for (const dfvn::PointSet& set : sets)
      for (double w : dfvn::point_statistics_stage_weights(options, set.size(), set.dimension)) stage_weights.push_back(w);
    if (!spectrum_prefix.empty())
      stage_weights.push_back(dfvn::expected_spectrum_cost(sets, spectrum_k));
    dfvn::ProgressReporter* reporter = progress.make(std::move(stage_weights));
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
      const auto spectrum = dfvn::power_spectrum(sets, spectrum_k, common.threads,
                                                 [&](double f) { reporter->report("spectrum", f); });
      reporter->finish();
      dfvn::write_spectrum_files(spectrum_prefix, spectrum,
                                 [](const std::string& line) { std::fprintf(stderr, "%s: %s\n", kProgram, line.c_str()); });
    }
    reporter->complete();
    if (!json_path.empty()) dfvn::write_file_atomically(json_path, dfvn::point_statistics_json(run));
    dfvn::write_file_atomically(output, csv);
  }
};

}  // namespace

std::unique_ptr<Subcommand> add_stats_command(CLI::App& app) { return registered<StatsCommand>(app); }

}  // namespace dfvn_cli
