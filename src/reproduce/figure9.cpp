// Figures 9 and 10 (Section 5.5): particle traces over a sloped surface, the 2D field lifted onto the
// plane h = SX x + SY y (field/field_transform.hpp), without and with the vertical ramp.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <stdexcept>

#include <fmt/format.h>
#include <omp.h>

#include "dfvn/core/machine.hpp"
#include "dfvn/core/parallel.hpp"
#include "dfvn/core/stopwatch.hpp"
#include "dfvn/integrate/trace.hpp"
#include "dfvn/io/atomic_file.hpp"
#include "dfvn/io/csv.hpp"
#include "dfvn/io/png.hpp"
#include "dfvn/noise/noise_domain.hpp"
#include "dfvn/plot/gnuplot.hpp"
#include "dfvn/reproduce/surface_figures.hpp"

namespace dfvn {

void Figure9Config::validate() const {
  const std::string n = name();
  if (!std::isfinite(slope_x) || !std::isfinite(slope_y) || std::hypot(slope_x, slope_y) == 0.0 ||
      std::hypot(slope_x, slope_y) > 1000.0)
    throw std::invalid_argument(fmt::format("{} --slope must be finite, not 0,0 and at most 1000 long, got {},{}", n,
                                            slope_x, slope_y));
  if (ramp_figure && (!std::isfinite(ramp) || std::abs(ramp) > 1e6))
    throw std::invalid_argument(fmt::format("{} --lift-ramp must be finite and at most 1e6 in size, got {}", n, ramp));
  if (grid < 2 || grid > 1024) throw std::invalid_argument(fmt::format("{} --grid must be in [2, 1024], got {}", n, grid));
  if (!std::isfinite(time) || time <= 0.0 || time > 100.0)
    throw std::invalid_argument(fmt::format("{} --trace-time must be in (0, 100], got {}", n, time));
  if (segments < 1 || segments > 1000)
    throw std::invalid_argument(fmt::format("{} --segments must be in [1, 1000], got {}", n, segments));
  if (steps < segments || steps > 100000 || steps % segments != 0)
    throw std::invalid_argument(
        fmt::format("{} --rk4-steps must be a multiple of --segments ({}) in [{}, 100000], got {}", n, segments, segments, steps));
  if (image < 16 || image > 8192) throw std::invalid_argument(fmt::format("{} --image must be in [16, 8192], got {}", n, image));
  check_noise_frequency(frequency, n + " --frequency");
  if (!std::isfinite(bump_height) || std::abs(bump_height) > 1000.0 || !(bump_radius > 0.0 && bump_radius <= 10.0))
    throw std::invalid_argument(fmt::format("{} --bump H,R needs a finite H of at most 1000 in size and R in (0, 10], got {},{}",
                                            n, bump_height, bump_radius));
  check_thread_count(threads);
}

Figure9Result run_figure9(const Figure9Config& config, const FractionProgress& progress) {
  config.validate();
  Figure9Result result;
  result.config = config;
  result.machine = machine_description();
  FieldOptions options{config.noise, config.frequency};
  if (config.bump_height != 0.0) {  // the hill on the plane
    options.transform.lift.kind = LiftSpec::Kind::bump;
    options.transform.lift.parameters = {config.bump_height, config.bump_radius, 0.5, 0.5, config.slope_x, config.slope_y};
  } else {
    options.transform.lift.kind = LiftSpec::Kind::plane;
    options.transform.lift.parameters = {config.slope_x, config.slope_y};
  }
  options.transform.lift.ramp = config.used_ramp();
  const DfvnField<2> field(config.seed, options);
  TraceOptions trace;
  trace.integrator = Integrator::rk4;
  trace.steps = config.steps / config.segments;
  trace.reprojection = Reprojection::gauss_newton;
  const Tracer<2> tracer(field, trace);
  const int k = config.grid, points = config.segments + 1, particles = k * k;
  result.traces.assign(static_cast<std::size_t>(particles) * points * 2, 0.0);
  const int threads = resolve_threads(config.threads);
  std::vector<TraceStats> per_thread(static_cast<std::size_t>(threads));
  std::atomic<int> started{0};
  Stopwatch watch;
  // Each trace is drawn at `segments` points: one Algorithm 1 trace of steps / segments steps per
  // segment, each holding the f_i at the segment's start.
#pragma omp parallel for schedule(dynamic, 4) num_threads(threads)
  for (int p = 0; p < particles; ++p) {
    const int s = started.fetch_add(1, std::memory_order_relaxed);
    if (progress && omp_get_thread_num() == 0) progress(static_cast<double>(s) / particles);
    TraceStats& stats = per_thread[static_cast<std::size_t>(omp_get_thread_num())];
    Vec<2> x((p % k + 0.5) / k, (p / k + 0.5) / k);
    double* out = result.traces.data() + static_cast<std::size_t>(p) * points * 2;
    out[0] = x[0], out[1] = x[1];
    for (int j = 1; j < points; ++j) {
      x = tracer.trace(x, config.time / config.segments, &stats);
      out[2 * j] = x[0], out[2 * j + 1] = x[1];
    }
  }
  if (progress) progress(1.0);
  result.seconds = watch.seconds();
  for (const TraceStats& t : per_thread) result.field_evaluations += t.field_evaluations;
  // Displacement statistics, summed in particle order (independent of the thread count).
  double sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0, syy = 0.0;
  for (int p = 0; p < particles; ++p) {
    const double* t = result.traces.data() + static_cast<std::size_t>(p) * points * 2;
    const double dx = t[2 * (points - 1)] - t[0], dy = t[2 * (points - 1) + 1] - t[1];
    sx += dx, sy += dy, sxx += dx * dx, sxy += dx * dy, syy += dy * dy;
  }
  // Turns about the hill's centre of the particles starting within R / 2 of it (the angle's unwrapped increments).
  if (config.bump_height != 0.0) {
    double turns = 0.0;
    for (int p = 0; p < particles; ++p) {
      const double* t = result.traces.data() + static_cast<std::size_t>(p) * points * 2;
      if (std::hypot(t[0] - 0.5, t[1] - 0.5) > 0.5 * config.bump_radius) continue;
      double angle = 0.0;
      for (int j = 0; j + 1 < points; ++j) {
        const double a0 = std::atan2(t[2 * j + 1] - 0.5, t[2 * j] - 0.5), a1 = std::atan2(t[2 * j + 3] - 0.5, t[2 * j + 2] - 0.5);
        angle += std::remainder(a1 - a0, 2.0 * std::numbers::pi);
      }
      turns += angle / (2.0 * std::numbers::pi);
      ++result.centre_particles;
    }
    if (result.centre_particles > 0) result.centre_turns = turns / static_cast<double>(result.centre_particles);
  }
  const double n = particles;
  result.mean_dx = sx / n, result.mean_dy = sy / n;
  result.rms_displacement = std::sqrt((sxx + syy) / n);
  result.cov_xx = sxx / n - result.mean_dx * result.mean_dx;
  result.cov_xy = sxy / n - result.mean_dx * result.mean_dy;
  result.cov_yy = syy / n - result.mean_dy * result.mean_dy;
  const double half_trace = 0.5 * (result.cov_xx + result.cov_yy);
  const double root = std::hypot(0.5 * (result.cov_xx - result.cov_yy), result.cov_xy);
  result.eigen_major = half_trace + root, result.eigen_minor = half_trace - root;
  constexpr double kDegrees = 180.0 / std::numbers::pi;
  double principal = 0.5 * std::atan2(2.0 * result.cov_xy, result.cov_xx - result.cov_yy) * kDegrees;  // (-90, 90]
  if (principal <= -90.0) principal += 180.0;
  result.principal_angle = principal;
  const double slope_angle = std::atan2(config.slope_y, config.slope_x) * kDegrees;
  double between = std::fmod(std::abs(principal - slope_angle), 180.0);
  result.principal_to_slope = between > 90.0 ? 180.0 - between : between;
  const double mean_norm = std::hypot(result.mean_dx, result.mean_dy);
  const double slope_norm = std::hypot(config.slope_x, config.slope_y);
  result.mean_to_slope =
      mean_norm > 0.0 ? std::acos(std::clamp((result.mean_dx * config.slope_x + result.mean_dy * config.slope_y) /
                                                 (mean_norm * slope_norm), -1.0, 1.0)) * kDegrees
                      : 0.0;
  return result;
}

std::vector<std::string> figure9_output_files(const Figure9Config& config) {
  const std::string n = config.name();
  return {n + ".csv", n + "_traces.csv", n + ".md", n + "_traces.png", n + ".png"};
}

namespace {

// The traces as dark lines over the height field's grey shading (light = low), framed on their bounding square.
GrayImage draw_traces(const Figure9Result& r) {
  const Figure9Config& c = r.config;
  double lo_x = 0.0, hi_x = 1.0, lo_y = 0.0, hi_y = 1.0;
  for (std::size_t i = 0; i < r.traces.size(); i += 2) {
    lo_x = std::min(lo_x, r.traces[i]), hi_x = std::max(hi_x, r.traces[i]);
    lo_y = std::min(lo_y, r.traces[i + 1]), hi_y = std::max(hi_y, r.traces[i + 1]);
  }
  const double side = 1.05 * std::max(hi_x - lo_x, hi_y - lo_y);
  const double cx = 0.5 * (lo_x + hi_x), cy = 0.5 * (lo_y + hi_y);
  const int s = c.image;
  GrayImage image{s, s, std::vector<std::uint8_t>(static_cast<std::size_t>(s) * s)};
  auto world = [&](int col, int row, double& x, double& y) {
    x = cx - 0.5 * side + side * (col + 0.5) / s;
    y = cy + 0.5 * side - side * (row + 0.5) / s;  // y up
  };
  // The surface's heights at every pixel, shaded between their extremes.
  auto height = [&](double x, double y) {
    const double dx = (x - 0.5) / c.bump_radius, dy = (y - 0.5) / c.bump_radius, q = 1.0 - dx * dx - dy * dy;
    return c.slope_x * x + c.slope_y * y + (q > 0.0 ? c.bump_height * q * q * q : 0.0);
  };
  std::vector<double> heights(static_cast<std::size_t>(s) * s);
  for (int row = 0; row < s; ++row)
    for (int col = 0; col < s; ++col) {
      double x, y;
      world(col, row, x, y);
      heights[static_cast<std::size_t>(row) * s + col] = height(x, y);
    }
  const auto [lo, hi] = std::minmax_element(heights.begin(), heights.end());
  const double h_lo = *lo, h_hi = *hi;
  for (std::size_t i = 0; i < heights.size(); ++i) {
    const double t = h_hi > h_lo ? (heights[i] - h_lo) / (h_hi - h_lo) : 0.0;
    image.pixels[i] = static_cast<std::uint8_t>(std::lround(250.0 - 70.0 * t));
  }
  auto plot = [&](double x, double y, std::uint8_t value) {
    const auto col = static_cast<long>(std::floor((x - (cx - 0.5 * side)) / side * s));
    const auto row = static_cast<long>(std::floor(((cy + 0.5 * side) - y) / side * s));
    if (col >= 0 && row >= 0 && col < s && row < s) image.pixels[static_cast<std::size_t>(row) * s + col] = value;
  };
  const int points = c.segments + 1;
  for (int p = 0; p < r.particles(); ++p) {
    const double* t = r.traces.data() + static_cast<std::size_t>(p) * points * 2;
    for (int j = 0; j + 1 < points; ++j) {
      const double length_px = std::hypot(t[2 * j + 2] - t[2 * j], t[2 * j + 3] - t[2 * j + 1]) / side * s;
      const int samples = 1 + static_cast<int>(std::ceil(2.0 * std::min(length_px, 4.0 * s)));
      for (int q = 0; q <= samples; ++q) {
        const double a = static_cast<double>(q) / samples;
        plot(t[2 * j] + a * (t[2 * j + 2] - t[2 * j]), t[2 * j + 1] + a * (t[2 * j + 3] - t[2 * j + 1]), 40);
      }
    }
    plot(t[0], t[1], 0);
  }
  return image;
}

}  // namespace

std::string figure9_markdown(const Figure9Result& r) {
  const Figure9Config& c = r.config;
  const std::string n = c.name();
  std::string md = fmt::format("# {}: particle traces over a slope, {} the vertical ramp\n\n",
                               c.ramp_figure ? "Figure 9" : "Figure 10", c.ramp_figure ? "with" : "without");
  md += fmt::format(
      "Made by `dfvn-sample reproduce {} --slope {},{}{}{} --grid {} --trace-time {} --rk4-steps {} --segments {} --frequency {} "
      "--noise {} --seed {}`: {}x{} particles at the cell centres of the unit square, traced for t = {} ({} RK4 steps, "
      "Gauss-Newton reprojection after each, drawn at {} points) along the 2D field lifted onto the plane h = {} x + {} "
      "y (`--lift plane:{},{}`{}): f(x) = F(x, h(x)) for {} noise F at {} cycles per unit length.\n\n",
      n, format_real(c.slope_x, 6), format_real(c.slope_y, 6),
      c.ramp_figure ? fmt::format(" --lift-ramp {}", format_real(c.ramp, 6)) : std::string(),
      c.ramp_figure ? fmt::format(" --bump {},{}", format_real(c.bump_height, 6), format_real(c.bump_radius, 6)) : std::string(),
      c.grid,
      format_real(c.time, 6), c.steps, c.segments, format_real(c.frequency, 6), to_string(c.noise), c.seed, c.grid, c.grid,
      format_real(c.time, 6), c.steps, c.segments, format_real(c.slope_x, 6), format_real(c.slope_y, 6),
      format_real(c.slope_x, 6), format_real(c.slope_y, 6),
      c.ramp_figure ? fmt::format(" `--lift-ramp {}`", format_real(c.ramp, 6)) : std::string(), to_string(c.noise),
      format_real(c.frequency, 6));
  md += "| mean displacement (x, y) | covariance xx, xy, yy | eigenvalues | principal direction (deg from x) | "
        "principal to slope (deg) | mean to slope (deg) | RMS displacement | seconds |\n";
  md += "| --- | --- | --- | --- | --- | --- | --- | --- |\n";
  md += fmt::format("| {}, {} | {}, {}, {} | {}, {} | {} | {} | {} | {} | {} |\n\n", format_real(r.mean_dx, 4),
                    format_real(r.mean_dy, 4), format_real(r.cov_xx, 4), format_real(r.cov_xy, 4), format_real(r.cov_yy, 4),
                    format_real(r.eigen_major, 4), format_real(r.eigen_minor, 4), format_real(r.principal_angle, 4),
                    format_real(r.principal_to_slope, 4), format_real(r.mean_to_slope, 4),
                    format_real(r.rms_displacement, 4), format_real(r.seconds, 3));
  md += "## Reading\n\n";
  const double ratio = r.eigen_minor > 0.0 ? r.eigen_major / r.eigen_minor : 0.0;
  const double slope2 = c.slope_x * c.slope_x + c.slope_y * c.slope_y;
  md += fmt::format(
      "- **Spread.** The displacements (about their mean) spread most along the direction {} degrees from the slope "
      "direction grad h = ({}, {}), {} (the lift reads the noise sqrt(1 + |grad h|^2) = {} times faster along the "
      "slope, so its gradients are larger there and c = (df/dy, -df/dx) is larger across it). Their variance is {} "
      "times larger along the principal direction than across it (the gradient covariance's ratio 1 + |grad h|^2 is {}).\n",
      format_real(r.principal_to_slope, 3), format_real(c.slope_x, 4), format_real(c.slope_y, 4),
      r.principal_to_slope > 45.0 ? "closer to across the slope (along its contour lines) than along it"
                                  : "closer to along the slope than across it",
      format_real(std::sqrt(1.0 + slope2), 4), format_real(ratio, 3), format_real(1.0 + slope2, 4));
  md += fmt::format(
      "- **Drift.** The mean displacement is ({}, {}), {} long against an RMS displacement of {}, at {} degrees to "
      "the slope direction.{}\n",
      format_real(r.mean_dx, 4), format_real(r.mean_dy, 4), format_real(std::hypot(r.mean_dx, r.mean_dy), 4),
      format_real(r.rms_displacement, 4), format_real(r.mean_to_slope, 4),
      c.ramp_figure ? fmt::format(" The ramp adds the constant velocity {} (h_y, -h_x) = ({}, {}) (RMS-speed units), "
                                  "{} over t = {}.",
                                  format_real(c.ramp, 4), format_real(c.ramp * c.slope_y, 4),
                                  format_real(-c.ramp * c.slope_x, 4),
                                  fmt::format("a displacement of ({}, {})", format_real(c.ramp * c.slope_y * c.time, 4),
                                              format_real(-c.ramp * c.slope_x * c.time, 4)),
                                  format_real(c.time, 4))
                    : std::string(" Without the ramp no direction along the contour lines is preferred."));
  if (c.bump_height != 0.0)
    md += fmt::format(
        "- **Central vortex.** The surface has a hill of height {} and radius {} in the middle of the square (`--lift "
        "bump:{},{},0.5,0.5,{},{}`), steeper than the plane near its flank, so its contour lines close around it and the "
        "ramp's motion along them circles it, as the paper's Figure 9 shows: the {} particles starting within R / 2 of "
        "its centre turn {} times about it on average (counter-clockwise positive) while the stream passes around it.\n",
        format_real(c.bump_height, 4), format_real(c.bump_radius, 4), format_real(c.bump_height, 6),
        format_real(c.bump_radius, 6), format_real(c.slope_x, 6), format_real(c.slope_y, 6), r.centre_particles,
        format_real(r.centre_turns, 3));
  md += fmt::format("\nFiles: `{}.csv` (these numbers), `{}_traces.csv` (every trace point), `{}_traces.png` (the traces "
                    "over the height field, lighter = lower; y up) and, with gnuplot, `{}.png` (the same with axes, the "
                    "slope direction, the mean drift and the spread's principal direction). Seconds measured on {}.\n",
                    n, n, n, n, r.machine);
  return md;
}

std::string write_figure9(const Figure9Result& r, const FigureLog& log) {
  const Figure9Config& c = r.config;
  const std::filesystem::path dir(c.out_dir);
  const std::string n = c.name();
  std::string csv =
      "slope_x,slope_y,ramp,particles,time,steps,mean_dx,mean_dy,cov_xx,cov_xy,cov_yy,eigen_major,eigen_minor,"
      "principal_angle_deg,principal_to_slope_deg,mean_to_slope_deg,rms_displacement,bump_height,bump_radius,centre_turns,"
      "field_evaluations,seconds\n";
  csv += fmt::format("{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n", format_real(c.slope_x),
                     format_real(c.slope_y), format_real(c.used_ramp()), r.particles(), format_real(c.time), c.steps,
                     format_real(r.mean_dx), format_real(r.mean_dy), format_real(r.cov_xx), format_real(r.cov_xy),
                     format_real(r.cov_yy), format_real(r.eigen_major), format_real(r.eigen_minor),
                     format_real(r.principal_angle), format_real(r.principal_to_slope), format_real(r.mean_to_slope),
                     format_real(r.rms_displacement), format_real(c.bump_height), format_real(c.bump_radius),
                     format_real(r.centre_turns), r.field_evaluations, format_real(r.seconds));
  std::string traces = "particle,point,x0,x1\n";
  const int points = c.segments + 1;
  for (int p = 0; p < r.particles(); ++p)
    for (int j = 0; j < points; ++j) {
      const double* t = r.traces.data() + (static_cast<std::size_t>(p) * points + j) * 2;
      traces += fmt::format("{},{},{},{}\n", p, j, format_real(t[0]), format_real(t[1]));
    }
  const std::string md = figure9_markdown(r);
  write_png((dir / (n + "_traces.png")).string(), draw_traces(r));
  write_file_atomically((dir / (n + ".csv")).string(), csv);
  write_file_atomically((dir / (n + "_traces.csv")).string(), traces);
  write_file_atomically((dir / (n + ".md")).string(), md);
  const std::string surface =
      c.bump_height != 0.0 ? fmt::format("h = {} x + {} y with a hill of height {} and radius {} in the middle (background: h, "
                                         "lighter = lower)",
                                         format_real(c.slope_x, 6), format_real(c.slope_y, 6),
                                         format_real(c.bump_height, 6), format_real(c.bump_radius, 6))
                           : fmt::format("the plane h = {} x + {} y (background: h, lighter = lower)",
                                         format_real(c.slope_x, 6), format_real(c.slope_y, 6));
  draw_figure(PlotProgram::slope, (dir / (n + ".png")).string(),
              {(dir / (n + "_traces.png")).string(),
               fmt::format("{}: {}x{} particles traced over {}\n{}", c.ramp_figure ? "Figure 9" : "Figure 10", c.grid,
                           c.grid, c.ramp_figure ? fmt::format("a slope with the vertical ramp {}", format_real(c.ramp, 6))
                                                 : std::string("a slope, without the vertical ramp"),
                           surface),
               fmt::format("{} {}", format_real(c.slope_x, 9), format_real(c.slope_y, 9)),
               fmt::format("{} {}", format_real(r.mean_dx, 9), format_real(r.mean_dy, 9)),
               format_real(r.principal_angle, 9),
               fmt::format("t = {}, {} RK4 steps + reprojection, {} noise at {} cycles per unit length, seed {}",
                           format_real(c.time, 6), c.steps, to_string(c.noise), format_real(c.frequency, 6), c.seed),
               std::to_string(c.image)},
              log ? log : FigureLog([](const std::string&) {}));
  return md;
}

}  // namespace dfvn
