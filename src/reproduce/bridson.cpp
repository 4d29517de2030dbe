// Bridson et al. 2007's Figure 2 (seed 003) and the checks of its toolbox (reproduce/bridson.hpp).
#include "dfvn/reproduce/bridson.hpp"

#include "dfvn/plot/gnuplot.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <filesystem>
#include <limits>
#include <memory>
#include <numbers>
#include <random>
#include <stdexcept>

#include <Eigen/Geometry>
#include <fmt/format.h>
#include <omp.h>

#include "dfvn/core/image.hpp"
#include "dfvn/core/machine.hpp"
#include "dfvn/core/parallel.hpp"
#include "dfvn/core/stopwatch.hpp"
#include "dfvn/field/dfvn_field.hpp"
#include "dfvn/io/atomic_file.hpp"
#include "dfvn/io/csv.hpp"
#include "dfvn/io/png.hpp"
#include "dfvn/noise/noise_domain.hpp"

namespace dfvn {

namespace {

// The wake: a sphere of radius 0.07 at (0.5, 0.5, 0.32) moving down at unit speed and spinning about its axis
// (4 radians per unit time), so that it crosses its own diameter in 0.14 time units; turbulence within 0.5 of it
// and above z = 0.3 (ramping to full strength at 0.45): only behind it. Its blend region (2R) stays clear of
// the walls' zones for w <= 0.07 (check_flow refuses more). Particles start on a K x K grid of the rectangle
// [0.3, 0.7] x [0.5, 0.7] at z = 0.04 (the half behind the body's mid-plane, so that the side view shows the body
// in front of the stream it parts) and are traced in the body's frame for 0.9 time units (the fluid streams up
// at unit speed there, across 0.9 of the cube).
const RigidBody kWakeBody{Vec<3>(0.5, 0.5, 0.32), 0.07, Vec<3>(0.0, 0.0, -1.0), Vec<3>(0.0, 0.0, 4.0)};
constexpr double kWakeTime = 0.9;
// The ring: a sphere of radius 0.08 fixed at (0.5, 0.5, 0.58); a ring of radius 0.2 and core radius 0.07 normal
// to z (its tube passes just around the sphere), turning at 20 radians per unit time about its core (its fluid
// moves at up to ~0.6), its centre rising from z = 0.15 at 0.25 per unit time for 2.6 time units (to 0.8): the
// ring is slower than most of its own fluid, which it therefore carries along; the turbulence ramps in from
// z = 0.62 to 0.82, above the sphere. Its particles start in the core tube.
const Vec<3> kRingStart(0.5, 0.5, 0.15);
constexpr double kRingRadius = 0.2, kRingCore = 0.07, kRingStrength = 20.0, kRingSpeed = 0.25, kRingTime = 2.6;
const Obstacle kRingSphere{{0.5, 0.5, 0.58}, 0.08};
constexpr int kTraceStride = 8;  // the traces CSV holds every 8th point of a trace (and its last)

FieldOptions curl_in_cube(const BridsonConfig& c) {
  FieldOptions o{NoiseBasis::turning_bands, c.frequency, FieldConstraint::inside_cube, c.boundary_width, Bound::ramp};
  o.kind = FieldKind::curl;
  o.flow.octaves = c.octaves;
  o.flow.octave_gain = c.octave_gain;
  return o;
}

FieldOptions wake_options(const BridsonConfig& c, bool viscous) {
  FieldOptions o = curl_in_cube(c);
  o.flow.bodies = {kWakeBody};
  o.flow.amplitude = {parse_amplitude("obstacles:0.5"), parse_amplitude("height:0.3,0.45")};
  o.flow.viscous = viscous;
  return o;
}

FieldOptions ring_options(const BridsonConfig& c, double time) {
  FieldOptions o = curl_in_cube(c);
  o.obstacles = {kRingSphere};
  Vortex ring;
  ring.kind = Vortex::Kind::ring;
  ring.centre = kRingStart + Vec<3>(0.0, 0.0, kRingSpeed * time);
  ring.normal = Vec<3>(0.0, 0.0, 1.0);
  ring.ring_radius = kRingRadius;
  ring.strength = kRingStrength;
  ring.core_radius = kRingCore;
  o.flow.vortices = {ring};
  o.flow.amplitude = {parse_amplitude("height:0.62,0.82")};
  return o;
}

bool in_cube(const Vec<3>& x) { return (x.array() >= 0.0).all() && (x.array() <= 1.0).all(); }

// RK4 from x over [t, t + h] along velocity(x, t); a particle that leaves the cube stays where it left.
template <typename Velocity>
Vec<3> rk4_step(const Velocity& velocity, const Vec<3>& x, double t, double h) {
  const Vec<3> k1 = velocity(x, t);
  const Vec<3> k2 = velocity(Vec<3>(x + 0.5 * h * k1), t + 0.5 * h);
  const Vec<3> k3 = velocity(Vec<3>(x + 0.5 * h * k2), t + 0.5 * h);
  const Vec<3> k4 = velocity(Vec<3>(x + h * k3), t + h);
  return x + (h / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
}

// Median |div c| / RMS |c| over the points where c moves (an amplitude of 0 gives c = 0 and div c = 0 exactly),
// central differences with h = 1e-5.
double divergence_ratio(const DfvnField<3>& field, int points, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.01, 0.99);
  std::vector<double> speed, div;
  constexpr double h = 1e-5;
  for (int k = 0; k < points; ++k) {
    const Vec<3> x(u(rng), u(rng), u(rng));
    speed.push_back(field.velocity(x).norm());
    double d = 0.0;
    for (int j = 0; j < 3; ++j) {
      Vec<3> step = Vec<3>::Zero();
      step[j] = h;
      d += (field.velocity(Vec<3>(x + step))[j] - field.velocity(Vec<3>(x - step))[j]) / (2.0 * h);
    }
    div.push_back(std::abs(d));
  }
  double sum2 = 0.0;
  for (double s : speed) sum2 += s * s;
  const double rms = std::sqrt(sum2 / points);
  std::vector<double> moving;
  for (int k = 0; k < points; ++k)
    if (speed[k] > 1e-6 * rms) moving.push_back(div[k]);
  if (moving.empty() || !(rms > 0.0)) return std::numeric_limits<double>::infinity();
  std::nth_element(moving.begin(), moving.begin() + moving.size() / 2, moving.end());
  return moving[moving.size() / 2] / rms;
}

// Random points of the six faces: (point, inward normal).
std::vector<std::pair<Vec<3>, Vec<3>>> face_points(int points, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.02, 0.98);
  std::vector<std::pair<Vec<3>, Vec<3>>> out;
  for (int k = 0; k < points; ++k) {
    const int axis = k % 3;
    const double side = (k / 3) % 2;
    Vec<3> x(u(rng), u(rng), u(rng)), n = Vec<3>::Zero();
    x[axis] = side;
    n[axis] = side == 0.0 ? 1.0 : -1.0;
    out.emplace_back(x, n);
  }
  return out;
}

std::vector<Vec<3>> unit_directions(int count, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> g;
  std::vector<Vec<3>> out;
  while (static_cast<int>(out.size()) < count) {
    const Vec<3> v(g(rng), g(rng), g(rng));
    if (v.norm() > 1e-6) out.push_back(v / v.norm());
  }
  return out;
}

void run_checks(const BridsonConfig& c, BridsonResult& result) {
  const DfvnField<3> wake(c.seed, wake_options(c, false)), viscous(c.seed, wake_options(c, true)),
      ring(c.seed, ring_options(c, 0.0));
  const int n = c.check_points;
  auto add = [&](std::string what, std::string field, double value, double bound) {
    result.checks.push_back(BridsonCheck{std::move(what), std::move(field), value, bound});
  };
  add("median abs(div c) / RMS speed", "wake", divergence_ratio(wake, n, c.seed), 1e-5);
  add("median abs(div c) / RMS speed", "wake viscous", divergence_ratio(viscous, n, c.seed), 1e-5);
  add("median abs(div c) / RMS speed", "ring", divergence_ratio(ring, n, c.seed), 1e-5);
  double wall_normal = 0.0, wall_normal_ring = 0.0, wall_speed_viscous = 0.0;
  for (const auto& [x, normal] : face_points(n, c.seed + 1)) {
    wall_normal = std::max(wall_normal, std::abs(wake.velocity(x).dot(normal)));
    wall_normal_ring = std::max(wall_normal_ring, std::abs(ring.velocity(x).dot(normal)));
    wall_speed_viscous = std::max(wall_speed_viscous, viscous.velocity(x).norm());
  }
  add("max abs(c . n) on the walls", "wake", wall_normal, 1e-10);
  add("max abs(c . n) on the walls", "ring", wall_normal_ring, 1e-10);
  double sphere_normal = 0.0, body_normal = 0.0, body_normal_viscous = 0.0, body_slip_viscous = 0.0, body_slip = 0.0;
  const Vec<3> sphere_centre(kRingSphere.centre[0], kRingSphere.centre[1], kRingSphere.centre[2]);
  for (const Vec<3>& dir : unit_directions(n, c.seed + 2)) {
    sphere_normal = std::max(sphere_normal, std::abs(ring.velocity(Vec<3>(sphere_centre + kRingSphere.radius * dir)).dot(dir)));
    const Vec<3> x = kWakeBody.centre + kWakeBody.radius * dir;
    const Vec<3> rigid = kWakeBody.velocity + kWakeBody.angular.cross(x - kWakeBody.centre);
    const Vec<3> relative = wake.velocity(x) - rigid, relative_viscous = viscous.velocity(x) - rigid;
    body_normal = std::max(body_normal, std::abs(relative.dot(dir)));
    body_slip = std::max(body_slip, relative.norm());
    body_normal_viscous = std::max(body_normal_viscous, std::abs(relative_viscous.dot(dir)));
    body_slip_viscous = std::max(body_slip_viscous, relative_viscous.norm());
  }
  add("max abs(c . n) on the fixed sphere", "ring", sphere_normal, 1e-8);
  add("max abs((c - V - W x r) . n) on the moving body", "wake", body_normal, 1e-8);
  add("max abs((c - V - W x r) . n) on the moving body", "wake viscous", body_normal_viscous, 1e-8);
  add("no-slip: max abs(c) on the walls", "wake viscous", wall_speed_viscous, 1e-12);
  add("no-slip: max abs(c - V - W x r) on the moving body", "wake viscous", body_slip_viscous, 1e-8);
  result.inviscid_slip = body_slip;  // not a bound: the inviscid body lets the fluid slip past it
}

// The nested fields of curl noise with k = 1..K octaves in free space differ by exactly octave k-1's field,
// once each is scaled back by its norm n_k = sqrt(sum_{o<k} g^(2o)) (field/bridson_flow.hpp).
void measure_energies(const BridsonConfig& c, BridsonResult& result) {
  std::vector<DfvnField<3>> fields;
  for (int k = 1; k <= c.octaves; ++k) {
    FieldOptions o{NoiseBasis::turning_bands, c.frequency};
    o.kind = FieldKind::curl;
    o.flow.octaves = k;
    o.flow.octave_gain = c.octave_gain;
    fields.emplace_back(c.seed, o);
  }
  auto norm = [&](int k) {
    double s = 0.0;
    for (int o = 0; o < k; ++o) s += std::pow(c.octave_gain, 2 * o);
    return std::sqrt(s);
  };
  std::mt19937_64 rng(c.seed + 3);
  const double side = 20.0 / c.frequency;  // 20 cycles of octave 0
  std::uniform_real_distribution<double> u(0.0, side);
  std::vector<double> energy(static_cast<std::size_t>(c.octaves), 0.0);
  const int points = 4 * c.check_points;
  for (int p = 0; p < points; ++p) {
    const Vec<3> x(u(rng), u(rng), u(rng));
    Vec<3> previous = Vec<3>::Zero();
    for (int k = 1; k <= c.octaves; ++k) {
      const Vec<3> scaled = norm(k) * fields[k - 1].velocity(x);
      energy[k - 1] += (scaled - previous).squaredNorm();
      previous = scaled;
    }
  }
  const double total = norm(c.octaves) * norm(c.octaves);
  for (int o = 0; o < c.octaves; ++o) {
    BridsonOctaveEnergy e{o, energy[o] / points / total, std::pow(c.octave_gain, 2 * o) / total};
    result.energies.push_back(e);
    result.checks.push_back(BridsonCheck{fmt::format("abs(energy of octave {} / a_{}^2 - 1)", o, o), "free curl noise",
                                         std::abs(e.measured / e.law - 1.0), 0.1});
  }
}

// Traces of K^2 particles, `steps` RK4 steps of the velocity, stored at every step.
template <typename Velocity>
std::vector<double> trace_all(const std::vector<Vec<3>>& starts, double time, int steps, int threads,
                              const Velocity& velocity, const FractionProgress& progress) {
  const int particles = static_cast<int>(starts.size());
  std::vector<double> traces(static_cast<std::size_t>(particles) * (steps + 1) * 3);
  const double h = time / steps;
  std::atomic<int> started{0};
#pragma omp parallel for schedule(dynamic, 4) num_threads(threads)
  for (int p = 0; p < particles; ++p) {
    const int s = started.fetch_add(1, std::memory_order_relaxed);
    if (progress && omp_get_thread_num() == 0) progress(static_cast<double>(s) / particles);
    double* out = traces.data() + static_cast<std::size_t>(p) * (steps + 1) * 3;
    Vec<3> x = starts[p];
    bool inside = true;
    for (int k = 0; k <= steps; ++k) {
      for (int j = 0; j < 3; ++j) out[3 * k + j] = x[j];
      if (k == steps || !inside) continue;
      const Vec<3> next = rk4_step(velocity, x, k * h, h);
      inside = in_cube(next) && next.allFinite();
      if (inside) x = next;
    }
  }
  return traces;
}

}  // namespace

