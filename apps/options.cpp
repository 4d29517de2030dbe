#include "options.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <unistd.h>

#include "dfvn/core/dimension.hpp"
#include "dfvn/core/message_text.hpp"
#include "dfvn/core/parallel.hpp"
#include "dfvn/noise/noise_domain.hpp"
#include "dfvn/sampling/curl_noise_jitter.hpp"
#include "dfvn/stats/distance_scale.hpp"

namespace dfvn_cli {

// Every error is one line on stderr: escape_bytes turns any newline or control byte left in the
// message into a visible escape, so nothing reaches the terminal raw.
void fail(const std::string& message, int code) {
  const std::string line = dfvn::escape_bytes(message, false);
  std::fprintf(stderr, "%s: error: %s\n", kProgram, line.c_str());
  std::exit(code);
}

namespace {

// Optimal string alignment distance: Levenshtein's edits plus the transposition of two neighbours.
std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
  for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i)
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t substitution = a[i - 1] == b[j - 1] ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + substitution});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[a.size()][b.size()];
}

std::string without_dashes(const std::string& name) { return name.substr(std::min(name.find_first_not_of('-'), name.size())); }

}  // namespace

std::vector<std::string> closest_names(const std::string& typed, const std::vector<std::string>& names) {
  constexpr std::size_t kMaxEdits = 2;
  constexpr std::size_t kMaxTied = 3;  // more names tied than this: no suggestion at all
  const std::string word = without_dashes(typed);
  std::size_t best = kMaxEdits + 1;
  std::vector<std::string> closest;
  for (const std::string& name : names) {
    if (name.starts_with("--") != typed.starts_with("--")) continue;  // a long name for a long one
    const std::size_t distance = edit_distance(word, without_dashes(name));
    if (distance == 0 || 2 * distance >= word.size() || distance > best) continue;
    if (distance < best) closest.clear();
    best = distance;
    if (std::find(closest.begin(), closest.end(), name) == closest.end()) closest.push_back(name);
  }
  if (closest.size() > kMaxTied) closest.clear();
  return closest;
}

namespace {

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
// Digits only, read exactly: CLI11 would take "-1" and "18446744073709551616" as 2^64 - 1 and "" as 0.
bool read_unsigned(const std::string& text, std::uint64_t& value) {
  const char* end = text.data() + text.size();
  const auto [ptr, error] = std::from_chars(text.data(), end, value);
  return !text.empty() && text.find_first_not_of("0123456789") == std::string::npos && error == std::errc() &&
         ptr == end;
}

}  // namespace

CLI::Validator real_in(double lo, double hi, bool open_below, const std::string& shown) {
  const std::string range = !shown.empty() ? shown : fmt::format("{}{:g}, {:g}]", open_below ? "(" : "[", lo, hi);
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        double value = 0.0;
        const bool ok = CLI::detail::lexical_cast(text, value) && (open_below ? value > lo : value >= lo) && value <= hi;
        return ok ? std::string() : "must be a number in " + range + ", got " + dfvn::quote_for_message(text);
      },
      "FLOAT in " + range);
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
void add_noise_option(CLI::App& cmd, std::string& noise, bool steerable) {
  std::vector<std::string> names = {"simplex", "turning-bands", "quintic-gradient", "simplex-separate"};
  if (steerable) names.push_back("steerable");
  cmd.add_option("--noise", noise,
                 "Noise basis of the N-1 functions: turning-bands (healthy in every dimension), simplex (the\n"
                 "paper's construction, all functions in one shared traversal: in 3D optimised bitangent noise; its\n"
                 "field is nearly still in most of space from 4D on), quintic-gradient (Perlin-style lattice\n"
                 "gradient noise, the noise of the paper's image-warping shader) or simplex-separate (the same\n"
                 "simplex noise, one traversal per function at an offset point: in 3D bitangent noise's reference\n"
                 "form)" +
                     std::string(steerable ? " or steerable (Rice's steerable Perlin noise, 2D-4D: elongated along\n"
                                             "--steer-dir or the circular --steer-field)"
                                           : ""))
      ->capture_default_str()
      ->check(CLI::IsMember(names));
}

