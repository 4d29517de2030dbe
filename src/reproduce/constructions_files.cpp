// The files of `reproduce constructions` (reproduce/constructions.hpp): the CSV, the Markdown reading,
// Figure 1's streamlines and its PNG.
#include <algorithm>
#include <cmath>
#include <filesystem>

#include <fmt/format.h>

#include "dfvn/io/atomic_file.hpp"
#include "dfvn/io/csv.hpp"
#include "dfvn/plot/gnuplot.hpp"
#include "dfvn/reproduce/constructions.hpp"

namespace dfvn {

namespace {

// The divergence targets (issue 26): median |div c| / |Dc| <= 1e-8, p95 <= 1e-6.
constexpr double kMedianTarget = 1e-8, kP95Target = 1e-6;

bool meets_divergence_targets(const ConstructionField& f) {
  return f.divergence_median <= kMedianTarget && f.divergence_p95 <= kP95Target;
}

std::string field_name(const ConstructionField& f) {
  return fmt::format("{}D {} {}", f.dimension, to_string(f.construction), to_string(f.noise));
}

std::string reprojection_name(Reprojection r) { return r == Reprojection::none ? "none" : std::string(to_string(r)); }

const ConstructionTraceRow* find_trace(const ConstructionField& f, Integrator integrator, int steps, Reprojection r) {
  for (const auto& row : f.traces)
    if (row.variant.integrator == integrator && row.variant.steps == steps && row.variant.reprojection == r) return &row;
  return nullptr;
}

const ConstructionField* find_field(const ConstructionsResult& r, int dimension, FieldKind kind, NoiseBasis noise) {
  for (const auto& f : r.fields)
    if (f.dimension == dimension && f.kind == kind && f.noise == noise) return &f;
  return nullptr;
}

std::string g3(double value) { return fmt::format("{:.3g}", value); }
std::string percent(double fraction) { return fmt::format("{:.2f}%", 100.0 * fraction); }

// (integrator, steps) in the tables' column order.
const std::pair<Integrator, int> kColumns[] = {
    {Integrator::euler, 64}, {Integrator::rk4, 64}, {Integrator::euler, 512}, {Integrator::rk4, 512}};

std::string field_table(const ConstructionsResult& r) {
  std::string md =
      "| field | \\|div c\\|/\\|Dc\\| median | p95 | max | targets | ns / evaluation | RMS \\|c\\| | q01 | q10 | q50 | q90 | "
      "q99 | below 1% of RMS |\n| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |\n";
  for (const auto& f : r.fields)
    md += fmt::format("| {} | {} | {} | {} | {} | {:.0f} | {:.3f} | {} | {} | {} | {} | {} | {} |\n", field_name(f),
                      g3(f.divergence_median), g3(f.divergence_p95), g3(f.divergence_max),
                      meets_divergence_targets(f) ? "met" : "**missed**", f.ns_per_evaluation, f.speed_rms, g3(f.speed_q01),
                      g3(f.speed_q10), g3(f.speed_q50), g3(f.speed_q90), g3(f.speed_q99), percent(f.fraction_below_1pct));
  return md;
}

std::string accuracy_table(const ConstructionsResult& r) {
  std::string md = "| field | reprojection |";
  for (const auto& [integrator, steps] : kColumns) md += fmt::format(" {} {} |", to_string(integrator), steps);
  md += "\n| --- | --- | --- | --- | --- | --- |\n";
  for (const auto& f : r.fields)
    for (Reprojection rep : {Reprojection::none, Reprojection::gauss_newton}) {
      md += fmt::format("| {} | {} |", field_name(f), reprojection_name(rep));
      for (const auto& [integrator, steps] : kColumns) {
        const ConstructionTraceRow* row = find_trace(f, integrator, steps, rep);
        md += row ? fmt::format(" {} |", g3(row->endpoint_rmse)) : std::string(" none exists |");
      }
      md += "\n";
    }
  return md;
}

std::string escape_table(const ConstructionsResult& r) {
  constexpr int steps = ConstructionsConfig::kEscapeSteps;
  std::string md = "| field | reprojection |";
  for (Integrator integrator : {Integrator::euler, Integrator::rk4})
    md += fmt::format(" {} {}: cube / obstacle |", to_string(integrator), steps);
  md += "\n| --- | --- | --- | --- |\n";
  for (const auto& f : r.fields)
    for (Reprojection rep : {Reprojection::none, Reprojection::gauss_newton}) {
      md += fmt::format("| {} | {} |", field_name(f), reprojection_name(rep));
      for (Integrator integrator : {Integrator::euler, Integrator::rk4}) {
        const ConstructionTraceRow* row = find_trace(f, integrator, steps, rep);
        md += row ? fmt::format(" {} / {} |", percent(row->escape_cube), percent(row->escape_obstacle))
                  : std::string(" none exists |");
      }
      md += "\n";
    }
  return md;
}

std::string claim_reading(const ConstructionsResult& r) {
  const std::vector<ClaimCell> cells = constructions_claim(r);
  const auto holding = static_cast<std::size_t>(std::count_if(cells.begin(), cells.end(), [](const ClaimCell& c) { return c.holds(); }));
  const bool holds = !cells.empty() && holding == cells.size();
  std::string md = fmt::format(
      "The issue's claim: the cross-product field (DFVN, bitangent) **with reprojection** has a lower end-point RMSE "
      "than curl noise on the same basis at equal integrator and steps. One cell per dimension, basis, integrator "
      "and step count.\n\n**Verdict: {}** (it holds in {} of {} cells).\n",
      holds ? "holds" : "does not hold", holding, cells.size());
  if (!holds) {
    md += "\nCells where it does not hold (reprojected RMSE >= curl RMSE), with the cross product's RMSE without "
          "reprojection beside them:\n\n";
    int field_before = 0, failing = 0;
    for (const ClaimCell& c : cells) {
      if (c.holds()) continue;
      ++failing;
      const ConstructionField* cross = find_field(r, c.dimension, FieldKind::dfvn, c.noise);
      const ConstructionTraceRow* plain = cross ? find_trace(*cross, c.integrator, c.steps, Reprojection::none) : nullptr;
      field_before += plain && c.curl < plain->endpoint_rmse;
      md += fmt::format("- {}D {} {} {} steps: {} reprojected against {} curl ({} without reprojection)\n", c.dimension,
                        to_string(c.noise), to_string(c.integrator), c.steps, g3(c.reprojected), g3(c.curl),
                        plain ? g3(plain->endpoint_rmse) : std::string("?"));
    }
    md += fmt::format(
        "\nIn {} of these {} cells curl noise's RMSE is already below the cross product's without reprojection: "
        "there the two fields differ in how hard they are to integrate (3D curl noise and the cross product are "
        "different fields), and reprojection, which lowers the cross product's own RMSE, does not close that gap.\n",
        field_before, failing);
  }
  md += "\nBy how much:\n\n";
  for (int n : {2, 3})
    for (Integrator integrator : {Integrator::euler, Integrator::rk4}) {
      int total = 0, held = 0;
      for (const ClaimCell& c : cells)
        if (c.dimension == n && c.integrator == integrator) {
          ++total;
          held += c.holds();
        }
      if (total > 0) md += fmt::format("- {}D {}: holds in {} of {} cells.\n", n, to_string(integrator), held, total);
    }
  // Where it holds, by how much: the median ratio reprojected / curl, per dimension and step count.
  for (int n : {2, 3})
    for (int steps : {64, 512}) {
      std::vector<double> ratios;
      for (const ClaimCell& c : cells)
        if (c.dimension == n && c.steps == steps && c.curl > 0.0) ratios.push_back(c.reprojected / c.curl);
      if (ratios.empty()) continue;
      std::sort(ratios.begin(), ratios.end());
      md += fmt::format("- {}D, {} steps: reprojected / curl RMSE from {} to {} over the bases and integrators.\n", n, steps,
                        g3(ratios.front()), g3(ratios.back()));
    }
  // 2D: is the unreprojected cross-product field the curl field? Then reprojection alone makes the difference.
  int same = 0, compared = 0;
  for (const auto& f : r.fields) {
    if (f.dimension != 2 || f.kind != FieldKind::dfvn) continue;
    const ConstructionField* curl = find_field(r, 2, FieldKind::curl, f.noise);
    if (!curl) continue;
    for (const auto& [integrator, steps] : kColumns) {
      const auto* a = find_trace(f, integrator, steps, Reprojection::none);
      const auto* b = find_trace(*curl, integrator, steps, Reprojection::none);
      if (!a || !b) continue;
      ++compared;
      same += a->endpoint_rmse == b->endpoint_rmse;
    }
  }
  if (compared > 0)
    md += fmt::format(
        "- 2D: without reprojection the DFVN and curl RMSE are equal in {} of {} cells{}.\n", same, compared,
        same == compared ? " (c = rot90 grad psi is one field up to its sign, so the 2D comparison is reprojection against "
                           "none on the same field)"
                         : "");
  md += "- 3D: curl noise (three potentials) and the cross product (two functions) are different fields with the same "
        "RMS speed and frequency, so the 3D comparison is between constructions, not only the reprojection.\n";
  return md;
}

std::string divergence_reading(const ConstructionsResult& r) {
  std::string missed;
  double worst_median = 0.0, worst_p95 = 0.0;
  for (const auto& f : r.fields) {
    worst_median = std::max(worst_median, f.divergence_median);
    worst_p95 = std::max(worst_p95, f.divergence_p95);
    if (!meets_divergence_targets(f)) missed += (missed.empty() ? "" : ", ") + field_name(f);
  }
  return fmt::format(
      "- **Divergence** (targets median <= 1e-8, p95 <= 1e-6, on {} uniform random points per field): {}; the worst "
      "median is {} and the worst p95 {}.\n",
      r.config.divergence_points, missed.empty() ? "met by every field" : "**missed** by " + missed, g3(worst_median),
      g3(worst_p95));
}

std::string speed_reading(const ConstructionsResult& r) {
  std::string md;
  // Cost of curl noise against the cross product on the same basis, and of bitangent's separate form.
  for (int n : {2, 3}) {
    std::string ratios;
    for (NoiseBasis b : kAllNoiseBases) {
      const auto* curl = find_field(r, n, FieldKind::curl, b);
      const auto* cross = find_field(r, n, FieldKind::dfvn, b);
      if (curl && cross && cross->ns_per_evaluation > 0.0)
        ratios += fmt::format("{}{} {:.2f}", ratios.empty() ? "" : ", ", to_string(b), curl->ns_per_evaluation / cross->ns_per_evaluation);
    }
    md += fmt::format("- **Cost, {}D**: curl / cross-product ns per evaluation: {}.{}\n", n, ratios,
                      n == 2 ? " In 2D both are one field computed by one gradient of the basis, so these ratios "
                               "show how far the timing itself varies on this machine."
                             : "");
  }
  const auto* fused = find_field(r, 3, FieldKind::dfvn, NoiseBasis::simplex);
  const auto* separate = find_field(r, 3, FieldKind::dfvn, NoiseBasis::simplex_separate);
  if (fused && separate)
    md += fmt::format(
        "- **Bitangent, 3D**: the separate form costs {:.2f}x the fused one here (one CPU thread; seed 004 reports "
        "1.95x on a GPU). The fused form has {} of its points below 1% of the RMS speed against {} separate (q01 "
        "{} against {}): the shared envelope.\n",
        separate->ns_per_evaluation / fused->ns_per_evaluation, percent(fused->fraction_below_1pct),
        percent(separate->fraction_below_1pct), g3(fused->speed_q01), g3(separate->speed_q01));
  double lo = 1e300, hi = 0.0;
  for (const auto& f : r.fields) {
    lo = std::min(lo, f.speed_rms);
    hi = std::max(hi, f.speed_rms);
  }
  md += fmt::format("- **RMS |c|** over {} points is {:.3f} to {:.3f} (every field is normalised to 1).\n",
                    r.config.speed_points, lo, hi);
  return md;
}

std::string escape_reading(const ConstructionsResult& r) {
  // Totals over the fields and variants: curl, cross product without and with reprojection.
  double curl = 0.0, none = 0.0, projected = 0.0, curl_max = 0.0, projected_max = 0.0;
  int curl_n = 0, none_n = 0, projected_n = 0;
  for (const auto& f : r.fields)
    for (const auto& row : f.traces) {
      if (row.variant.steps != ConstructionsConfig::kEscapeSteps) continue;
      const double e = row.escape_cube + row.escape_obstacle;
      if (f.kind == FieldKind::curl) {
        curl += e;
        ++curl_n;
        curl_max = std::max(curl_max, e);
      } else if (row.variant.reprojection == Reprojection::none) {
        none += e;
        ++none_n;
      } else {
        projected += e;
        ++projected_n;
        projected_max = std::max(projected_max, e);
      }
    }
  std::string md = fmt::format(
      "- **Escapes** (cube with Bridson's ramp of width {:g} on its faces and a sphere obstacle of radius {:g} at the "
      "centre; {} uniform starts outside it, one raw trace each, no retracing): curl noise (no reprojection exists) "
      "ends outside the cube or inside the obstacle in {} of its traces on average (at most {}), the cross product "
      "without reprojection in {}, with reprojection in {} (at most {}).",
      ConstructionsConfig::kBoundaryWidth, ConstructionsConfig::kObstacleRadius, r.config.escape_starts,
      percent(curl / std::max(curl_n, 1)), percent(curl_max), percent(none / std::max(none_n, 1)),
      percent(projected / std::max(projected_n, 1)), percent(projected_max));
  md += projected_max > 0.0
            ? " Reprojection does not make every raw trace stay: a step can jump across the wall where f_1 is "
              "ramped to 0 (`trace_points` and CNJ retrace such ends with more steps).\n"
            : " No reprojected trace escaped.\n";
  return md;
}

}  // namespace

std::string constructions_markdown(const ConstructionsResult& r) {
  const ConstructionsConfig& c = r.config;
  std::string md = "# The divergence-free constructions side by side (issue 26)\n\n";
  md += fmt::format(
      "`dfvn-sample reproduce constructions --frequency {:g} --trace-time {:g} --divergence-points {} --speed-points {} "
      "--trace-starts {} --escape-starts {} --seed {}`: {} thread(s) of {}, {:.1f} s.\n\n",
      c.frequency, c.trace_time, c.divergence_points, c.speed_points, c.trace_starts, c.escape_starts, c.seed, r.threads,
      r.machine, r.seconds);
  md +=
      "Constructions, every one at the same frequency ({:g} cycles per unit length) and RMS |c| = 1, on every noise "
      "basis: **curl** (Bridson et al. 2007: c = (dpsi/dy, -dpsi/dx) in 2D, curl of three potentials in 3D; no "
      "reprojection exists for it, since its streamlines are not intersections of iso-surfaces, paper Section 3.3), "
      "**bitangent** (seed 004: the cross product of two simplex gradients, 3D; `simplex` is its one-traversal fused "
      "form, `simplex-separate` its reference form with one traversal per function) and **dfvn** (the cross product "
      "on the other bases, and in 2D on every basis). Bitangent noise is the DFVN field on simplex noise, so it has "
      "DFVN's reprojection.\n\n";
  md = fmt::format(fmt::runtime(md), c.frequency);
  md += "## Field: divergence, cost and speed distribution\n\n";
  md += fmt::format(
      "|div c|/|Dc| from central differences on {} uniform random points over 1000 noise cycles per side "
      "(`field --diagnose`); ns per evaluation and the |c| quantiles on {} other points, one thread (wall clock: "
      "varies between runs and with the machine's load).\n\n",
      c.divergence_points, c.speed_points);
  md += field_table(r);
  md += "\n## Tracing accuracy (as Table 2)\n\n";
  md += fmt::format(
      "End-point RMSE sqrt(mean |x_end - x_ref|^2) in length units over {} uniform starts in [0,1]^N, traced for t = "
      "{:g} in the free field, against 2048 RK4 steps without reprojection of the same field. Reprojection: "
      "Gauss-Newton, up to 10 updates after every step (the tracer's default). Curl noise: none exists, so its "
      "reprojection row says so instead of a number.\n\n",
      c.trace_starts, c.trace_time);
  md += accuracy_table(r);
  md += "\n## The claim: reprojected DFVN against curl noise\n\n";
  md += claim_reading(r);
  md += "\n## Escapes from the cube and into an obstacle\n\n";
  md += fmt::format(
      "Fraction of {} traces (t = {:g}, uniform starts in the cube outside the obstacle, {} steps: with 512 they are "
      "rare and cost 8 times as much) whose raw end is outside the cube / inside the obstacle. Bounded fields: the cube with Bridson's ramp (`--bound ramp`, width {:g}) and "
      "`--obstacle sphere:0.5,...,0.5,{:g}`.\n\n",
      c.escape_starts, c.trace_time, ConstructionsConfig::kEscapeSteps, ConstructionsConfig::kBoundaryWidth, ConstructionsConfig::kObstacleRadius);
  md += escape_table(r);
  md += "\n## Reading\n\n";
  md += divergence_reading(r);
  md += speed_reading(r);
  md += escape_reading(r);
  md += fmt::format(
      "\n## Figure 1 (Bridson et al. 2007)\n\n`curl_obstacle.png`: {} streamlines of 2D curl noise ({}) in the unit "
      "square around the disc obstacle of radius {:g}, from a {}x{} grid of seeds, traced backward and forward for "
      "t = {:g} each with {} RK4 steps per half until they meet a boundary; the points are in `curl_obstacle.csv`.\n",
      r.streamlines.size(), to_string(kDefaultNoiseBasis), ConstructionsConfig::kObstacleRadius,
      ConstructionsConfig::kFigureSeedsPerAxis, ConstructionsConfig::kFigureSeedsPerAxis, ConstructionsConfig::kFigureLength,
      ConstructionsConfig::kFigureSteps);
  return md;
}

// Empty where escapes were not measured (512 steps).
static std::string escape_cell(double fraction) { return std::isnan(fraction) ? std::string() : format_real(fraction); }

std::string constructions_csv(const ConstructionsResult& r) {
  const ConstructionsConfig& c = r.config;
  std::string csv =
      "dim,construction,field,noise,frequency,seed,divergence_points,divergence_median,divergence_p95,divergence_max,"
      "still_points,speed_points,ns_per_evaluation,speed_rms,speed_q01,speed_q10,speed_q50,speed_q90,speed_q99,"
      "fraction_below_1pct,integrator,steps,reprojection,trace_starts,trace_time,endpoint_rmse,evaluations_per_trace,"
      "escape_starts,escape_cube_fraction,escape_obstacle_fraction\n";
  for (const auto& f : r.fields)
    for (const auto& row : f.traces)
      csv += fmt::format("{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n",
                         f.dimension, to_string(f.construction), to_string(f.kind), to_string(f.noise),
                         format_real(c.frequency), c.seed, c.divergence_points, format_real(f.divergence_median),
                         format_real(f.divergence_p95), format_real(f.divergence_max), f.still_points, c.speed_points,
                         format_real(f.ns_per_evaluation, 6), format_real(f.speed_rms), format_real(f.speed_q01),
                         format_real(f.speed_q10), format_real(f.speed_q50), format_real(f.speed_q90),
                         format_real(f.speed_q99), format_real(f.fraction_below_1pct), to_string(row.variant.integrator),
                         row.variant.steps, reprojection_name(row.variant.reprojection), c.trace_starts,
                         format_real(c.trace_time), format_real(row.endpoint_rmse), format_real(row.evaluations_per_trace),
                         c.escape_starts, escape_cell(row.escape_cube), escape_cell(row.escape_obstacle));
  return csv;
}

std::vector<std::string> constructions_output_files() {
  return {"constructions.csv", "constructions.md", "curl_obstacle.csv", "curl_obstacle.png"};
}

std::string write_constructions(const ConstructionsResult& r, const std::function<void(const std::string&)>& log) {
  const auto path = [&](const std::string& name) { return (std::filesystem::path(r.config.out_dir) / name).string(); };
  std::string lines = "line,x0,x1\n";
  for (std::size_t l = 0; l < r.streamlines.size(); ++l)
    for (const auto& p : r.streamlines[l]) lines += fmt::format("{},{},{}\n", l, format_real(p[0]), format_real(p[1]));
  const std::string md = constructions_markdown(r);
  for (const auto& [name, text] : {std::pair{"constructions.csv", constructions_csv(r)}, {"constructions.md", md},
                                   {"curl_obstacle.csv", lines}})
    write_file_atomically(path(name), text);
  draw_figure(PlotProgram::curl_obstacle, path("curl_obstacle.png"),
              {path("curl_obstacle.csv"), format_real(ConstructionsConfig::kObstacleRadius),
               format_real(ConstructionsConfig::kBoundaryWidth)},
              log);
  return md;
}

}  // namespace dfvn