void BridsonConfig::validate() const {
  check_noise_frequency(frequency, "bridson --frequency");
  if (frequency > 64.0) throw std::invalid_argument(fmt::format("bridson --frequency must be at most 64 (the cube holds 64 cycles), got {}", frequency));
  if (octaves < 1 || octaves > kMaxOctaves)
    throw std::invalid_argument(fmt::format("bridson --octaves must be in [1, {}], got {}", kMaxOctaves, octaves));
  if (!(octave_gain > 0.0) || !std::isfinite(octave_gain))
    throw std::invalid_argument(fmt::format("bridson --octave-gain must be a finite number > 0, got {}", octave_gain));
  if (!(boundary_width > 0.0 && boundary_width <= 0.07))
    throw std::invalid_argument(fmt::format(
        "bridson --boundary-width must be in (0, 0.07] (the moving body's blend region must clear the walls' zones), got {}",
        boundary_width));
  if (grid < 2 || grid > 256) throw std::invalid_argument(fmt::format("bridson --grid must be in [2, 256], got {}", grid));
  if (steps < 8 || steps > 100000) throw std::invalid_argument(fmt::format("bridson --trace-steps must be in [8, 100000], got {}", steps));
  if (image < 16 || image > 8192) throw std::invalid_argument(fmt::format("bridson --image must be in [16, 8192], got {}", image));
  if (check_points < 100 || check_points > 10000000)
    throw std::invalid_argument(fmt::format("bridson --check-points must be in [100, 10^7], got {}", check_points));
  check_thread_count(threads);
}