void SteerOptions::add_to(CLI::App& cmd) {
  options[0] = cmd.add_option("--steer-dir", direction,
                              "With --noise steerable: the direction U the noise is elongated along, N comma-separated\n"
                              "components, any length but not zero (U and -U give the same noise). Default: none")
                   ->type_name("U");
  options[1] = cmd.add_option("--steer-field", field,
                              "With --noise steerable: constant (--steer-dir) or circular (u = (-x2, x1, 0, ...) around the\n"
                              "origin, isotropic within one lattice cell of its axis)")
                   ->capture_default_str()
                   ->check(CLI::IsMember({"constant", "circular"}));
  options[2] = cmd.add_option("--steer-k", k,
                              "With --noise steerable: the metric's eigenvalue K along u, in (0, 1] (below 0.99993 in 4D);\n"
                              "across u it is (4 - K) / (N - 1) - 1e-4, so smaller K elongates more")
                   ->capture_default_str();
  options[3] = cmd.add_option("--steer-quality", quality,
                              "With --noise steerable: the quality Q in 0..N, the corners -Q..Q+1 along each axis\n"
                              "((2Q+2)^N per function), the eigenvalue along u K / (Q + 1): larger Q elongates more and\n"
                              "costs more; 0 is the single-order noise")
                   ->capture_default_str()
                   ->check(CLI::Range(0, dfvn::kMaxSteerableDimension));
  options[4] = cmd.add_option("--steer-image", image,
                              "With --noise steerable in 2D: steer along an image's direction field over the unit square\n"
                              "(Figure 3): a .png flow map (colour; direction (2R/255 - 1, 2G/255 - 1), x right, y up) or a\n"
                              ".npy array (rows, columns, 2) of directions u[i, j] at x = j / (columns - 1), y = i / (rows - 1);\n"
                              "smoothed by a cubic B-spline of u u^T. Default: none")
                   ->type_name("FILE")
                   ->check(CLI::ExistingFile);
}

std::vector<std::pair<std::string, std::string>> SteerOptions::input_files() const {
  if (image.empty()) return {};
  return {{"--steer-image", image}};
}

dfvn::SteerSpec SteerOptions::spec(const std::string& noise, int dimension) const {
  int count = 0;
  for (const CLI::Option* option : options) count += static_cast<int>(option->count());
  const bool given = count > 0;
  dfvn::SteerSpec s;
  if (noise != "steerable") {
    if (given)
      fail("--steer-dir, --steer-field, --steer-k, --steer-quality and --steer-image steer --noise steerable, not --noise " + noise);
    return s;
  }
  s.k = k;
  s.quality = quality;
  s.circular = field == "circular";
  if (!image.empty()) {
    try {
      s.image = dfvn::read_steer_image(image);
    } catch (const std::invalid_argument& e) {
      fail(e.what());
    }
  }
  if (options[0]->count() > 0) {
    for (const std::string& part : CLI::detail::split(direction, ',')) {
      double value = 0.0;
      if (!CLI::detail::lexical_cast(CLI::detail::trim_copy(part), value))
        fail("--steer-dir: " + dfvn::quote_for_message(part) + " is not a number (U is N comma-separated components)");
      s.direction.push_back(value);
    }
  }
  if (dimension > 0) {
    try {
      dfvn::check_steer_spec(s, dimension);
    } catch (const std::invalid_argument& e) {
      fail(e.what());
    }
  }
  return s;
}

