// Figure 6 (Section 5.3): a texture warped on the unit sphere along the surface field.
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

void Figure6Config::validate() const {
  if (width < 8 || width > 4096 || width % 2 != 0)
    throw std::invalid_argument(fmt::format("figure6 --width must be even and in [8, 4096], got {}", width));
  if (!std::isfinite(time) || time <= 0.0 || time > 100.0)
    throw std::invalid_argument(fmt::format("figure6 --trace-time must be in (0, 100], got {}", time));
  check_noise_frequency(frequency, "figure6 --frequency");
  check_thread_count(threads);
}

double figure6_texture(double x, double y, double z) {
  (void)y;
  const double phase = 3.0 * (x + 0.25 * std::sin(2.0 * std::numbers::pi * z));
  return 0.5 + 0.5 * std::sin(2.0 * std::numbers::pi * phase);
}

namespace {

struct Setting {
  std::string label;
  int steps;
  bool projected;
};

std::vector<Setting> settings() {
  std::vector<Setting> out = {{"reference", Figure6Config::kReferenceSteps, false}};
  for (int steps : Figure6Config::kSteps) {
    out.push_back({fmt::format("rk4-{}", steps), steps, false});
    out.push_back({fmt::format("rk4-{}-projected", steps), steps, true});
  }
  return out;
}

// The equirectangular map's pixel centre on the unit sphere: longitude across, latitude down.
Vec<3> sphere_point(int col, int row, int width, int height) {
  const double lon = 2.0 * std::numbers::pi * (col + 0.5) / width - std::numbers::pi;
  const double lat = 0.5 * std::numbers::pi - std::numbers::pi * (row + 0.5) / height;
  return Vec<3>(std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat));
}

}  // namespace

std::vector<double> figure6_stage_weights(const Figure6Config&) {
  std::vector<double> w;
  for (const Setting& s : settings()) w.push_back(s.steps * (s.projected ? 2.0 : 1.0));
  for (std::size_t k = 0; k < std::size(Figure6Config::kTimeFractions); ++k) w.push_back(2.0 * Figure6Config::kTimeRowSteps);
  return w;
}

Figure6Result run_figure6(const Figure6Config& config, const StageProgress& progress) {
  config.validate();
  Figure6Result result;
  result.config = config;
  result.machine = machine_description();
  const int w = config.width, h = config.height();
  const std::size_t pixels = static_cast<std::size_t>(w) * h;
  FieldOptions options{config.noise, config.frequency};
  options.constraint = FieldConstraint::on_sphere;
  const DfvnField<3> field(config.seed, options);
  result.source = FloatImage{w, h, std::vector<float>(pixels)};
  for (int row = 0; row < h; ++row)
    for (int col = 0; col < w; ++col) {
      const Vec<3> p = sphere_point(col, row, w, h);
      result.source.values[static_cast<std::size_t>(row) * w + col] = static_cast<float>(figure6_texture(p[0], p[1], p[2]));
    }
  const int threads = resolve_threads(config.threads);
  // Every pixel traced for `time` with `steps` RK4 steps, with or without projection: the texture where
  // each trace ends, and each end's drift from the sphere.
  const auto warp = [&](const std::string& label, int steps, bool projected, double time, FloatImage& image,
                        std::vector<double>& drift, std::vector<TraceStats>& per_thread) {
    TraceOptions trace;
    trace.integrator = Integrator::rk4;
    trace.steps = steps;
    trace.reprojection = projected ? Reprojection::gauss_newton : Reprojection::none;
    const Tracer<3> tracer(field, trace);
    image = FloatImage{w, h, std::vector<float>(pixels)};
    drift.assign(pixels, 0.0);
    per_thread.assign(static_cast<std::size_t>(threads), TraceStats{});
    std::atomic<int> rows_started{0};
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
    for (int row = 0; row < h; ++row) {
      const int started = rows_started.fetch_add(1, std::memory_order_relaxed);
      if (progress && omp_get_thread_num() == 0) progress(label, static_cast<double>(started) / h);
      TraceStats& stats = per_thread[static_cast<std::size_t>(omp_get_thread_num())];
      for (int col = 0; col < w; ++col) {
        const Vec<3> q = tracer.trace(sphere_point(col, row, w, h), time, &stats);
        const std::size_t i = static_cast<std::size_t>(row) * w + col;
        image.values[i] = static_cast<float>(figure6_texture(q[0], q[1], q[2]));
        drift[i] = std::abs(q.norm() - 1.0);
      }
    }
    if (progress) progress(label, 1.0);
  };
  for (const Setting& s : settings()) {
    FloatImage image;
    std::vector<double> drift;
    std::vector<TraceStats> per_thread;
    Stopwatch watch;
    warp(s.label, s.steps, s.projected, config.time, image, drift, per_thread);
    Figure6Row row;
    row.seconds = watch.seconds();
    row.label = s.label;
    row.steps = s.steps;
    row.projected = s.projected;
    double sum = 0.0;
    for (double d : drift) {
      row.max_radius_drift = std::max(row.max_radius_drift, d);
      sum += d;
    }
    row.mean_radius_drift = sum / static_cast<double>(pixels);
    for (const TraceStats& t : per_thread) row.field_evaluations += t.field_evaluations;
    result.rows.push_back(row);
    result.images.push_back(std::move(image));
  }
  for (std::size_t r = 0; r < result.rows.size(); ++r) result.rows[r].rmse = rmse(result.images[r], result.images[0]);
  for (double fraction : Figure6Config::kTimeFractions) {
    const double t = fraction * config.time;
    FloatImage image;
    std::vector<double> drift;
    std::vector<TraceStats> per_thread;
    warp(fmt::format("t = {:g}", t), Figure6Config::kTimeRowSteps, true, t, image, drift, per_thread);
    result.row_times.push_back(t);
    result.time_images.push_back(std::move(image));
  }
  return result;
}

