// dfvn-sample: the command line. It parses arguments, validates them and calls the library.
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>

#include "core/dimension.hpp"
#include "field/evaluate_points.hpp"
#include "io/atomic_file.hpp"
#include "io/csv.hpp"

namespace {

constexpr const char* kProgram = "dfvn-sample";

[[noreturn]] void fail(const std::string& message, int code = 1) {
  std::fprintf(stderr, "%s: error: %s\n", kProgram, message.c_str());
  std::exit(code);
}

// A finite number > 0 (CLI11's PositiveNumber prints its whole range, DBL_MAX included).
const CLI::Validator kPositiveFinite(
    [](std::string& text) -> std::string {
      double value = 0.0;
      if (!CLI::detail::lexical_cast(text, value) || !std::isfinite(value) || value <= 0.0)
        return "must be a finite number > 0, got '" + text + "'";
      return {};
    },
    "POSITIVE");

// Options that every subcommand shares.
struct CommonOptions {
  std::uint64_t seed = 1;
  int threads = 0;
};

void add_common_options(CLI::App& app, CommonOptions& common) {
  app.add_option("--seed", common.seed, "Seed of every random choice; same seed, same output")
      ->capture_default_str();
  app.add_option("--threads", common.threads, "Worker threads; 0 = all cores (output never depends on it)")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
}

struct FieldCommand {
  CommonOptions common;
  int dimension = 3;
  double frequency = 1.0;
  std::string input;
  std::string output = "-";

  void add_to(CLI::App& parent) {
    CLI::App* cmd = parent.add_subcommand(
        "field",
        "Evaluate the divergence-free field at points read as CSV (N columns a line, optional header).\n"
        "Writes x0..x{N-1},c0..c{N-1},f1..f{N-1}: the point, the field vector c = cross(grad f_1..f_{N-1})\n"
        "(Eq. 8, RMS |c| = 1) and the N-1 noise values, with 17 significant digits.");
    cmd->add_option("--dim", dimension, "Dimension N of the points (2..8)")
        ->capture_default_str()
        ->check(CLI::Range(dfvn::kMinDimension, dfvn::kMaxDimension));
    cmd->add_option("--frequency", frequency, "Noise frequency F: f_i(x) = (A_N/F) n_i(F x)")
        ->capture_default_str()
        ->check(kPositiveFinite);
    cmd->add_option("--input", input, "CSV file of points (default: standard input)")->check(CLI::ExistingFile);
    cmd->add_option("--output", output, "Output CSV file, written whole or not at all ('-' = standard output)")
        ->capture_default_str();
    add_common_options(*cmd, common);
    cmd->callback([this] { run(); });
  }

  void run() const {
    if (output != "-") dfvn::check_writable(output);
    dfvn::PointTable points;
    try {
      if (input.empty()) {
        points = dfvn::read_points_csv(std::cin, dimension);
      } else {
        std::ifstream in(input);
        if (!in) fail("cannot read '" + input + "'");
        points = dfvn::read_points_csv(in, dimension);
      }
    } catch (const dfvn::InputError& e) {
      fail((input.empty() ? std::string("standard input") : input) + ", " + e.what());
    }
    dfvn::FieldQuery query;
    query.dimension = dimension;
    query.seed = common.seed;
    query.frequency = frequency;
    query.threads = common.threads;
    const std::string csv = dfvn::evaluate_field_csv(query, points);
    dfvn::AtomicOutput out(output);
    out.stream() << csv;
    out.commit();
  }
};

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"dfvn-sample: divergence-free vector noise (DFVN) in 2..8 dimensions: the field, curl-noise\n"
               "jittering of lattices, and the point-set statistics of 'Improving Curl Noise' (SIGGRAPH Asia 2025).",
               kProgram};
  app.set_version_flag("--version", std::string(kProgram) + " " + DFVN_VERSION);
  app.require_subcommand(1);
  FieldCommand field;
  field.add_to(app);

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    fail(std::string(e.what()) + " (run with --help for the options)", 2);
  } catch (const std::exception& e) {
    fail(e.what());
  }
  return 0;
}