CLI::Option* add_field_kind_option(CLI::App& cmd, std::string& field, const std::string& consequences) {
  return cmd.add_option("--field", field,
                        "Divergence-free field: dfvn (c = cross(grad f_1..f_{N-1}), Eq. 8, any N) or curl (Bridson et\n"
                        "al. 2007's curl noise, 2D and 3D: c = (d psi/dy, -d psi/dx), in 3D c = curl (psi_1, psi_2, psi_3)\n"
                        "of three independent functions of --noise; the same RMS |c| = 1 and --frequency). Curl noise has\n"
                        "no reprojection (its streamlines are not intersections of iso-surfaces); its boundaries are\n"
                        "Bridson's (field --domain cube or ball --bound ramp); in 2D it equals the dfvn field. " + consequences)
      ->capture_default_str()
      ->check(CLI::IsMember({"dfvn", "curl"}));
}

void add_phase_option(CLI::App& cmd, double& phase) {
  cmd.add_option("--phase", phase,
                 "Noise phase alpha in radians, any finite real: every gradient of the basis turns in its own seeded\n"
                 "plane (McEwan & Gustavson's rotating gradients), so the field changes smoothly with alpha, has\n"
                 "period 2 pi (alpha + pi flips every f_i), and stays exactly divergence-free with RMS |c| = 1;\n"
                 "0 is the field without a phase, bit for bit")
      ->capture_default_str()
      ->check(CLI::Validator(
          [](std::string& text) -> std::string {
            double value = 0.0;
            if (CLI::detail::lexical_cast(text, value) && std::isfinite(value)) return {};
            return "must be a finite number of radians, got " + dfvn::quote_for_message(text);
          },
          "RADIANS"));
}

namespace {

const CLI::Validator kFiniteReal(
    [](std::string& text) -> std::string {
      double value = 0.0;
      if (CLI::detail::lexical_cast(text, value) && std::isfinite(value)) return {};
      return "must be a finite number, got " + dfvn::quote_for_message(text);
    },
    "REAL");

}  // namespace

void TransformOptions::add_to(CLI::App& cmd) {
  stretch_option = cmd.add_option("--stretch", stretch,
                 "Stretch the noise along a direction, U:S (U comma-separated, any length but not zero; S in\n"
                 "[1e-6, 1e6]): f_i(A x) with A = I + (S - 1) u u^T, u = U / |U|, for every basis, so the noise varies\n"
                 "S times faster along u; still exactly divergence-free, RMS |c| renormalised to 1. Not on the torus.\n"
                 "Default: none")
      ->type_name("U:S");
  time_option = cmd.add_option("--time", time,
                               "Time as an extra noise dimension: the N-1 functions of the (N+1)-dimensional basis at\n"
                               "(x, T), T any finite real in the units of x (one cycle of --frequency long along time as\n"
                               "along x); N <= 7. Beside --phase the (N+1)D basis turns at that phase. Default: none (the\n"
                               "N-dimensional basis; --time 0 is a different field)")
                    ->check(kFiniteReal)
                    ->type_name("T");
  lift_option = cmd.add_option("--lift", lift,
                 "2D only: lift the noise onto a surface z = h(x) (the paper's Section 5.5), f(x) = F(x, h(x)) with\n"
                 "F the first function of the 3D basis; still exactly divergence-free. plane:SX,SY (h = SX x + SY y)\n"
                 "or bump:H,R[,CX,CY[,SX,SY]] (h = H (1 - r^2)^3 for r = |x - (CX,CY)| / R < 1, else 0; centre default\n"
                 "0,0; on the plane SX x + SY y if given)\n"
                 "or npy:FILE (a 2D float .npy array h[i, j] at x = j / (columns - 1), y = i / (rows - 1) over the unit\n"
                 "square, interpolated by a cubic B-spline, so C2). Default: none")
      ->type_name("SPEC");
  ramp_option = cmd.add_option("--lift-ramp", lift_ramp,
                               "With --lift: the vertical ramp of the paper's Figure 9, F(x, z) + BETA z: on a slope it\n"
                               "adds BETA perp(grad h) to c (motion along the contour lines, BETA in RMS-speed units)")
                    ->capture_default_str()
                    ->check(kFiniteReal)
                    ->type_name("BETA");
}

