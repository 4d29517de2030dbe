// Table 1: running the point sets over the realizations, and its files (the Markdown is in
// table1_markdown.cpp).
#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <stdexcept>

#include <fmt/format.h>

#include "dfvn/core/machine.hpp"
#include "dfvn/core/message_text.hpp"
#include "dfvn/core/repeats.hpp"
#include "dfvn/core/seeds.hpp"
#include "dfvn/core/stopwatch.hpp"
#include "dfvn/io/atomic_file.hpp"
#include "dfvn/plot/gnuplot.hpp"
#include "dfvn/reproduce/reproduce.hpp"

namespace dfvn {

int table1_grid(int dimension) {
  switch (dimension) {
    case 3:
    case 4:
    case 5: return 10;
    case 6: return 7;
    case 7: return 6;
    default:
      throw std::invalid_argument(fmt::format("Table 1 covers dimensions 3..7, not {}", dimension));
  }
}

std::vector<int> parse_dimension_list(std::string_view text) {
  std::vector<int> dims;
  auto parse_int = [&](std::string_view s) {
    if (s.empty() || s.find_first_not_of("0123456789") != std::string_view::npos)
      throw std::invalid_argument(fmt::format("--dims: {} is not a list like 3-7 or 3,5,7", quote_for_message(text)));
    int v = 0;
    const auto [end, error] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (error != std::errc() || end != s.data() + s.size())
      throw std::invalid_argument(fmt::format("--dims: {} is not a dimension in 3..7", quote_for_message(s)));
    table1_grid(v);  // range check with the message
    return v;
  };
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = text.find(',', start);
    const std::string_view part = text.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start);
    const std::size_t dash = part.find('-');
    if (dash == std::string_view::npos) {
      dims.push_back(parse_int(part));
    } else {
      const int lo = parse_int(part.substr(0, dash)), hi = parse_int(part.substr(dash + 1));
      if (lo > hi) throw std::invalid_argument(fmt::format("--dims: empty range {}", quote_for_message(part)));
      for (int d = lo; d <= hi; ++d) dims.push_back(d);
    }
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  if (const auto repeat = first_repeat(dims))
    throw std::invalid_argument(fmt::format("--dims names {} twice", *repeat));
  return dims;
}

void Table1Config::validate() const {
  if (dimensions.empty()) throw std::invalid_argument("--dims: no dimension to run");
  for (int d : dimensions) table1_grid(d);
  if (realizations < 1 || realizations > 1000)
    throw std::invalid_argument(fmt::format("--realizations must be in 1..1000, got {}", realizations));
  check_seed_range(seed, static_cast<std::uint64_t>(realizations), "--seed", "--realizations");
}

namespace {

// Dimension d's configuration under the paper protocol.
SampleConfig table1_config(const Table1Config& config, int dimension) {
  SampleConfig c;
  c.dimension = dimension;
  c.grid = table1_grid(dimension);
  c.seed = config.seed;
  c.threads = config.threads;
  c.methods = {Method::cnj, Method::jitter, Method::pds, Method::sobol};
  c.cnj = config.cnj;
  // Section 5.1 for every method: the cube, CNJ's one RK4 step, the points that leave [0,1]^N dropped.
  c.use_protocol(Protocol::paper);
  c.rdf = config.rdf;
  return c;
}

// Realization r of a dimension's configuration: Figure 4 shows one realization, so only the first
// computes RDFs (their bins follow each set's density).
SampleConfig table1_realization(const Table1Config& config, const SampleConfig& c, int r) {
  SampleConfig realization = c;
  realization.seed = config.seed + static_cast<std::uint64_t>(r);
  realization.compute_rdf = r == 0;
  return realization;
}

// The simplex CNJ column: the paper's construction beside the realization.
SampleConfig paper_construction(const SampleConfig& realization) {
  SampleConfig paper = realization;
  paper.methods = {Method::cnj};
  paper.cnj.noise = NoiseBasis::simplex;
  // Section 5.1 traces one RK4 step; a count the user chose is kept.
  if (paper.cnj.trace.steps == CnjOptions::kStepsByDomainMode) paper.cnj.trace.steps = 1;
  paper.compute_rdf = false;
  return paper;
}

}  // namespace

std::vector<double> table1_stage_weights(const Table1Config& config) {
  std::vector<double> weights;
  for (int dimension : config.dimensions) {
    const SampleConfig c = table1_config(config, dimension);
    for (int r = 0; r < config.realizations; ++r) {
      const SampleConfig realization = table1_realization(config, c, r);
      for (const SampleConfig& run : {realization, paper_construction(realization)})
        for (double w : sampling_stage_weights(run)) weights.push_back(w);
    }
  }
  return weights;
}

