// The command line's shared pieces: the one-line error, the validators and the options that several
// subcommands take (apps/*_command.cpp use them; apps/main.cpp assembles the subcommands).
#pragma once

#include <CLI/CLI.hpp>

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "dfvn/core/progress.hpp"
#include "dfvn/field/bridson_flow.hpp"
#include "dfvn/field/field_transform.hpp"

namespace dfvn_cli {

inline constexpr const char* kProgram = "dfvn-sample";

// Every error is one line on stderr: escape_bytes turns any newline or control byte left in the
// message into a visible escape, so nothing reaches the terminal raw.
[[noreturn]] void fail(const std::string& message, int code = 1);

// The names closest to a mistyped one by edit distance (insertions, deletions, substitutions and
// transpositions of neighbours, leading dashes ignored): the one closest, or the few tied for closest;
// none when even the closest differs in more than 2 characters or in half of the word.
std::vector<std::string> closest_names(const std::string& typed, const std::vector<std::string>& names);

// Finite numbers > 0 and >= 0. CLI11's PositiveNumber would print its whole range, DBL_MAX included,
// and accepts no NaN check.
extern const CLI::Validator kPositiveFinite;
extern const CLI::Validator kNonNegativeFinite;
// A noise frequency in the supported range (noise/noise_domain.hpp); a subnormal one gave Inf.
extern const CLI::Validator kNoiseFrequency;
// stats --domain-side: a finite side in [2^-1000, 2^1000] (stats/distance_scale.hpp says why).
extern const CLI::Validator kDomainSide;
// CNJ's step scale: (0, 2^20] (sampling/curl_noise_jitter.hpp says why).
extern const CLI::Validator kStepScale;
// A real number in [lo, hi] ((lo, hi] with `open_below`), its range shown as `shown` (e.g. "(0, 1/4]") or
// else with %g: CLI11's Range printed its bounds with %f ("0.000000 to 0.250000" for (0, 1/4]).
CLI::Validator real_in(double lo, double hi, bool open_below = false, const std::string& shown = "");
// Digits only, read exactly: CLI11 would take "-1" and "18446744073709551616" as 2^64 - 1 and "" as 0.
extern const CLI::Validator kUnsignedInteger;
// --threads: 0 (all cores) or 1..max_thread_count() (core/parallel.hpp).
extern const CLI::Validator kThreadCount;

// --dim, checked against the dimensions the library instantiates.
CLI::Option* add_dimension_option(CLI::App& cmd, int& dimension, const std::string& help);

// --noise: the basis of the N-1 noise functions; `steerable`: steerable is one of them (the subcommand
// takes SteerOptions too).
void add_noise_option(CLI::App& cmd, std::string& noise, bool steerable = false);

// --steer-dir U, --steer-field constant|circular, --steer-k K, --steer-quality Q and --steer-image FILE: the
// direction field of --noise steerable
// (noise/steerable_noise.hpp). spec() fail()s with one line when one is given without --noise steerable, or
// (with `dimension` > 0) when the spec does not fit the dimension.
struct SteerOptions {
  std::string direction;
  std::string field = "constant";
  double k = dfvn::kDefaultSteerK;
  int quality = 0;
  std::string image;
  CLI::Option* options[5] = {};

  void add_to(CLI::App& cmd);
  dfvn::SteerSpec spec(const std::string& noise, int dimension) const;
  // The file --steer-image reads, as (option, path) for dfvn::check_outputs.
  std::vector<std::pair<std::string, std::string>> input_files() const;
};
// --field: which divergence-free field the noise makes, dfvn (the paper's) or curl (Bridson's curl noise).
CLI::Option* add_field_kind_option(CLI::App& cmd, std::string& field, const std::string& consequences);
// --phase: the noise's phase alpha in radians (rotating gradients; any finite real, default 0).
void add_phase_option(CLI::App& cmd, double& phase);

// --stretch U:S, --time T, --lift SPEC and --lift-ramp BETA: where the field reads its noise
// (field/field_transform.hpp). transform() parses them (fail() with one line on a malformed spec).
struct TransformOptions {
  std::string stretch;
  double time = 0.0;
  std::string lift;
  double lift_ramp = 0.0;
  CLI::Option* stretch_option = nullptr;
  CLI::Option* time_option = nullptr;
  CLI::Option* lift_option = nullptr;
  CLI::Option* ramp_option = nullptr;