bool BridsonResult::passed() const {
  return std::all_of(checks.begin(), checks.end(), [](const BridsonCheck& c) { return c.passed(); });
}

std::vector<double> bridson_stage_weights(const BridsonConfig& config) {
  const double checks = 40.0 * config.check_points, traces = 4.0 * config.grid * config.grid * config.steps;
  return {checks, traces, 2.0 * config.steps * 300.0, traces};
}

BridsonResult run_bridson(const BridsonConfig& config, const StageProgress& progress) {
  config.validate();
  BridsonResult result;
  result.config = config;
  result.machine = machine_description();
  Stopwatch watch;
  const int threads = resolve_threads(config.threads);
  auto stage = [&](const char* name) -> FractionProgress {
    if (!progress) return {};
    return [&progress, name](double f) { progress(name, f); };
  };
  if (progress) progress("checks", 0.0);
  run_checks(config, result);
  measure_energies(config, result);
  const int k = config.grid;
  // The wake, in the body's frame: c - V.
  {
    const DfvnField<3> field(config.seed, wake_options(config, false));
    std::vector<Vec<3>> starts;
    for (int i = 0; i < k * k; ++i) starts.emplace_back(0.3 + 0.4 * ((i % k) + 0.5) / k, 0.5 + 0.2 * ((i / k) + 0.5) / k, 0.04);
    result.wake_traces = trace_all(starts, kWakeTime, config.steps, threads,
                                   [&](const Vec<3>& x, double) { return Vec<3>(field.velocity(x) - kWakeBody.velocity); },
                                   stage("wake"));
  }
  // The ring: the field of each half step's moment, built once (the noise's amplitude is measured per field).
  {
    const int moments = 2 * config.steps + 1;
    const double h = kRingTime / config.steps;
    std::vector<std::unique_ptr<DfvnField<3>>> fields(static_cast<std::size_t>(moments));
    const FractionProgress building = stage("ring fields");
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
    for (int m = 0; m < moments; ++m) {
      if (building && omp_get_thread_num() == 0) building(static_cast<double>(m) / moments);
      fields[m] = std::make_unique<DfvnField<3>>(config.seed, ring_options(config, 0.5 * h * m));
    }
    // K^2 particles in the core tube: K angles about the axis times K points of a sunflower disc of radius
    // 0.6 R about the core line.
    std::vector<Vec<3>> starts;
    constexpr double kGolden = 2.39996322972865332;  // pi (3 - sqrt 5), the sunflower's turn
    for (int a = 0; a < k; ++a)
      for (int b = 0; b < k; ++b) {
        const double phi = 2.0 * std::numbers::pi * (a + 0.5) / k;
        const double rho = 0.6 * kRingCore * std::sqrt((b + 0.5) / k), turn = kGolden * b;
        const Vec<3> radial(std::cos(phi), std::sin(phi), 0.0);
        starts.push_back(kRingStart + (kRingRadius + rho * std::cos(turn)) * radial + Vec<3>(0.0, 0.0, rho * std::sin(turn)));
      }
    result.ring_traces = trace_all(starts, kRingTime, config.steps, threads,
                                   [&](const Vec<3>& x, double t) {
                                     const int m = static_cast<int>(std::lround(2.0 * t / h));
                                     return fields[static_cast<std::size_t>(std::clamp(m, 0, moments - 1))]->velocity(x);
                                   },
                                   stage("ring"));
  }
  result.seconds = watch.seconds();
  return result;
}