double figure6_largest_error(const Figure6Result& result) {
  double largest = 0.0;
  for (std::size_t r = 1; r < result.images.size(); ++r)
    for (std::size_t i = 0; i < result.images[r].values.size(); ++i)
      largest = std::max(largest, static_cast<double>(std::abs(result.images[r].values[i] - result.images[0].values[i])));
  return 255.0 * largest;  // the texture's values are in [0, 1]: 8-bit grey levels, as the RMSE
}

namespace {
std::string time_file(double t) { return fmt::format("time-{:g}.png", t); }
}  // namespace

std::vector<std::string> figure6_output_files(const Figure6Config& config) {
  std::vector<std::string> files = {"figure6.csv", "figure6.md", "source.png", "figure6.png"};
  for (const Setting& s : settings()) {
    files.push_back(s.label + ".png");
    if (s.label != "reference") files.push_back("error-" + s.label + ".png");
  }
  for (double fraction : Figure6Config::kTimeFractions) files.push_back(time_file(fraction * config.time));
  return files;
}

std::string figure6_markdown(const Figure6Result& result) {
  const Figure6Config& c = result.config;
  std::string md = "# Figure 6: a texture warped on the unit sphere\n\n";
  md += fmt::format(
      "Made by `dfvn-sample reproduce figure6 --width {} --trace-time {} --frequency {} --noise {} --seed {}`: every pixel "
      "centre of a {}x{} equirectangular map of the unit sphere is traced for t = {} along the 3D DFVN field whose first "
      "function is f_1 = (G/2) |x|^2 (so c is tangent to every sphere |x| = r) and whose second is {} noise at {} cycles "
      "per unit length; the texture (wavy stripes, a function of the 3D point) is read where the trace ends. The "
      "reference is {} RK4 steps without projection; the settings are RK4 at {} and {} steps, without projection and "
      "with Gauss-Newton reprojection onto f_1 and f_2 after every step (Eq. 10-12). RMSE is in 8-bit grey levels from "
      "float values; drift is ||x(t)| - 1| over the pixels.\n\n",
      c.width, format_real(c.time, 6), format_real(c.frequency, 6), to_string(c.noise), c.seed, c.width, c.height(),
      format_real(c.time, 6), to_string(c.noise), format_real(c.frequency, 6), Figure6Config::kReferenceSteps,
      Figure6Config::kSteps[0], Figure6Config::kSteps[1]);
  md += "| setting | steps | projection | RMSE | max drift of abs(x) | mean drift | field evaluations | seconds |\n";
  md += "| --- | --- | --- | --- | --- | --- | --- | --- |\n";
  for (const Figure6Row& r : result.rows)
    md += fmt::format("| {} | {} | {} | {} | {} | {} | {} | {} |\n", r.label, r.steps, r.projected ? "yes" : "no",
                      format_real(r.rmse, 4), format_real(r.max_radius_drift, 3), format_real(r.mean_radius_drift, 3),
                      r.field_evaluations, format_real(r.seconds, 3));
  md += "\n## Reading\n\n";
  bool all_lower = true, all_on_sphere = true;
  for (std::size_t k = 1; k + 1 < result.rows.size(); k += 2) {
    const Figure6Row& free = result.rows[k];
    const Figure6Row& projected = result.rows[k + 1];
    const bool lower = projected.rmse < free.rmse;
    all_lower = all_lower && lower;
    all_on_sphere = all_on_sphere && projected.max_radius_drift <= 1e-12;
    md += fmt::format(
        "- **{} steps.** Projection {} the RMSE against the reference: {} without, {} with ({}x). Without projection "
        "|x| drifts from 1 by up to {}; with it by up to {}, {} the 1e-12 target.\n",
        free.steps, lower ? "lowers" : "does not lower", format_real(free.rmse, 4), format_real(projected.rmse, 4),
        format_real(projected.rmse > 0.0 ? free.rmse / projected.rmse : 0.0, 3), format_real(free.max_radius_drift, 3),
        format_real(projected.max_radius_drift, 3), projected.max_radius_drift <= 1e-12 ? "within" : "outside");
  }
  md += fmt::format(
      "- **Targets.** Projection lowers the RMSE at both step counts: {}. |x| stays 1 within 1e-12 with projection at "
      "both: {}. The reference itself (no projection) drifts by up to {}.\n",
      all_lower ? "yes" : "no", all_on_sphere ? "yes" : "no", format_real(result.rows[0].max_radius_drift, 3));
  md += fmt::format(
      "\nImages (longitude across, latitude down): `source.png`, `<setting>.png`, `time-<t>.png` (the warp at t = {}, "
      "{} projected RK4 steps) and `error-<setting>.png` (|warp - reference| on a log scale: white is the largest "
      "error of any setting, {} grey levels, black {} decades below it); `figure6.png` puts them side by side. "
      "Seconds measured on {}.\n",
      [&] {
        std::string times;
        for (double t : result.row_times) times += (times.empty() ? "" : ", ") + format_real(t, 6);
        return times;
      }(),
      Figure6Config::kTimeRowSteps, format_real(figure6_largest_error(result), 3), kFigure6ErrorDecades, result.machine);
  return md;
}

