// Figure 7 (Section 5.4): a ring pattern warped by 2D DFVN confined to a disc (Eq. 13, the inscribed ball).
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
#include "dfvn/warp/image_warp.hpp"

namespace dfvn {

namespace {
constexpr double kRadius = 0.5;  // the inscribed ball of the unit square: centre (1/2, 1/2)
const double kMaxRadius = std::sqrt(0.5);

double ring_pattern(int rings, double r) { return 0.5 + 0.5 * std::cos(2.0 * std::numbers::pi * rings * r / kRadius); }
}  // namespace

void Figure7Config::validate() const {
  if (width < 8 || width > 8192) throw std::invalid_argument(fmt::format("figure7 --width must be in [8, 8192], got {}", width));
  if (!std::isfinite(time) || time <= 0.0 || time > 100.0)
    throw std::invalid_argument(fmt::format("figure7 --trace-time must be in (0, 100], got {}", time));
  if (steps < 1 || steps > 100000) throw std::invalid_argument(fmt::format("figure7 --rk4-steps must be in [1, 100000], got {}", steps));
  check_noise_frequency(frequency, "figure7 --frequency");
  if (!(transition_width > 0.0 && transition_width <= 0.25))
    throw std::invalid_argument(fmt::format("figure7 --boundary-width must be in (0, 0.25], got {}", transition_width));
  if (rings < 1 || rings > 1000) throw std::invalid_argument(fmt::format("figure7 --rings must be in [1, 1000], got {}", rings));
  if (bins < 2 || bins > 4096) throw std::invalid_argument(fmt::format("figure7 --bins must be in [2, 4096], got {}", bins));
  if (width3d < 8 || width3d > 2048)
    throw std::invalid_argument(fmt::format("figure7 --width-3d must be in [8, 2048], got {}", width3d));
  check_thread_count(threads);
}

Figure7Result run_figure7(const Figure7Config& config, const FractionProgress& progress) {
  config.validate();
  Figure7Result result;
  result.config = config;
  result.machine = machine_description();
  const int w = config.width;
  const std::size_t pixels = static_cast<std::size_t>(w) * w;
  FieldOptions options{config.noise, config.frequency};
  options.constraint = FieldConstraint::inside_ball;
  options.transition_width = config.transition_width;
  options.bound = Bound::eq13;
  const DfvnField<2> field(config.seed, options);
  TraceOptions trace;
  trace.integrator = Integrator::rk4;
  trace.steps = config.steps;
  trace.reprojection = Reprojection::gauss_newton;
  const Tracer<2> tracer(field, trace);
  const int threads = resolve_threads(config.threads);
  result.source = FloatImage{w, w, std::vector<float>(pixels)};
  result.warped = FloatImage{w, w, std::vector<float>(pixels)};
  std::vector<double> r0(pixels), r1(pixels);
  std::vector<TraceStats> per_thread(static_cast<std::size_t>(threads));
  std::atomic<int> rows_started{0};
  Stopwatch watch;
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
  for (int row = 0; row < w; ++row) {
    const int started = rows_started.fetch_add(1, std::memory_order_relaxed);
    if (progress && omp_get_thread_num() == 0) progress(static_cast<double>(started) / w / 3.0);
    TraceStats& stats = per_thread[static_cast<std::size_t>(omp_get_thread_num())];
    for (int col = 0; col < w; ++col) {
      const Vec<2> p((col + 0.5) / w, (row + 0.5) / w);  // row 0 at the top is y near 0: the disc is symmetric
      const Vec<2> q = tracer.trace(p, config.time, &stats);
      const std::size_t i = static_cast<std::size_t>(row) * w + col;
      r0[i] = (p - Vec<2>(0.5, 0.5)).norm();
      r1[i] = (q - Vec<2>(0.5, 0.5)).norm();
      result.source.values[i] = static_cast<float>(ring_pattern(config.rings, r0[i]));
      result.warped.values[i] = static_cast<float>(ring_pattern(config.rings, r1[i]));
    }
  }
  result.seconds = watch.seconds();
  for (const TraceStats& t : per_thread) result.field_evaluations += t.field_evaluations;
  result.bin_pixels.assign(config.bins, 0);
  result.bin_source.assign(config.bins, 0.0);
  result.bin_warped.assign(config.bins, 0.0);
  double change_inside = 0.0;
  for (std::size_t i = 0; i < pixels; ++i) {
    const double change = std::abs(static_cast<double>(result.warped.values[i]) - result.source.values[i]);
    if (r0[i] <= kRadius) {
      ++result.inside;
      result.left += r1[i] > kRadius;
      change_inside += change;
      result.max_radius_inside_end = std::max(result.max_radius_inside_end, r1[i]);
    } else {
      ++result.outside;
      result.max_change_outside = std::max(result.max_change_outside, change);
      result.max_radius_drift_outside = std::max(result.max_radius_drift_outside, std::abs(r1[i] - r0[i]));
    }
    const int bin = std::min(config.bins - 1, static_cast<int>(r0[i] / kMaxRadius * config.bins));
    ++result.bin_pixels[bin];
    result.bin_source[bin] += result.source.values[i];
    result.bin_warped[bin] += result.warped.values[i];
  }
  for (int b = 0; b < config.bins; ++b)
    if (result.bin_pixels[b] > 0) {
      result.bin_source[b] /= static_cast<double>(result.bin_pixels[b]);
      result.bin_warped[b] /= static_cast<double>(result.bin_pixels[b]);
    }
  result.mean_change_inside = result.inside > 0 ? change_inside / static_cast<double>(result.inside) : 0.0;
  // The 2D run is the first third of the work, the constructions and the 3D half the rest.
  run_figure7_constructions(config, result, [&](double f) {
    if (progress) progress((1.0 + 2.0 * f) / 3.0);
  });
  return result;
}

std::vector<std::string> figure7_output_files() {
  return {"figure7.csv", "figure7_profile.csv", "figure7.md", "source.png", "warped.png", "figure7_constructions_3d.csv",
          "warped_paper.png", "slices_3d.png", "figure7.png"};
}

namespace {
// The largest |profile difference| over the bins wholly outside (inner edge beyond the radius) or wholly inside.
double profile_difference(const Figure7Result& r, bool outside) {
  double largest = 0.0;
  const int bins = r.config.bins;
  for (int b = 0; b < bins; ++b) {
    const double lo = kMaxRadius * b / bins, hi = kMaxRadius * (b + 1) / bins;
    if (r.bin_pixels[b] == 0 || (outside ? lo <= kRadius : hi > kRadius)) continue;
    largest = std::max(largest, std::abs(r.bin_warped[b] - r.bin_source[b]));
  }
  return largest;
}
}  // namespace

std::string figure7_markdown(const Figure7Result& r) {
  const Figure7Config& c = r.config;
  std::string md = "# Figure 7: DFVN confined to a disc\n\n";
  md += fmt::format(
      "Made by `dfvn-sample reproduce figure7 --width {} --trace-time {} --rk4-steps {} --frequency {} --boundary-width {} --rings "
      "{} --bins {} --width-3d {} --noise {} --seed {}`: every pixel centre of the unit square ({}x{}) is traced for t = {} ({} RK4 "
      "steps, Gauss-Newton reprojection after each) along 2D DFVN bounded by the disc of radius 1/2 at (1/2, 1/2): f_1 "
      "is Eq. (13)'s blend of the disc's signed distance and {} noise at {} cycles per unit length, over a transition "
      "width of {}. Outside the disc f_1 is the distance itself, so c turns about the centre there. The pattern is {} "
      "rings, 0.5 + 0.5 cos(2 pi {} r / (1/2)), read where each trace ends.\n\n",
      c.width, format_real(c.time, 6), c.steps, format_real(c.frequency, 6), format_real(c.transition_width, 6), c.rings,
      c.bins, c.width3d, to_string(c.noise), c.seed, c.width, c.width, format_real(c.time, 6), c.steps, to_string(c.noise),
      format_real(c.frequency, 6), format_real(c.transition_width, 6), c.rings, c.rings);
  md += "| samples inside | left the disc | share left | largest end radius of an inside start | mean change inside | "
        "samples outside | max change outside | max radius drift outside | seconds |\n";
  md += "| --- | --- | --- | --- | --- | --- | --- | --- | --- |\n";
  md += fmt::format("| {} | {} | {} | {} | {} | {} | {} | {} | {} |\n\n", r.inside, r.left, format_real(r.share_left(), 4),
                    format_real(r.max_radius_inside_end, 9), format_real(r.mean_change_inside, 4), r.outside,
                    format_real(r.max_change_outside, 3), format_real(r.max_radius_drift_outside, 3),
                    format_real(r.seconds, 3));
  md += "## Reading\n\n";
  md += fmt::format(
      "- **Confinement.** {} of the {} samples that start in the closed disc end outside it (share {}; 0 expected); the "
      "largest end radius of such a trace is {} (the disc's radius is 0.5).\n",
      r.left, r.inside, format_real(r.share_left(), 4), format_real(r.max_radius_inside_end, 9));
  const double outside_profile = profile_difference(r, true), inside_profile = profile_difference(r, false);
  md += fmt::format(
      "- **Outside.** The radial profile is {}: the pixels outside the disc change by at most {} (value units, 1 = "
      "white), the radius of their traces by at most {}, and the profile's bins wholly outside by at most {}.\n",
      outside_profile <= 1e-6 && r.max_change_outside <= 1e-6 ? "preserved" : "not preserved",
      format_real(r.max_change_outside, 3), format_real(r.max_radius_drift_outside, 3), format_real(outside_profile, 3));
  md += fmt::format(
      "- **Inside.** The warp moves the rings: the mean change of a pixel inside is {}, and the profile's bins wholly "
      "inside change by up to {}.\n",
      format_real(r.mean_change_inside, 4), format_real(inside_profile, 4));
  md += "\n## The paper's construction beside Eq. 13, and the 3D half\n\n";
  md += fmt::format(
      "The paper builds the disc's field as a 3D cross product: \"the first vector is a 3D noise gradient ... the second "
      "vector is interpolated from (0,0,1) inside to the normal of the contour\", and the ball's (its Figure 7, bottom) "
      "\"from another noise gradient inside to the surface normal\": c = grad F x v with v = (1 - alpha) n + alpha e_z "
      "(2D, on the plane z = 0) or v = (1 - alpha) G n + alpha grad f_2 (3D), alpha Eq. 13's. That v is not a gradient in "
      "the transition zone, so c has divergence there and no function holds its streamlines (RK4 alone, {} steps); Eq. 13 "
      "blends functions instead, so c stays a cross product of gradients (Gauss-Newton reprojection). The 3D half "
      "traces the pixels of the three central slices of the unit cube ({}x{} each) through the ball of radius 1/2, a "
      "checker texture with a dark shell of 0.03 inside the sphere (the paper's outline): `slices_3d.png`, rows source, "
      "eq13, paper; columns z, y, x = 1/2.\n\n",
      c.steps, c.width3d, c.width3d);
  md += "| N | construction | starts inside | left | largest end radius of an inside start | largest radius drift "
        "outside | zone abs(div c) / RMS, median | p95 | seconds |\n| --- | --- | --- | --- | --- | --- | --- | --- | --- |\n";
  for (const Figure7ConstructionRow& k : r.constructions)
    md += fmt::format("| {} | {} | {} | {} | {} | {} | {} | {} | {} |\n", k.dimension, k.construction, k.inside, k.left,
                      format_real(k.max_end_radius_inside, 9), format_real(k.max_radius_drift_outside, 3),
                      format_real(k.zone_divergence_median, 3), format_real(k.zone_divergence_p95, 3),
                      format_real(k.seconds, 3));
  if (r.constructions.size() == 4) {
    const Figure7ConstructionRow &e2 = r.constructions[0], &p2 = r.constructions[1], &e3 = r.constructions[2],
                                 &p3 = r.constructions[3];
    md += fmt::format(
        "\n- **Divergence.** In the transition zone Eq. 13's field is divergence-free to the central differences' error "
        "(median {} in 2D, {} in 3D, of RMS |c|); the paper's is not (median {} in 2D, {} in 3D): its interpolated vector drops Eq. 13's "
        "(f~ - G d) grad alpha term.\n",
        format_real(e2.zone_divergence_median, 2), format_real(e3.zone_divergence_median, 2),
        format_real(p2.zone_divergence_median, 2), format_real(p3.zone_divergence_median, 2));
    md += fmt::format(
        "- **Confinement.** Both are tangent to the circle (sphere) and to every circle (sphere) outside: {} and {} of the "
        "inside starts leave in 2D (eq13, paper), {} and {} in 3D; outside, radii drift by at most {} and {} (2D), {} and "
        "{} (3D): the paper's RK4 without reprojection lets the radius drift by the integration error, Eq. 13's "
        "reprojection holds the distance itself.\n",
        e2.left, p2.left, e3.left, p3.left, format_real(e2.max_radius_drift_outside, 2),
        format_real(p2.max_radius_drift_outside, 2), format_real(e3.max_radius_drift_outside, 2),
        format_real(p3.max_radius_drift_outside, 2));
  }
  md += fmt::format(
      "\nFiles: `figure7.csv` (these numbers), `figure7_profile.csv` (the radial profile per bin), `source.png`, "
      "`warped.png`, `warped_paper.png` (the paper's 2D construction), `figure7_constructions_3d.csv` (the table above), "
      "`slices_3d.png`. Seconds measured on {}.\n",
      r.machine);
  return md;
}

std::string write_figure7(const Figure7Result& r, const FigureLog& log) {
  const std::filesystem::path dir(r.config.out_dir);
  std::string csv =
      "width,steps,samples_inside,left,share_left,max_end_radius_inside,mean_change_inside,samples_outside,"
      "max_change_outside,max_radius_drift_outside,field_evaluations,seconds\n";
  csv += fmt::format("{},{},{},{},{},{},{},{},{},{},{},{}\n", r.config.width, r.config.steps, r.inside, r.left,
                     format_real(r.share_left()), format_real(r.max_radius_inside_end), format_real(r.mean_change_inside),
                     r.outside, format_real(r.max_change_outside), format_real(r.max_radius_drift_outside),
                     r.field_evaluations, format_real(r.seconds));
  std::string profile = "bin,r_lo,r_hi,region,pixels,source_mean,warped_mean\n";
  const int bins = r.config.bins;
  for (int b = 0; b < bins; ++b) {
    const double lo = kMaxRadius * b / bins, hi = kMaxRadius * (b + 1) / bins;
    const char* region = hi <= kRadius ? "inside" : (lo > kRadius ? "outside" : "edge");
    profile += fmt::format("{},{},{},{},{},{},{}\n", b, format_real(lo), format_real(hi), region, r.bin_pixels[b],
                           format_real(r.bin_source[b]), format_real(r.bin_warped[b]));
  }
  const std::string md = figure7_markdown(r);
  write_png((dir / "source.png").string(), to_gray(r.source));
  write_png((dir / "warped.png").string(), to_gray(r.warped));
  write_png((dir / "warped_paper.png").string(), to_gray(r.warped_paper));
  // The slices as a 3 x 3 mosaic with a white gap of 2 pixels.
  const int side = r.config.width3d, gap = 2, mosaic = 3 * side + 2 * gap;
  FloatImage slices{mosaic, mosaic, std::vector<float>(static_cast<std::size_t>(mosaic) * mosaic, 1.0f)};
  for (int k = 0; k < 9 && k < static_cast<int>(r.slices_3d.size()); ++k)
    for (int row = 0; row < side; ++row)
      for (int col = 0; col < side; ++col)
        slices.values[static_cast<std::size_t>((k / 3) * (side + gap) + row) * mosaic + (k % 3) * (side + gap) + col] =
            r.slices_3d[k].values[static_cast<std::size_t>(row) * side + col];
  write_png((dir / "slices_3d.png").string(), to_gray(slices));
  std::string rows = "dimension,construction,samples_inside,left,max_end_radius_inside,max_radius_drift_outside,"
                     "zone_divergence_median,zone_divergence_p95,field_evaluations,seconds\n";
  for (const Figure7ConstructionRow& k : r.constructions)
    rows += fmt::format("{},{},{},{},{},{},{},{},{},{}\n", k.dimension, k.construction, k.inside, k.left,
                        format_real(k.max_end_radius_inside), format_real(k.max_radius_drift_outside),
                        format_real(k.zone_divergence_median), format_real(k.zone_divergence_p95), k.field_evaluations,
                        format_real(k.seconds));
  write_file_atomically((dir / "figure7_constructions_3d.csv").string(), rows);
  write_file_atomically((dir / "figure7.csv").string(), csv);
  write_file_atomically((dir / "figure7_profile.csv").string(), profile);
  write_file_atomically((dir / "figure7.md").string(), md);
  std::string left;  // the 2D traces that left the disc, eq13 then paper
  for (const Figure7ConstructionRow& k : r.constructions)
    if (k.dimension == 2) left += (left.empty() ? "" : " ") + std::to_string(k.left);
  const Figure7Config& c = r.config;
  draw_figure(PlotProgram::figure7, (dir / "figure7.png").string(),
              {dir.string(), std::to_string(c.width), std::to_string(c.width3d),
               fmt::format("t = {}, {} RK4 steps, {} noise at {} cycles per unit length, transition width {}, seed {}",
                           format_real(c.time, 6), c.steps, to_string(c.noise), format_real(c.frequency, 6),
                           format_real(c.transition_width, 6), c.seed),
               left.empty() ? "0 0" : left},
              log ? log : FigureLog([](const std::string&) {}));
  return md;
}

}  // namespace dfvn
