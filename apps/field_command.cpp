// dfvn-sample field: the field's vector and noise values at points read as text, or its diagnosis.
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "dfvn/core/dimension.hpp"
#include "dfvn/core/message_text.hpp"
#include "dfvn/field/diagnose.hpp"
#include "dfvn/field/evaluate_points.hpp"
#include "dfvn/io/atomic_file.hpp"
#include "dfvn/io/csv.hpp"
#include "dfvn/io/field_csv.hpp"
#include "dfvn/io/point_reader.hpp"

#include "options.hpp"

namespace dfvn_cli {
namespace {

struct FieldCommand : Subcommand {
  CommonOptions common;
  int dimension = 0;  // 0: the input's column count (3 with --diagnose)
  double frequency = 1.0;
  double phase = 0.0;
  TransformOptions transform;
  SteerOptions steer;
  BridsonOptions bridson;
  std::string rotation{dfvn::to_string(dfvn::kDefaultGradientRotation)};
  std::string noise{dfvn::to_string(dfvn::kDefaultNoiseBasis)};
  std::string field_kind{dfvn::to_string(dfvn::kDefaultFieldKind)};
  std::string domain = "free";
  std::string bound = "eq13";
  double boundary_width = 0.1;
  CLI::Option* bound_options[2] = {};  // --bound, --boundary-width: only with a bounded domain
  std::vector<std::string> obstacles;
  std::string input;
  std::string output = "-";
  bool diagnose = false;
  dfvn::DiagnosisOptions diagnosis;
  ProgressOptions progress;

  void add_to(CLI::App& parent) {
    CLI::App* cmd = parent.add_subcommand(
        "field",
        "Evaluate the field at points read as text, or diagnose its health (--diagnose)\n\n"
        "Evaluate the divergence-free field at points read as text: comma-separated (optional header) or\n"
        "whitespace-separated (numpy.savetxt's default; '#' lines are comments), one point a line.\n"
        "Writes x0..x{N-1},c0..c{N-1},f1..f{N-1}: the point, the field vector c = cross(grad f_1..f_{N-1})\n"
        "(Eq. 8, RMS |c| = 1) and the N-1 noise values, with 17 significant digits.");
    add_dimension_option(*cmd, dimension,
                         "Dimension N (2..8) of the points; default: the column count of the input's first line\n"
                         "(3 with --diagnose)");
    cmd->add_option("--frequency", frequency,
                    "Noise frequency F in cycles per unit length (one cycle = 2 pi / k_eff of the basis):\n"
                    "f_i(x) = (A/s) n_i(s x) with s = 2 pi F / k_eff; in [2^-50, 2^50], and every |F x_j| must be\n"
                    "below 2^50")
        ->capture_default_str()
        ->check(kNoiseFrequency);
    add_noise_option(*cmd, noise, true);
    steer.add_to(*cmd);
    add_field_kind_option(*cmd, field_kind,
                          "With curl: --domain free or torus, or cube or ball\nwith --bound ramp; the columns f1..f{N-1} are then psi_1..psi_{N-1}");
    add_phase_option(*cmd, phase);
    add_rotation_option(*cmd, rotation);
    transform.add_to(*cmd);
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
        ->check(real_in(0.0, 0.25, true, "(0, 1/4]"));
    cmd->add_option("--obstacle", obstacles,
                    "With --domain cube or ball: a spherical obstacle sphere:CX,CY[,CZ...],R (N centre coordinates\n"
                    "and a radius; repeatable; default none) that the field flows around: f_1 times Bridson's\n"
                    "ramp(d / w) (w = --boundary-width, d the distance to the sphere) for dfvn and 2D curl noise,\n"
                    "Bridson's psi_c = alpha psi + (1 - alpha) n (n . psi) for 3D curl noise. Each obstacle with its\n"
                    "zone must lie inside the domain clear of the wall's zone and of the other obstacles' zones")
        ->take_all();
    bridson.add_to(*cmd);
    CLI::Option* input_option =
        cmd->add_option("-i,--input", input, "Point file to read, CSV or whitespace-separated (default: standard input)")
            ->type_name("FILE");  // a file that cannot be read is bad data, exit 1, said by the reader
    CLI::Option* diagnose_flag = cmd->add_flag(
        "--diagnose", diagnose,
        "Instead of reading points, measure the field on uniform random points and write one CSV row: RMS |c|,\n"
        "median/RMS, q10/RMS, fraction of points below 1% of the RMS, |div c|/|Dc| by central differences\n"
        "(median, p95, max) and the measured k_eff against 2 pi F");
    diagnose_flag->excludes(input_option);
    cmd->add_option("--diagnose-points", diagnosis.points, "With --diagnose: number of uniform random points")
        ->capture_default_str()
        ->check(CLI::Range(std::uint64_t{10}, std::uint64_t{100000000}));
    cmd->add_option("--periods", diagnosis.periods, "With --diagnose: the points fill [0, periods / F]^N; periods in [0.001, 1e9]")
        ->capture_default_str()
        ->check(real_in(1e-3, 1e9));
    cmd->add_option("-o,--output", output,
                    "Main output: the CSV of points, field vectors and noise values (with --diagnose: the diagnosis\n"
                    "row), written whole or not at all ('-' = standard output)")
        ->capture_default_str();
    progress.add_to(*cmd);
    add_common_options(*cmd, common);
    cmd->callback([this] { run(); });
  }