std::string write_figure6(const Figure6Result& result, const FigureLog& log) {
  const std::filesystem::path dir(result.config.out_dir);
  std::string csv = "setting,steps,projection,rmse,max_radius_drift,mean_radius_drift,field_evaluations,seconds\n";
  for (const Figure6Row& r : result.rows)
    csv += fmt::format("{},{},{},{},{},{},{},{}\n", r.label, r.steps, r.projected ? "gauss-newton" : "none",
                       format_real(r.rmse), format_real(r.max_radius_drift), format_real(r.mean_radius_drift),
                       r.field_evaluations, format_real(r.seconds));
  const std::string md = figure6_markdown(result);
  write_png((dir / "source.png").string(), to_gray(result.source));
  for (std::size_t r = 0; r < result.rows.size(); ++r)
    write_png((dir / (result.rows[r].label + ".png")).string(), to_gray(result.images[r]));
  const double largest = figure6_largest_error(result);
  std::string rmses;
  for (std::size_t r = 1; r < result.rows.size(); ++r) {
    FloatImage error = result.images[r];
    for (std::size_t i = 0; i < error.values.size(); ++i) {
      const double e = 255.0 * std::abs(result.images[r].values[i] - result.images[0].values[i]);
      const double level = e > 0.0 && largest > 0.0 ? 1.0 + std::log10(e / largest) / kFigure6ErrorDecades : 0.0;
      error.values[i] = static_cast<float>(std::clamp(level, 0.0, 1.0));
    }
    write_png((dir / ("error-" + result.rows[r].label + ".png")).string(), to_gray(error));
    rmses += (rmses.empty() ? "" : " ") + format_real(result.rows[r].rmse, 3);
  }
  std::string times;
  for (std::size_t k = 0; k < result.row_times.size(); ++k) {
    write_png((dir / time_file(result.row_times[k])).string(), to_gray(result.time_images[k]));
    times += (times.empty() ? "" : " ") + fmt::format("{:g}", result.row_times[k]);
  }
  write_file_atomically((dir / "figure6.csv").string(), csv);
  write_file_atomically((dir / "figure6.md").string(), md);
  const Figure6Config& c = result.config;
  draw_figure(PlotProgram::figure6, (dir / "figure6.png").string(),
              {dir.string(), std::to_string(c.width), std::to_string(c.height()), times, rmses, format_real(largest, 3),
               fmt::format("{} noise, {} cycles per unit length, seed {}, {}x{} pixels", to_string(c.noise),
                           format_real(c.frequency, 6), c.seed, c.width, c.height())},
              log ? log : FigureLog([](const std::string&) {}));
  return md;
}

}  // namespace dfvn