  void add_to(CLI::App& cmd);
  dfvn::NoiseTransform transform() const;
  // The files these options read, as (option, path) for dfvn::check_outputs: --lift npy:FILE's FILE.
  std::vector<std::pair<std::string, std::string>> input_files() const;
};

// Bridson et al. 2007's toolbox on the field (field/bridson_flow.hpp): --octaves K, --octave-gain G,
// --amplitude SHAPE (repeatable), --viscous, --body sphere:... (repeatable), --vortex particle:...|ring:...
// (repeatable). flow() parses them (fail() with one line on a malformed spec or value).
struct BridsonOptions {
  int octaves = 1;
  double octave_gain = dfvn::kKolmogorovOctaveGain;
  std::vector<std::string> amplitude;
  bool viscous = false;
  std::vector<std::string> bodies;
  std::vector<std::string> vortices;

  void add_to(CLI::App& cmd);
  dfvn::FlowOptions flow() const;
};

// --rotation: how simplex noise's gradients turn with --phase (noise/rotating_gradients.hpp).
void add_rotation_option(CLI::App& cmd, std::string& rotation);

// Names that no longer mean what they meant here (issue 24's one vocabulary), each with the line that
// names the option to use instead: hidden from the help, and giving one (with a value or without)
// stops the run with its line as soon as the subcommand is parsed. Never reinterpreted silently.
void refuse_options(CLI::App& cmd, const std::vector<std::pair<std::string, std::string>>& names_and_messages);

// Options that every subcommand shares.
struct CommonOptions {
  std::uint64_t seed = 1;
  int threads = 0;
};

void add_threads_option(CLI::App& app, int& threads);
void add_common_options(CLI::App& app, CommonOptions& common);

// Progress on stderr: --progress and -q/--quiet, shared by the subcommands that run long.
struct ProgressOptions {
  std::string mode = "auto";
  bool quiet = false;
  const char* program = kProgram;  // the lines' prefix (dfvn-sample-mpi names itself)

  void add_to(CLI::App& app);
  // A reporter on stderr; `stages`: how many stages the run reports (0: unknown).
  dfvn::ProgressReporter* make(int stages = 0);
  // A reporter on stderr for stages of these expected costs, in the order the run reports them.
  dfvn::ProgressReporter* make(std::vector<double> stage_weights);

 private:
  std::optional<dfvn::ProgressReporter> reporter_;
};

// The outputs of a reproduction: its files in `dir`, each named as "--out (table1.csv)" in messages.
std::vector<std::pair<std::string, std::string>> files_in(const std::string& dir, const std::vector<std::string>& names);

// A subcommand's options and its run: alive from its registration (add_*_command) to the end of main.
struct Subcommand {
  virtual ~Subcommand() = default;
};
// A Command (a Subcommand with add_to(app), which registers its options and its run) made and registered.
template <typename Command>
std::unique_ptr<Subcommand> registered(CLI::App& app) {
  auto command = std::make_unique<Command>();
  command->add_to(app);
  return command;
}
std::unique_ptr<Subcommand> add_sample_command(CLI::App& app);
std::unique_ptr<Subcommand> add_field_command(CLI::App& app);
std::unique_ptr<Subcommand> add_reproduce_command(CLI::App& app);
std::unique_ptr<Subcommand> add_stats_command(CLI::App& app);
std::unique_ptr<Subcommand> add_animate_command(CLI::App& app);

}  // namespace dfvn_cli