  std::string input_name() const {
    return input.empty() ? std::string("standard input") : dfvn::quote_for_message(input, dfvn::kMaxPathEchoChars);
  }

  dfvn::FieldOptions field_options() const {
    dfvn::FieldOptions o{dfvn::parse_noise_basis(noise), frequency};
    o.periodic = domain == "torus";
    o.kind = dfvn::parse_field_kind(field_kind);
    o.phase = phase;
    o.transform = transform.transform();
    o.transform.steer = steer.spec(noise, dimension);
    o.transform.rotation = dfvn::parse_gradient_rotation(rotation);
    if (domain == "cube" || domain == "ball") {
      o.constraint = domain == "cube" ? dfvn::FieldConstraint::inside_cube : dfvn::FieldConstraint::inside_ball;
      o.transition_width = boundary_width;
      o.bound = dfvn::parse_bound(bound);
      for (const std::string& spec : obstacles) o.obstacles.push_back(dfvn::parse_obstacle(spec));
    }
    o.flow = bridson.flow();
    return o;
  }

  void run() {
    std::vector<std::pair<std::string, std::string>> inputs = transform.input_files();
    for (const auto& file : steer.input_files()) inputs.push_back(file);
    inputs.emplace_back("--input", input.empty() ? std::string("-") : input);
    dfvn::check_outputs({{"--output", output}}, {}, inputs);
    if (field_kind == "curl" && (domain == "cube" || domain == "ball") && bound != "ramp")
      fail("--field curl's boundary is Bridson's (the ramped stream function in 2D, psi_c in 3D): --domain " + domain +
           " needs --bound ramp");
    if (!obstacles.empty() && domain != "cube" && domain != "ball")
      fail("--obstacle lies inside a domain: it needs --domain cube or ball, not " + domain);
    for (const std::string& spec : obstacles) {
      try {
        (void)dfvn::parse_obstacle(spec);
      } catch (const std::invalid_argument& e) {
        fail(std::string("--obstacle: ") + e.what());
      }
    }
    if (field_kind == "curl" && dimension > 3)
      fail(fmt::format("--field curl is Bridson's curl noise in 2D and 3D; --dim {} needs --field dfvn", dimension));
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
      dfvn::ProgressReporter* reporter = progress.make(1);
      const dfvn::FieldDiagnosis d = dfvn::diagnose_field(
          diagnosis, [&](double f) { reporter->report(fmt::format("diagnose {} points", diagnosis.points), f); });
      reporter->complete();
      dfvn::write_file_atomically(output, dfvn::diagnosis_csv_header() + dfvn::diagnosis_csv_row(d));
      return;
    }
    dfvn::PointTable points;
    try {
      if (input.empty()) {
        points = dfvn::read_points_text(std::cin, dimension);
      } else {
        dfvn::check_readable_file(input);  // a missing file or a directory: one line, exit 1
        std::ifstream in(input);
        if (!in) fail(input_name() + ", cannot read the file");
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
      dfvn::ProgressReporter* reporter = progress.make(1);
      const std::string stage = fmt::format("field at {} points", points.rows());
      dfvn::evaluate_field(query, points.coordinates.data(), points.rows(), velocity.data(), values.data(),
                           [&](double f) { reporter->report(stage, f); });
      reporter->complete();
      dfvn::write_file_atomically(output, dfvn::field_csv(points, velocity.data(), values.data(), query.threads));
    } catch (const std::invalid_argument& e) {
      fail(input_name() + ", " + e.what());
    }
  }
};

}  // namespace

std::unique_ptr<Subcommand> add_field_command(CLI::App& app) { return registered<FieldCommand>(app); }

}  // namespace dfvn_cli