dfvn::NoiseTransform TransformOptions::transform() const {
  dfvn::NoiseTransform t;
  try {
    if (!stretch.empty() || (stretch_option != nullptr && stretch_option->count() > 0)) dfvn::parse_stretch(stretch, t);
    if (time_option != nullptr && time_option->count() > 0) t.time = time;
    if (!lift.empty() || (lift_option != nullptr && lift_option->count() > 0)) {
      t.lift = dfvn::parse_lift(lift);
      t.lift.ramp = lift_ramp;
    } else if (ramp_option != nullptr && ramp_option->count() > 0) {
      fail("--lift-ramp applies with --lift");
    }
    t.validate();
  } catch (const std::invalid_argument& e) {
    fail(e.what());
  }
  return t;
}

std::vector<std::pair<std::string, std::string>> TransformOptions::input_files() const {
  constexpr std::string_view kNpyPrefix = "npy:";
  if (lift.starts_with(kNpyPrefix)) return {{"--lift npy:", lift.substr(kNpyPrefix.size())}};
  return {};
}

void BridsonOptions::add_to(CLI::App& cmd) {
  cmd.add_option("--octaves", octaves,
                 fmt::format("Octaves K of the noise (Bridson et al. 2007, Section 2.2), in [1, {}]: octave o is an\n"
                             "independently seeded instance at 2^o times --frequency, with its own boundary width w / 2^o;\n"
                             "weights g^o / sqrt(sum g^2k) keep RMS |c| = 1 (for --field curl each octave's energy is\n"
                             "its weight squared; for dfvn the weights apply to every f_i). 1 is the field without\n"
                             "octaves, bit for bit",
                             dfvn::kMaxOctaves))
      ->capture_default_str()
      ->check(CLI::Range(1, dfvn::kMaxOctaves));
  cmd.add_option("--octave-gain", octave_gain,
                 "With --octaves: the velocity ratio g from one octave to the next (half the length scale), any\n"
                 "finite g > 0; default Kolmogorov's 2^(-1/3) = 0.7937 (energy spectrum k^(-5/3))")
      ->capture_default_str()
      ->check(kPositiveFinite);
  cmd.add_option("--amplitude", amplitude,
                 "Modulate the potential by A(x) (Bridson Section 2.3; for dfvn f_1, in 3D the potential f_1\n"
                 "grad f_2): constant:A, height:Z0,Z1 (the C2 smoothstep from 0 at x_N = Z0 to 1 at Z1) or\n"
                 "obstacles:D (1 on every --obstacle and --body, 0 once all are D away); repeatable, the\n"
                 "product; still exactly divergence-free. Default: none (A = 1)")
      ->type_name("SHAPE")
      ->take_all();
  cmd.add_flag("--viscous", viscous,
               "With --domain cube or ball: no-slip solids (Bridson Section 2.4): the potential times the C2\n"
               "smoothstep S(d / w) of the distance to the wall and to every obstacle and body, so c = 0 on\n"
               "them (a --body's surface moves with it). Default: off (c tangent to them)");
  cmd.add_option("--body", bodies,
                 "With --field curl in 3D and --domain cube or ball: a moving rigid sphere\n"
                 "sphere:CX,CY,CZ,R,VX,VY,VZ,WX,WY,WZ (centre, radius, velocity V, angular velocity W; Bridson\n"
                 "Eq. 6 with V x r / 2, blended to 0 at 2R from the centre): on its surface c . n equals\n"
                 "(V + W x (x - centre)) . n. Repeatable; default none")
      ->type_name("SPEC")
      ->take_all();
  cmd.add_option("--vortex", vortices,
                 "With --field curl in 3D: a vortex (Bridson Eqs. 7-8, fall-off 1 - S(d / R) to 0 at the core\n"
                 "radius R): particle:CX,CY,CZ,WX,WY,WZ,R (rotation at angular velocity W about the centre) or\n"
                 "ring:CX,CY,CZ,NX,NY,NZ,RR,W,R (a smoke ring of radius RR normal to N, angular velocity W about\n"
                 "its core; W > 0 pushes through the ring along N). Repeatable; default none")
      ->type_name("SPEC")
      ->take_all();
}