std::vector<std::string> bridson_output_files() {
  return {"bridson.md", "bridson_checks.csv", "bridson_octaves.csv", "wake.png", "ring.png", "wake_traces.png",
          "ring_traces.png", "wake_traces.csv",
          "ring_traces.csv"};
}

namespace {

// A side view (x right, z up) of the unit cube: traces in grey by depth (nearer, smaller y: darker) over the
// solids (light grey discs) at the positions given, a trace hidden where a sphere stands in front of it.
GrayImage side_view(const std::vector<double>& traces, int steps, int side, const std::vector<std::pair<Vec<3>, double>>& discs) {
  GrayImage image{side, side, std::vector<std::uint8_t>(static_cast<std::size_t>(side) * side, 250)};
  for (int row = 0; row < side; ++row)
    for (int col = 0; col < side; ++col) {
      const double x = (col + 0.5) / side, z = 1.0 - (row + 0.5) / side;
      for (const auto& [centre, radius] : discs)
        if (std::hypot(x - centre[0], z - centre[2]) <= radius) image.pixels[static_cast<std::size_t>(row) * side + col] = 200;
    }
  auto plot = [&](double x, double z, double depth) {
    const auto col = static_cast<long>(std::floor(x * side)), row = static_cast<long>(std::floor((1.0 - z) * side));
    if (col < 0 || row < 0 || col >= side || row >= side) return;
    for (const auto& [centre, radius] : discs)  // hidden behind a sphere
      if (depth > centre[1] && std::hypot(x - centre[0], z - centre[2]) <= radius) return;
    auto& pixel = image.pixels[static_cast<std::size_t>(row) * side + col];
    pixel = std::min(pixel, static_cast<std::uint8_t>(std::lround(20.0 + 150.0 * std::clamp(depth, 0.0, 1.0))));
  };
  const std::size_t particles = traces.size() / (3 * (steps + 1));
  for (std::size_t p = 0; p < particles; ++p) {
    const double* t = traces.data() + p * (steps + 1) * 3;
    for (int k = 0; k < steps; ++k) {
      const double* a = t + 3 * k;
      const double* b = a + 3;
      const double length_px = std::hypot(b[0] - a[0], b[2] - a[2]) * side;
      const int samples = 1 + static_cast<int>(std::ceil(2.0 * std::min(length_px, 4.0 * side)));
      for (int q = 0; q <= samples; ++q) {
        const double s = static_cast<double>(q) / samples;
        plot(a[0] + s * (b[0] - a[0]), a[2] + s * (b[2] - a[2]), a[1] + s * (b[1] - a[1]));
      }
    }
  }
  return image;
}

std::string traces_csv(const std::vector<double>& traces, int steps) {
  std::string csv = "particle,step,x,y,z\n";
  const std::size_t particles = traces.size() / (3 * (steps + 1));
  for (std::size_t p = 0; p < particles; ++p)
    for (int k = 0; k <= steps; ++k) {
      if (k % kTraceStride != 0 && k != steps) continue;
      const double* x = traces.data() + (p * (steps + 1) + k) * 3;
      csv += fmt::format("{},{},{},{},{}\n", p, k, format_real(x[0]), format_real(x[1]), format_real(x[2]));
    }
  return csv;
}

// Mean end height and the share of particles that end above a height: how far the flow carried them.
void end_heights(const std::vector<double>& traces, int steps, double above, double& mean_z, double& share_above) {
  const std::size_t particles = traces.size() / (3 * (steps + 1));
  double sum = 0.0;
  std::size_t count = 0;
  for (std::size_t p = 0; p < particles; ++p) {
    const double z = traces[(p * (steps + 1) + steps) * 3 + 2];
    sum += z;
    count += z > above;
  }
  mean_z = sum / particles;
  share_above = static_cast<double>(count) / particles;
}

}  // namespace