Table1Result run_table1(const Table1Config& config, const StageProgress& progress) {
  config.validate();
  Table1Result result;
  result.realizations = config.realizations;
  result.machine = machine_description();
  for (int dimension : config.dimensions) {
    const SampleConfig c = table1_config(config, dimension);
    result.configs.push_back(c);
    result.runs.emplace_back();
    result.simplex_cnj.emplace_back();
    const Stopwatch wall;
    for (int r = 0; r < config.realizations; ++r) {
      const SampleConfig realization = table1_realization(config, c, r);
      const std::string name = config.realizations > 1 ? fmt::format("{}D seed {}", dimension, realization.seed)
                                                       : fmt::format("{}D", dimension);
      result.runs.back().push_back(run_sampling(realization, false, [&](std::string_view stage, double f) {
        if (progress) progress(fmt::format("{} {}", name, stage), f);
      }));
      result.simplex_cnj.back().push_back(run_sampling(paper_construction(realization), false, [&](std::string_view stage, double f) {
        if (progress) progress(fmt::format("{} simplex {}", name, stage), f);
      }).front());
    }
    result.wall_seconds.push_back(wall.seconds());
  }
  return result;
}

Table1Cell Table1Result::cell(std::size_t d, Method method, bool simplex) const {
  std::vector<double> median, min, seconds, points;
  for (std::size_t r = 0; r < runs[d].size(); ++r) {
    const MethodResult* found = nullptr;
    if (simplex) {
      found = &simplex_cnj[d][r];
    } else {
      for (const auto& m : runs[d][r])
        if (m.plan.method == method) found = &m;
    }
    if (!found) throw std::out_of_range(fmt::format("Table 1 has no {} results in {}D", to_string(method), configs[d].dimension));
    median.push_back(found->nearest.median);
    min.push_back(found->nearest.min);
    seconds.push_back(found->seconds_generate + found->seconds_stats);
    points.push_back(static_cast<double>(found->nearest.points));
  }
  return {mean_sd(median), mean_sd(min), mean_sd(seconds), mean_sd(points), *std::min_element(min.begin(), min.end())};
}

namespace {

// The Table 1 column a row belongs to, as the paper names it (the first column of table1.csv).
std::string table1_column(Method m, bool simplex) {
  switch (m) {
    case Method::cnj: return simplex ? "CNJ (simplex)" : "CNJ";
    case Method::jitter: return "Jittering";
    case Method::pds: return "PDS";
    case Method::sobol: return "Sobol";
    default: return std::string(to_string(m));
  }
}

// DIR/figure4.png: the first realization's RDFs; each row of panels shares the largest r of its row.
void draw_figure4(const Table1Result& result, const std::string& dir, const Log& log) {
  std::string dims, medians, x_max;
  for (std::size_t d = 0; d < result.configs.size(); ++d) {
    dims += fmt::format("{} ", result.configs[d].dimension);
    double row_max = 0.0;
    for (Method m : {Method::cnj, Method::jitter, Method::pds, Method::sobol}) {
      const MethodResult* found = nullptr;
      for (const auto& r : result.first(d))
        if (r.plan.method == m) found = &r;
      medians += found ? fmt::format("{:.4f} ", found->nearest.median) : std::string("- ");
      if (found && found->rdf) row_max = std::max(row_max, found->rdf->r_max);
    }
    x_max += fmt::format("{:.6g} ", row_max > 0.0 ? row_max : 1.0);
  }
  const std::string note = result.realizations > 1
                               ? fmt::format("seed {} (realization 1 of {}; table1.md has mean and sd over all)",
                                             result.configs.front().seed, result.realizations)
                               : fmt::format("seed {}", result.configs.front().seed);
  const auto path = [&](const char* name) { return (std::filesystem::path(dir) / name).string(); };
  draw_figure(PlotProgram::figure4, path("figure4.png"), {path("rdf.csv"), dims, medians, x_max, note}, log);
}

}  // namespace

std::vector<std::string> table1_output_files() {
  return {"table1.csv", "table1_summary.csv", "rdf.csv", "table1.md", "figure4.png"};
}

std::string write_table1(const Table1Config& config, const Table1Result& result, const Log& log) {
  const std::string dir = config.out_dir;
  const std::string header = "table1_column," + stats_csv_header();
  std::string stats = header, rdf = rdf_csv_header();
  std::vector<std::string> rows;  // without newlines, for the summary
  const auto add = [&](const SampleConfig& c, const MethodResult& r, bool simplex) {
    rows.push_back("\"" + table1_column(r.plan.method, simplex) + "\"," + stats_csv_row(c, r));
    stats += rows.back();
    rows.back().pop_back();
  };
  for (std::size_t d = 0; d < result.configs.size(); ++d) {
    for (std::size_t r = 0; r < result.runs[d].size(); ++r) {
      SampleConfig c = result.configs[d];
      c.seed += r;
      for (const auto& m : result.runs[d][r]) add(c, m, false);
      add(c, result.simplex_cnj[d][r], true);
    }
    for (const auto& m : result.first(d)) rdf += rdf_csv_rows(result.configs[d], m);
  }
  const std::string summary =
      realization_summary_csv(header.substr(0, header.size() - 1), rows, {"table1_column", "dim", "grid", "method"}, "seed");
  const std::string md = table1_markdown(result);
  for (const auto& [name, text] :
       {std::pair{"table1.csv", stats}, {"table1_summary.csv", summary}, {"rdf.csv", rdf}, {"table1.md", md}})
    write_file_atomically((std::filesystem::path(dir) / name).string(), text);
  draw_figure4(result, dir, log);
  return md;
}

}  // namespace dfvn
