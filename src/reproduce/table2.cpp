#include <algorithm>
#include <cmath>
#include <filesystem>

#include <fmt/format.h>

#include "dfvn/core/machine.hpp"
#include "dfvn/core/parallel.hpp"
#include "dfvn/core/stopwatch.hpp"
#include "dfvn/io/atomic_file.hpp"
#include "dfvn/io/csv.hpp"
#include "dfvn/io/png.hpp"
#include "dfvn/plot/gnuplot.hpp"
#include "dfvn/reproduce/paper_tables.hpp"
#include "dfvn/reproduce/reproduce.hpp"

namespace dfvn {

namespace {

const Table2Row* find_row(const Table2Result& r, Integrator integrator, int steps, int newton) {
  for (const auto& row : r.rows)
    if (row.variant.integrator == integrator && row.variant.steps == steps && row.variant.newton_steps == newton) return &row;
  return nullptr;
}

const PaperTable2Row* find_paper_row(int steps, int newton) {
  for (const auto& row : paper_table2())
    if (row.steps == steps && row.reprojection_steps == newton) return &row;
  return nullptr;
}

// The twelve variants of Table 2 in the paper's order of rows (steps, reprojection), Euler then RK4.
std::vector<WarpVariant> table2_variants() {
  std::vector<WarpVariant> variants;
  for (int steps : {64, 512})
    for (int newton : {0, 1, 10})
      for (Integrator integrator : {Integrator::euler, Integrator::rk4}) variants.push_back({integrator, steps, newton});
  return variants;
}

const WarpVariant kReference{Integrator::rk4, 2048, 0};

// Enough digits to tell small RMSE values apart: 4 significant digits, in exponent form below 1e-4.
std::string format_rmse(double value) { return fmt::format("{:.4g}", value); }

// Which absolute values can be compared with the paper's, and why the others cannot.
std::string table2_agreement_note(const Table2Result& r) {
  const auto* euler64 = find_row(r, Integrator::euler, 64, 0);
  const auto* rk4_64 = find_row(r, Integrator::rk4, 64, 0);
  const auto* rk4_64_1 = find_row(r, Integrator::rk4, 64, 1);
  const auto* rk4_512 = find_row(r, Integrator::rk4, 512, 0);
  const auto* rk4_512_1 = find_row(r, Integrator::rk4, 512, 1);
  if (!euler64 || !rk4_64 || !rk4_64_1 || !rk4_512 || !rk4_512_1) return "";
  // Ratios ours / paper over every cell, for the float RMSE and for the wrap-around RMSE.
  double float_min = 1e300, float_max = 0.0, wrap_min = 1e300, wrap_max = 0.0;
  for (const auto& row : r.rows) {
    const PaperTable2Row* p = find_paper_row(row.variant.steps, row.variant.newton_steps);
    if (!p) continue;
    const double paper = row.variant.integrator == Integrator::euler ? p->euler_rmse : p->rk4_rmse;
    if (row.rmse == 0.0 || row.rmse_wraparound == 0.0) continue;  // RK4 512 + reprojection: see (3) below
    float_min = std::min(float_min, row.rmse / paper);
    float_max = std::max(float_max, row.rmse / paper);
    wrap_min = std::min(wrap_min, row.rmse_wraparound / paper);
    wrap_max = std::max(wrap_max, row.rmse_wraparound / paper);
  }
  std::string note;
  if (r.config.warp.pattern == WarpPattern::shader_bands) {
    note += fmt::format(
        "- **Float RMSE: no absolute value agrees.** Where ours is non-zero it is {:.2g} to {:.2g} times the paper's (Euler 64: {} vs 8.671). "
        "Two unrelated band images differ by an RMSE near 100, and every one of the paper's 12 values is below "
        "sqrt(255) = 15.97: the ceiling of an RMSE computed with 8-bit wrap-around arithmetic, where the difference and "
        "its square each wrap modulo 256 (`(a - b)**2` on uint8 arrays).\n",
        float_min, float_max, format_rmse(euler64->rmse));
    note += fmt::format(
        "- **Wrap-around RMSE: the magnitudes agree.** Computed that way on our 8-bit images (the wrap-8 columns), ours "
        "is {:.2g} to {:.2g} times the paper's in the cells where ours is non-zero: RK4 64 {} vs 6.625, RK4 64 + 1 step "
        "{} vs 3.861, RK4 512 {} vs 0.504. So the paper's RMSE was most likely computed with that arithmetic. This is "
        "our inference, because the paper's RMSE code is not published. The float RMSE is the correct measure and the "
        "one the checks above use.\n",
        wrap_min, wrap_max, format_rmse(rk4_64->rmse_wraparound), format_rmse(rk4_64_1->rmse_wraparound),
        format_rmse(rk4_512->rmse_wraparound));
  } else {
    note += fmt::format("- Setting `ours` uses a different noise, field magnitude and image from the paper's: only the "
                        "orderings can be compared (ours / paper: {:.2g} to {:.2g}).\n",
                        float_min, float_max);
  }
  note +=
      "- **What cannot agree, and why.** (1) The noise realisation: our hash is not the shader's integer hash, and a "
      "warp this strong is chaotic, so every RMSE depends on the realisation (change `--seed`). (2) Grey levels "
      "instead of the shader's viridis colours, so the colour steps between bands differ. (3) Double precision on a "
      "CPU against float32 on a GPU: round-off moves traces across band edges in the smallest cells (ours: RK4 512 + "
      "reprojection " +
      format_rmse(rk4_512_1->rmse) +
      ", paper 0.1). (4) Throughput: our CPU megapixels per second cannot be compared with GPU frames per second.\n";
  if (r.second.width != 0) {
    double worst = 0.0;  // largest relative change between the resolutions among the clearly non-zero cells
    for (const auto& row : r.rows)
      if (row.rmse > 10.0) worst = std::max(worst, std::abs(row.rmse_second / row.rmse - 1.0));
    note += fmt::format(
        "- **Resolution.** Between {} and {} pixels wide, every RMSE above 10 changes by at most {:.0f}%: {}. The small "
        "values change more (RK4 512: {} vs {}; with reprojection {} vs {}) because only a few pixels change band, "
        "and each one adds sampling noise. `--samples` averages that noise.\n",
        r.config.warp.width, r.second.width, 100.0 * worst,
        worst < 0.05 ? "these values have converged with resolution, and the paper's 3840x2160 should change them as little"
                     : "these values have NOT converged with resolution; use larger images",
        format_rmse(rk4_512->rmse), format_rmse(rk4_512->rmse_second),
        format_rmse(rk4_512_1->rmse), format_rmse(rk4_512_1->rmse_second));
  }
  return note;
}
}  // namespace

void Table2Config::validate() const {
  warp.validate();
  if (second_width != 0 && (second_width < 2 || second_width > 20000))
    throw std::invalid_argument(fmt::format("second resolution width must be 0 (none) or 2..20000, got {}", second_width));
  if (second_width != 0 && second_width * static_cast<long long>(warp.height) / warp.width < 2)
    throw std::invalid_argument("second resolution is too small for the aspect ratio");
  for (double t : figure_times)
    if (!std::isfinite(t)) throw std::invalid_argument("figure times must be finite");
}

namespace {

// The expected field evaluations per image sample of a warp: RK4 evaluates 4 times a step, Euler once,
// and Newton reprojection about once a step more for 1 iteration and 1.5-3.7 for 10 (they stop once
// converged; measured with field_evaluations), taken as 2.5.
double expected_evaluations(const WarpVariant& v) {
  const double per_step = v.integrator == Integrator::rk4 ? 4.0 : 1.0;
  return v.steps * (per_step + std::min(static_cast<double>(v.newton_steps), 2.5));
}

int second_height(const Table2Config& config) {
  return static_cast<int>(std::lround(static_cast<double>(config.warp.height) * config.second_width / config.warp.width));
}

}  // namespace

std::vector<double> table2_stage_weights(const Table2Config& config) {
  const std::vector<WarpVariant> variants = table2_variants();
  const double pixels = static_cast<double>(config.warp.width) * config.warp.height;
  std::vector<double> weights{pixels * expected_evaluations(kReference)};
  for (const WarpVariant& v : variants) weights.push_back(pixels * expected_evaluations(v));
  if (config.second_width != 0) {
    const double second = static_cast<double>(config.second_width) * second_height(config);
    weights.push_back(second * expected_evaluations(kReference));
    for (const WarpVariant& v : variants) weights.push_back(second * expected_evaluations(v));
  }
  for (std::size_t t = 0; t < config.figure_times.size(); ++t)
    weights.push_back(pixels * expected_evaluations(WarpVariant{Integrator::rk4, Table2Config::kFigureSteps, 0}));
  return weights;
}

Table2Result run_table2(const Table2Config& config, const StageProgress& progress) {
  config.validate();
  Table2Result result;
  result.config = config;
  const WarpConfig& warp = config.warp;
  result.threads = resolve_threads(warp.threads);
  result.machine = machine_description();
  const std::vector<WarpVariant> variants = table2_variants();
  const bool has_second = config.second_width != 0;
  // One stage per image warped, in table2_stage_weights' order, each reporting its rows as it goes.
  const auto stage = [&](const std::string& name) -> FractionProgress {
    if (!progress) return {};
    progress(name, 0.0);
    return [&progress, name](double f) { progress(name, f); };
  };

  result.source = source_image(warp);
  Stopwatch stopwatch;
  result.reference = warp_image(warp, kReference, nullptr, stage("reference"));
  result.reference_seconds = stopwatch.seconds();
  const double megapixels = static_cast<double>(warp.width) * warp.height * 1e-6;
  for (const WarpVariant& variant : variants) {
    const FractionProgress report = stage(variant.label());
    stopwatch.restart();
    std::int64_t evaluations = 0;
    FloatImage image = warp_image(warp, variant, &evaluations, report);
    Table2Row row;
    row.variant = variant;
    row.seconds = stopwatch.seconds();
    // A warp faster than the clock's resolution would read 0 s and print Inf.
    row.megapixels_per_second = megapixels / std::max(row.seconds, 1e-9);
    row.rmse = rmse(image, result.reference);
    row.rmse_wraparound = rmse_8bit_wraparound(to_gray(image), to_gray(result.reference));
    row.field_evaluations = evaluations;
    result.rows.push_back(row);
    result.images.push_back(std::move(image));
  }

  if (has_second) {
    result.second = warp;
    result.second.width = config.second_width;
    result.second.height = second_height(config);
    const std::string size = fmt::format("at {}x{}", result.second.width, result.second.height);
    const FloatImage reference = warp_image(result.second, kReference, nullptr, stage("reference " + size));
    for (std::size_t i = 0; i < variants.size(); ++i)
      result.rows[i].rmse_second =
          rmse(warp_image(result.second, variants[i], nullptr, stage(variants[i].label() + " " + size)), reference);
  }

  for (double t : config.figure_times) {
    WarpConfig timed = warp;
    timed.time = t;
    result.timeline.push_back(warp_image(timed, WarpVariant{Integrator::rk4, Table2Config::kFigureSteps, 0}, nullptr,
                                         stage(fmt::format("figure 5 at t = {:g}", t))));
  }
  return result;
}

Table2Conclusions table2_conclusions(const Table2Result& r, bool second) {
  const auto value = [second](const Table2Row* row) { return second ? row->rmse_second : row->rmse; };
  Table2Conclusions c;
  const auto* rk4_512 = find_row(r, Integrator::rk4, 512, 0);
  c.rk4_512_differs_from_reference = rk4_512 && value(rk4_512) > 0.0;
  c.rk4_beats_euler = c.more_steps_lower_rmse = c.reprojection_lowers_rmse = true;
  for (int newton : {0, 1, 10})
    for (int steps : {64, 512}) {
      const auto* e = find_row(r, Integrator::euler, steps, newton);
      const auto* k = find_row(r, Integrator::rk4, steps, newton);
      c.rk4_beats_euler = c.rk4_beats_euler && e && k && value(k) < value(e);
    }
  for (Integrator i : {Integrator::euler, Integrator::rk4}) {
    for (int newton : {0, 1, 10}) {
      const auto* few = find_row(r, i, 64, newton);
      const auto* many = find_row(r, i, 512, newton);
      c.more_steps_lower_rmse = c.more_steps_lower_rmse && few && many && value(many) < value(few);
    }
    for (int steps : {64, 512}) {
      const auto* plain = find_row(r, i, steps, 0);
      const auto* projected = find_row(r, i, steps, 1);
      c.reprojection_lowers_rmse = c.reprojection_lowers_rmse && plain && projected && value(projected) < value(plain);
    }
  }
  const auto* rk4 = find_row(r, Integrator::rk4, 64, 1);
  const auto* euler = find_row(r, Integrator::euler, 512, 0);
  c.rk4_64_reproject_beats_euler_512 = rk4 && euler && value(rk4) < value(euler) && rk4->seconds < euler->seconds;
  c.rk4_64_reproject_does_less_work = rk4 && euler && rk4->field_evaluations < euler->field_evaluations;
  return c;
}

std::string table2_markdown(const Table2Result& r) {
  const WarpConfig& w = r.config.warp;
  const bool has_second = r.second.width != 0;
  std::string md = "# Table 2, reproduced\n\n";
  md += fmt::format(
      "Setting `{}`: image warping along 2D DFVN (Section 5.2). Each pixel of a {}x{} image ({} sample{} per pixel) "
      "is traced for t = {:g} and the {} pattern is evaluated exactly where the trace lands. Noise: {} at {:.4g} "
      "cycles per image width, field RMS speed {:.4g} image widths per unit time, seed {}.",
      to_string(r.config.setting), w.width, w.height, w.samples, w.samples > 1 ? "s" : "", w.time,
      w.pattern == WarpPattern::shader_bands ? "shader's wave-band" : "sine-stripe", to_string(w.noise), w.frequency,
      w.field_magnitude, w.seed);
  if (r.config.setting == WarpSetting::shader)
    md += fmt::format(
        " This is the shader's field: its noise (2D quintic gradient noise, gradient components uniform in [-1, 1]) "
        "at noise_scale {:g} lattice cells per width, i.e. {:.4g} cycles of 2 pi / k_eff, and its unnormalised "
        "velocity rot90({:g} grad n({:g} x)), whose RMS speed is {:g} sigma = {:.4g} with sigma^2 = E|grad n|^2 = "
        "{:.4f} in closed form (src/noise/gradient_noise.cpp).",
        kShaderNoiseScale, w.frequency, kShaderNoiseScale, kShaderNoiseScale, kShaderNoiseScale, w.field_magnitude,
        std::pow(w.field_magnitude / kShaderNoiseScale, 2));
  md += fmt::format(
      "\n\nRMSE is against 2048 RK4 steps, in 8-bit units (255 x the difference of grey values in [0, 1]) computed "
      "from float values, so a difference far below one grey level still counts. **Ours**: CPU throughput in "
      "megapixels per second on {} thread(s) of {} (the reference took {:.2f} s){}. **Paper**: FPS on an M1 Max GPU "
      "at 1024x576 and RMSE over 8-bit colour at 3840x2160.\n\n",
      r.threads, r.machine, r.reference_seconds,
      has_second ? fmt::format("; RMSE also at {}x{} (\"RMSE {}\")", r.second.width, r.second.height, r.second.width) : "");
  const std::string second = has_second ? fmt::format(" RMSE {} |", r.second.width) : "";
  md += fmt::format("| steps | reprojection | Euler RMSE |{} Euler wrap-8 | paper Euler RMSE | RK4 RMSE |{} RK4 wrap-8 | "
                    "paper RK4 RMSE | Euler MP/s | RK4 MP/s | paper Euler FPS | paper RK4 FPS |\n",
                    has_second ? " Euler" + second : "", has_second ? " RK4" + second : "");
  md += fmt::format("| --- | --- | --- |{} --- | --- | --- |{} --- | --- | --- | --- | --- | --- |\n", has_second ? " --- |" : "",
                    has_second ? " --- |" : "");
  for (int steps : {64, 512})
    for (int newton : {0, 1, 10}) {
      const auto* e = find_row(r, Integrator::euler, steps, newton);
      const auto* k = find_row(r, Integrator::rk4, steps, newton);
      const PaperTable2Row* p = find_paper_row(steps, newton);
      if (!e || !k || !p) continue;
      const auto cells = [&](const Table2Row& row, double paper) {
        std::string text = fmt::format(" {} |", format_rmse(row.rmse));
        if (has_second) text += fmt::format(" {} |", format_rmse(row.rmse_second));
        return text + fmt::format(" {} | {} |", format_rmse(row.rmse_wraparound), paper);
      };
      md += fmt::format("| {} | {} |", steps,
                        newton == 0 ? std::string("no") : fmt::format("{} step{}", newton, newton > 1 ? "s" : ""));
      md += cells(*e, p->euler_rmse) + cells(*k, p->rk4_rmse);
      md += fmt::format(" {:.3g} | {:.3g} | {} | {} |\n", e->megapixels_per_second, k->megapixels_per_second, p->euler_fps,
                        p->rk4_fps);
    }
  md += "\nwrap-8: RMSE of the 8-bit images with wrap-around arithmetic (see below), for comparison with the paper only.\n";

  const auto yes = [](bool b) { return b ? "holds" : "DOES NOT hold"; };
  const Table2Conclusions c = table2_conclusions(r);
  const Table2Conclusions c2 = has_second ? table2_conclusions(r, true) : c;
  const auto both = [&](bool main, bool at_second) {
    if (!has_second) return std::string(yes(main));
    return fmt::format("{} at {}, {} at {}", yes(main), r.config.warp.width, yes(at_second), r.second.width);
  };
  const auto* rk4_512 = find_row(r, Integrator::rk4, 512, 0);
  const auto* rk4 = find_row(r, Integrator::rk4, 64, 1);
  const auto* euler = find_row(r, Integrator::euler, 512, 0);
  md += "\n## The paper's conclusions, each a strict inequality on our float RMSE\n\n";
  if (rk4_512)
    md += fmt::format("- RK4 with 512 steps is not the reference (RMSE > 0; {} at {}): {}.\n", format_rmse(rk4_512->rmse),
                      w.width, both(c.rk4_512_differs_from_reference, c2.rk4_512_differs_from_reference));
  md += fmt::format("- RK4 has a lower RMSE than Euler at equal steps and reprojection, in all 6 rows: {}.\n",
                    both(c.rk4_beats_euler, c2.rk4_beats_euler));
  md += fmt::format("- 512 steps have a lower RMSE than 64, for both integrators and every reprojection: {}.\n",
                    both(c.more_steps_lower_rmse, c2.more_steps_lower_rmse));
  md += fmt::format("- One Newton reprojection step lowers the RMSE, for both integrators at 64 and 512 steps: {}.\n",
                    both(c.reprojection_lowers_rmse, c2.reprojection_lowers_rmse));
  if (rk4 && euler) {
    md += fmt::format(
        "- 64 RK4 steps with 1 reprojection step beat 512 Euler steps without reprojection in RMSE ({} vs {}) and "
        "in time ({:.3f} s vs {:.3f} s): {}.\n",
        format_rmse(rk4->rmse), format_rmse(euler->rmse), rk4->seconds, euler->seconds,
        both(c.rk4_64_reproject_beats_euler_512, c2.rk4_64_reproject_beats_euler_512));
    md += fmt::format("  Work: {:.0f} against {:.0f} field evaluations per sample: {}.\n",
                      static_cast<double>(rk4->field_evaluations) / (static_cast<double>(w.width) * w.height * w.samples),
                      static_cast<double>(euler->field_evaluations) / (static_cast<double>(w.width) * w.height * w.samples),
                      c.rk4_64_reproject_does_less_work ? "fewer" : "NOT fewer");
  }
  md += "\n## Our numbers beside the paper's\n\n";
  md += table2_agreement_note(r);
  return md;
}

std::vector<std::string> table2_output_files(const Table2Config& config) {
  std::vector<std::string> files = {"table2.csv", "table2.md", "timeline.csv"};
  for (const WarpVariant& variant : table2_variants()) files.push_back(variant.label() + ".png");
  for (double t : config.figure_times) files.push_back(fmt::format("time-{:g}.png", t));
  for (const char* name : {"source.png", "reference.png", "figure5.png"}) files.emplace_back(name);
  return files;
}

std::string write_table2(const std::string& out_dir, const Table2Result& r, const Log& log) {
  const auto path = [&](const std::string& name) { return (std::filesystem::path(out_dir) / name).string(); };
  std::string csv =
      "integrator,steps,reprojection_steps,rmse,seconds,megapixels_per_second,width,height,threads,field_evaluations,"
      "rmse_second,second_width,second_height,samples,setting,rmse_8bit_wraparound\n";
  for (const auto& row : r.rows)
    csv += fmt::format("{},{},{},{},{:.6f},{},{},{},{},{},{},{},{},{},{},{}\n", to_string(row.variant.integrator),
                       row.variant.steps, row.variant.newton_steps, format_real(row.rmse), row.seconds,
                       format_real(row.megapixels_per_second, 6),
                       r.config.warp.width, r.config.warp.height, r.threads, row.field_evaluations,
                       // Without a second resolution its columns are empty: nothing was measured there.
                       r.second.width != 0 ? format_real(row.rmse_second) : std::string(),
                       r.second.width != 0 ? std::to_string(r.second.width) : std::string(),
                       r.second.width != 0 ? std::to_string(r.second.height) : std::string(), r.config.warp.samples,
                       to_string(r.config.setting), format_real(row.rmse_wraparound));
  std::string timeline = "time,steps,file\n";
  for (std::size_t i = 0; i < r.timeline.size(); ++i)
    timeline += fmt::format("{},{},time-{:g}.png\n", format_real(r.config.figure_times[i]), Table2Config::kFigureSteps,
                            r.config.figure_times[i]);
  const std::string md = table2_markdown(r);
  for (const auto& [name, text] : {std::pair{"table2.csv", csv}, {"table2.md", md}, {"timeline.csv", timeline}})
    write_file_atomically(path(name), text);
  for (std::size_t i = 0; i < r.rows.size(); ++i) write_png(path(r.rows[i].variant.label() + ".png"), to_gray(r.images[i]));
  for (std::size_t i = 0; i < r.timeline.size(); ++i)
    write_png(path(fmt::format("time-{:g}.png", r.config.figure_times[i])), to_gray(r.timeline[i]));
  write_png(path("source.png"), to_gray(r.source));
  write_png(path("reference.png"), to_gray(r.reference));
  std::string times, rmse_texts;
  for (std::size_t i = 0; i < r.timeline.size() && i < 3; ++i) times += fmt::format("{:g} ", r.config.figure_times[i]);
  for (int steps : {64, 512})
    for (Integrator integrator : {Integrator::euler, Integrator::rk4})
      for (int newton : {0, 1}) {
        const Table2Row* row = find_row(r, integrator, steps, newton);
        rmse_texts += (row ? format_rmse(row->rmse) : std::string("-")) + " ";
      }
  const WarpConfig& w = r.config.warp;
  draw_figure(PlotProgram::figure5, path("figure5.png"),
              {out_dir, std::to_string(w.width), std::to_string(w.height), times, rmse_texts,
               fmt::format("{} noise, {} cycles per width, RMS speed {}, t = {}, seed {}, {}x{} pixels", to_string(w.noise),
                           format_real(w.frequency, 4), format_real(w.field_magnitude, 4), format_real(w.time, 4), w.seed,
                           w.width, w.height)},
              log);
  return md;
}

}  // namespace dfvn