std::string bridson_markdown(const BridsonResult& r) {
  const BridsonConfig& c = r.config;
  std::string md = "# Bridson et al. 2007, Figure 2: a wake and a vortex ring, with the toolbox checked\n\n";
  md += fmt::format(
      "Made by `dfvn-sample reproduce bridson --frequency {} --octaves {} --octave-gain {} --boundary-width {} --grid {} "
      "--trace-steps {} --image {} --check-points {} --seed {}`: 3D curl noise (turning bands) in the unit cube, {} octaves "
      "from {} cycles per unit length at gain {} (octave o's boundary width {} / 2^o), Bridson's boundaries (`--bound "
      "ramp`, Eq. 5 at every solid).\n\n",
      format_real(c.frequency, 6), c.octaves, format_real(c.octave_gain, 6), format_real(c.boundary_width, 6), c.grid, c.steps,
      c.image, c.check_points, c.seed, c.octaves, format_real(c.frequency, 6), format_real(c.octave_gain, 6),
      format_real(c.boundary_width, 6));
  md += fmt::format(
      "- **Wake** (`wake.png`, side view, x right, z up, nearer traces darker): `--body {}` (moving down at unit speed, "
      "spinning at 4 rad per unit time about z) with `--amplitude obstacles:0.5 --amplitude height:0.3,0.45`: turbulence "
      "only near and behind (above) the body. {}x{} particles from z = 0.04 under it (x in [0.3, 0.7], y in [0.5, 0.7]: behind its mid-plane), traced for {} in the body's frame "
      "(c - V: the body stands still, the fluid streams up past it), {} RK4 steps; a trace stops where it leaves the cube.\n",
      to_string(kWakeBody), c.grid, c.grid, format_real(kWakeTime, 3), c.steps);
  md += fmt::format(
      "- **Ring** (`ring.png`): a vortex ring of radius {} and core radius {} turning at {} about its core (`--vortex "
      "ring:...`), its centre rising from z = {} at {} per unit time for {} (the field of each moment: the ring moves, the "
      "rest stays), towards `--obstacle {}`, with `--amplitude height:0.62,0.82`: turbulent mixing above the sphere. "
      "{}x{} particles in the ring's core tube, {} RK4 steps.\n\n",
      format_real(kRingRadius, 3), format_real(kRingCore, 3), format_real(kRingStrength, 3), format_real(kRingStart[2], 3),
      format_real(kRingSpeed, 3), format_real(kRingTime, 3), to_string(kRingSphere), c.grid, c.grid, c.steps);
  md += "## Checks from the field itself\n\n";
  md += "Central differences (h = 1e-5) on random points of the cube (the median over the points where c != 0), and "
        "the fields sampled on the walls, the fixed sphere and the moving body's surface; \"wake viscous\" is the wake's "
        "field with `--viscous`.\n\n";
  md += "| check | field | measured | bound | |\n| --- | --- | --- | --- | --- |\n";
  for (const BridsonCheck& k : r.checks)
    md += fmt::format("| {} | {} | {} | {} | {} |\n", k.what, k.field, format_real(k.value, 3), format_real(k.bound, 3),
                      k.passed() ? "ok" : "**FAILED**");
  md += fmt::format(
      "\nWithout `--viscous` the fluid slips past the moving body (max |c - V - W x r| = {} on its surface) while its "
      "normal component is the body's; with it the surface carries the fluid along.\n",
      format_real(r.inviscid_slip, 3));
  md += "\n## Energy per octave\n\n";
  md += fmt::format(
      "Free 3D curl noise with k = 1..{} octaves at the same seed, {} random points of a box 20 cycles wide: scaled back by "
      "n_k = sqrt(sum_(o<k) g^(2o)), the fields of k and k + 1 octaves differ by exactly octave k's own field, so its "
      "energy is measured from the fields alone and compared with the law a_o^2 = g^(2o) / n_K^2 (g = {}: ",
      c.octaves, 4 * c.check_points, format_real(c.octave_gain, 6));
  md += std::abs(c.octave_gain - 0.79370052598409973738) < 1e-12 ? "Kolmogorov's, E(k) ~ k^(-5/3)).\n\n" : "the gain asked).\n\n";
  md += "| octave | measured energy share | law a_o^2 | ratio |\n| --- | --- | --- | --- |\n";
  for (const BridsonOctaveEnergy& e : r.energies)
    md += fmt::format("| {} | {} | {} | {} |\n", e.octave, format_real(e.measured, 4), format_real(e.law, 4),
                      format_real(e.measured / e.law, 4));
  double wake_z = 0.0, wake_above = 0.0, ring_z = 0.0, ring_above = 0.0;
  end_heights(r.wake_traces, c.steps, kWakeBody.centre[2] + kWakeBody.radius, wake_z, wake_above);
  end_heights(r.ring_traces, c.steps, kRingSphere.centre[2], ring_z, ring_above);
  md += "\n## Reading\n\n";
  md += fmt::format("- Every check {}.\n", r.passed() ? "holds" : "does **not** hold (see the table)");
  md += fmt::format(
      "- **Wake.** {} of the particles end above the body's top (z > {}); their mean end height is {}. Below the body the "
      "traces are the laminar stream parted by the body (no turbulence there: the amplitude is 0); behind it the octaves' "
      "vortices tangle them.\n",
      format_real(wake_above, 3), format_real(kWakeBody.centre[2] + kWakeBody.radius, 3), format_real(wake_z, 3));
  md += fmt::format(
      "- **Ring.** {} of the ring's particles end above the sphere's centre (z > {}), mean end height {} from {}: the ring "
      "carries its fluid up around the sphere, where the turbulence takes over.\n",
      format_real(ring_above, 3), format_real(kRingSphere.centre[2], 3), format_real(ring_z, 3), format_real(kRingStart[2], 3));
  md += fmt::format("\nFiles: `bridson_checks.csv`, `bridson_octaves.csv`, `wake_traces.png` and `ring_traces.png` (the side "
                    "views) and, with gnuplot, `wake.png` and `ring.png` (the same with axes and a title), `wake_traces.csv` "
                    "and `ring_traces.csv` (every {}th step of each trace). {} seconds on {}.\n",
                    kTraceStride, format_real(r.seconds, 3), r.machine);
  return md;
}