dfvn::FlowOptions BridsonOptions::flow() const {
  dfvn::FlowOptions f;
  f.octaves = octaves;
  f.octave_gain = octave_gain;
  f.viscous = viscous;
  try {
    for (const std::string& spec : amplitude) f.amplitude.push_back(dfvn::parse_amplitude(spec));
    for (const std::string& spec : bodies) f.bodies.push_back(dfvn::parse_body(spec));
    for (const std::string& spec : vortices) f.vortices.push_back(dfvn::parse_vortex(spec));
    f.validate();
  } catch (const std::invalid_argument& e) {
    fail(e.what());
  }
  return f;
}

void add_rotation_option(CLI::App& cmd, std::string& rotation) {
  cmd.add_option("--rotation", rotation,
                 "How --noise simplex's gradients turn with --phase in 3D (McEwan & Gustavson): two-vector\n"
                 "(p cos a + q sin a, q a second hashed gradient made orthogonal to p: every dimension; phase 0 the\n"
                 "basis's own noise), fast (one Fibonacci-sphere hash: axis and offset, no phase gives a static set)\n"
                 "or well-behaved (p on the Fibonacci sphere, q by the rotation taking z to p: phase 0 is the\n"
                 "Fibonacci gradients' noise bit for bit)")
      ->capture_default_str()
      ->check(CLI::IsMember({"two-vector", "fast", "well-behaved"}));
}

void refuse_options(CLI::App& cmd, const std::vector<std::pair<std::string, std::string>>& names_and_messages) {
  std::vector<std::pair<const CLI::Option*, std::string>> refused;
  for (const auto& [name, message] : names_and_messages)
    refused.emplace_back(cmd.add_option(name, "")->group("")->expected(0, 1), message);
  cmd.parse_complete_callback([refused] {
    for (const auto& [option, message] : refused)
      if (option->count() > 0) fail(message, 2);
  });
}

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

void ProgressOptions::add_to(CLI::App& app) {
  app.add_option("--progress", mode,
                 "Progress on stderr: auto (a live line on a terminal, otherwise a plain line every 5 s of long\n"
                 "work), always (also a line as each stage starts) or never")
      ->capture_default_str()
      ->check(CLI::IsMember({"auto", "always", "never"}));
  app.add_flag("-q,--quiet", quiet, "No progress on stderr (same as --progress never)");
}

dfvn::ProgressReporter* ProgressOptions::make(int stages) {
  reporter_.emplace(quiet ? dfvn::ProgressMode::never : dfvn::parse_progress_mode(mode), stderr,
                    ::isatty(STDERR_FILENO) == 1, program);
  reporter_->set_stage_count(stages);
  return &*reporter_;
}

dfvn::ProgressReporter* ProgressOptions::make(std::vector<double> stage_weights) {
  dfvn::ProgressReporter* reporter = make(0);
  reporter->set_stage_weights(std::move(stage_weights));
  return reporter;
}

// The outputs of a reproduction: its files in `dir`, each named as "--out (table1.csv)" in messages.
std::vector<std::pair<std::string, std::string>> files_in(const std::string& dir, const std::vector<std::string>& names) {
  std::vector<std::pair<std::string, std::string>> outputs;
  for (const std::string& name : names) outputs.emplace_back("--out (" + name + ")", (std::filesystem::path(dir) / name).string());
  return outputs;
}

}  // namespace dfvn_cli