std::string write_bridson(const BridsonResult& r, const std::function<void(const std::string&)>& log) {
  const std::filesystem::path dir(r.config.out_dir);
  const int steps = r.config.steps;
  std::string checks = "check,field,measured,bound,passed\n";
  for (const BridsonCheck& k : r.checks)
    checks += fmt::format("{},{},{},{},{}\n", k.what, k.field, format_real(k.value), format_real(k.bound),
                          k.passed() ? 1 : 0);
  std::string octaves = "octave,measured,law\n";
  for (const BridsonOctaveEnergy& e : r.energies)
    octaves += fmt::format("{},{},{}\n", e.octave, format_real(e.measured), format_real(e.law));
  const std::string md = bridson_markdown(r);
  write_png((dir / "wake_traces.png").string(),
            side_view(r.wake_traces, steps, r.config.image, {{kWakeBody.centre, kWakeBody.radius}}));
  write_png((dir / "ring_traces.png").string(),
            side_view(r.ring_traces, steps, r.config.image,
                      {{Vec<3>(kRingSphere.centre[0], kRingSphere.centre[1], kRingSphere.centre[2]), kRingSphere.radius}}));
  write_file_atomically((dir / "bridson_checks.csv").string(), checks);
  write_file_atomically((dir / "bridson_octaves.csv").string(), octaves);
  write_file_atomically((dir / "wake_traces.csv").string(), traces_csv(r.wake_traces, steps));
  write_file_atomically((dir / "ring_traces.csv").string(), traces_csv(r.ring_traces, steps));
  write_file_atomically((dir / "bridson.md").string(), md);
  const BridsonConfig& c = r.config;
  const std::string settings =
      fmt::format("3D curl noise, {} octaves from {} cycles per unit length (gain {})\n{}x{} particles, {} RK4 steps, seed {}",
                  c.octaves, format_real(c.frequency, 6), format_real(c.octave_gain, 4), c.grid, c.grid, steps, c.seed);
  for (const auto& [name, title] :
       {std::pair<std::string, std::string>{"wake", "Bridson et al. 2007, Figure 2: the wake behind a moving, spinning sphere"},
        {"ring", "Bridson et al. 2007, Figure 2: a vortex ring carrying fluid past a sphere"}})
    draw_figure(PlotProgram::titled, (dir / (name + ".png")).string(),
                {(dir / (name + "_traces.png")).string(), title, settings + "; side view, nearer traces darker", "x",
                 "z (up)", std::to_string(c.image)},
                log ? log : std::function<void(const std::string&)>([](const std::string&) {}));
  return md;
}

}  // namespace dfvn
