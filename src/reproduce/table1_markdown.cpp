// Table 1's Markdown: the paper's layout with our cells beside the paper's (mean +- sd over the
// realizations), and a reading computed from the numbers, about the dimensions that were run only.
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "dfvn/reproduce/paper_tables.hpp"
#include "dfvn/reproduce/reproduce.hpp"

namespace dfvn {

namespace {

std::string method_title(Method m) {
  switch (m) {
    case Method::cnj: return "CNJ";
    case Method::jitter: return "Jittering";
    case Method::jitter_matched: return "Jittering (matched)";
    case Method::pds: return "PDS";
    case Method::sobol: return "Sobol";
    case Method::random: return "Random";
    case Method::halton: return "Halton";
    case Method::lhs: return "LHS";
  }
  return "?";
}

std::string seconds_text(double s) { return s >= 1000 ? fmt::format("{:.0f}k", s / 1000) : fmt::format("{:g}", s); }

// "0.071 +- 0.001" over several realizations, "0.071" for one.
std::string value_text(const MeanSd& v, int realizations) {
  return realizations > 1 ? fmt::format("{:.3f} ± {:.3f}", v.mean, v.sd) : fmt::format("{:.3f}", v.mean);
}

std::string ours_cell(const Table1Cell& c, int realizations) {
  return fmt::format("ours {} ({}):{:.2g}<br>{:.0f} pts", value_text(c.nn_median, realizations), value_text(c.nn_min, realizations),
                     c.seconds.mean, c.points.mean);
}

bool has_dimension(const Table1Result& result, int dimension) {
  for (const auto& c : result.configs)
    if (c.dimension == dimension) return true;
  return false;
}

// Dimensions run from `from` on, as "5D, 6D" ("" if none).
std::vector<int> dimensions_from(const Table1Result& result, int from) {
  std::vector<int> dims;
  for (const auto& c : result.configs)
    if (c.dimension >= from) dims.push_back(c.dimension);
  return dims;
}

}  // namespace

std::string table1_markdown(const Table1Result& result) {
  const Method methods[] = {Method::cnj, Method::jitter, Method::pds, Method::sobol};
  const int R = result.realizations;
  std::string md = "# Table 1, reproduced\n\n";
  md += "Each cell: median nearest-neighbour distance (minimum) : seconds. **paper** is Table 1 of the paper "
        "(Python on an Apple M1 Max, single runs); **ours** is dfvn-sample";
  md += R > 1 ? fmt::format(", mean ± standard deviation over {} realizations (seeds {}..{}; seconds and points are "
                            "means)",
                            R, result.configs.empty() ? 0 : result.configs.front().seed,
                            result.configs.empty() ? 0 : result.configs.front().seed + static_cast<std::uint64_t>(R - 1))
              : fmt::format(", one realization (seed {})", result.configs.empty() ? 0 : result.configs.front().seed);
  md += fmt::format(", with the number of points, on {}. Paper protocol (data/PROTOCOL.md): lattice linspace(0.05, "
                    "0.95, K), jitter +-0.05, PDS radius 0.1 and Sobol on [0, 0.1K]^n.\n\n",
                    result.machine);
  md += "| n | K | CNJ | CNJ (simplex) | Jittering | PDS | Sobol |\n| --- | --- | --- | --- | --- | --- | --- |\n";
  for (std::size_t d = 0; d < result.configs.size(); ++d) {
    const int n = result.configs[d].dimension;
    md += fmt::format("| {} | {} |", n, result.configs[d].grid);
    for (Method m : methods) {
      const auto p = paper_table1_cell(n, m);
      std::string cell;
      if (p) cell += fmt::format("paper {:.3f} ({:.3f}):{}<br>", p->nn_median, p->nn_min, seconds_text(p->seconds));
      md += " " + cell + ours_cell(result.cell(d, m), R) + " |";
      if (m == Method::cnj) md += " " + ours_cell(result.cell(d, m, true), R) + " |";
    }
    md += "\n";
  }

  // The reading, from the numbers above.
  md += "\n## Reading\n\n";
  const std::string means = R > 1 ? fmt::format(" (means over {} realizations)", R) : "";
  for (Method m : {Method::jitter, Method::sobol, Method::pds}) {
    std::string list;
    double worst = 0.0;
    for (std::size_t d = 0; d < result.configs.size(); ++d) {
      const int n = result.configs[d].dimension;
      const auto p = paper_table1_cell(n, m);
      if (!p) continue;
      const double dev = result.cell(d, m).nn_median.mean / p->nn_median - 1.0;
      worst = std::max(worst, std::abs(dev));
      list += fmt::format("{}{}D {:+.1f}%", list.empty() ? "" : ", ", n, 100.0 * dev);
    }
    md += fmt::format("- **{}** medians{} against the paper: {} (largest deviation {:.1f}%{}).\n", method_title(m), means,
                      list, 100.0 * worst, worst <= 0.05 ? ", within 5%" : ", MORE than 5%");
  }
  std::string pds_min;
  bool all_at_least_r = true;
  for (std::size_t d = 0; d < result.configs.size(); ++d) {
    const Table1Cell c = result.cell(d, Method::pds);
    const auto p = paper_table1_cell(result.configs[d].dimension, Method::pds);
    all_at_least_r = all_at_least_r && c.smallest_min >= 0.1;  // the paper protocol's radius
    pds_min += fmt::format("{}{}D {}{}", pds_min.empty() ? "" : ", ", result.configs[d].dimension,
                           R > 1 ? fmt::format("{:.4f} (smallest of {})", c.smallest_min, R) : fmt::format("{:.4f}", c.smallest_min),
                           p ? fmt::format(" (paper {:.3f})", p->nn_min) : "");
  }
  md += fmt::format("- **PDS minimum distance**: {}. {}", pds_min,
                    all_at_least_r ? "Ours keeps min >= r = 0.1 in every dimension." : "Ours DOES NOT keep min >= r here.");
  const std::vector<int> high = dimensions_from(result, 5);
  if (!high.empty()) {
    std::string paper_minima;
    for (int n : high)
      if (const auto p = paper_table1_cell(n, Method::pds))
        paper_minima += fmt::format("{}{}D {:.3f}", paper_minima.empty() ? "" : ", ", n, p->nn_min);
    md += fmt::format(" SciPy 1.10's PoissonDisk, which the paper used, checks only +-2 grid cells of side r/sqrt(n), so "
                      "from 5D on it accepts pairs closer than r (the paper's {}); ours searches every cell that can "
                      "hold a conflicting point.",
                      paper_minima);
  }
  md += "\n";
  std::string cnj;
  for (std::size_t d = 0; d < result.configs.size(); ++d) {
    const auto p = paper_table1_cell(result.configs[d].dimension, Method::cnj);
    if (!p) continue;
    const Table1Cell c = result.cell(d, Method::cnj);
    cnj += fmt::format("{}{}D {:.3f} ({:.3f}) vs {:.3f} ({:.3f})", cnj.empty() ? "" : "; ", result.configs[d].dimension,
                       c.nn_median.mean, c.nn_min.mean, p->nn_median, p->nn_min);
  }
  const CnjOptions& o = result.configs.empty() ? CnjOptions{} : result.configs.front().cnj;
  md += fmt::format(
      "- **CNJ** (ours vs paper, median (min){}): {}. The paper's step constant and noise frequency are not "
      "published, so our row uses our defaults ({} noise, step scale {:g}, frequency {:g} cycles per lattice "
      "spacing, {} RK4 step{}, chosen by the rule of `reproduce cnj-study`; data/cnj_defaults.md).\n",
      means, cnj, to_string(o.noise), o.step_scale, o.frequency, cnj_steps(o), cnj_steps(o) == 1 ? "" : "s");
  // Which construction moved points, and how far (displacements over every traced point, in spacings;
  // the first realization).
  std::string moved;
  for (std::size_t d = 0; d < result.configs.size(); ++d) {
    const MethodResult* ours = nullptr;
    for (const auto& r : result.first(d))
      if (r.plan.method == Method::cnj) ours = &r;
    const MethodResult& simplex = result.simplex_cnj[d].front();
    if (!ours || !ours->displacement || !simplex.displacement) continue;
    const double a = result.configs[d].lattice().spacing();
    moved += fmt::format("{}{}D: {} {:.1f}% unmoved, median move {:.3f}, RMS {:.3f}; simplex {:.1f}% unmoved, median "
                         "{:.2g}, RMS {:.3f}",
                         moved.empty() ? "" : "; ", result.configs[d].dimension, to_string(o.noise),
                         100.0 * ours->displacement->fraction_unmoved, ours->displacement->median / a,
                         ours->displacement->rms / a, 100.0 * simplex.displacement->fraction_unmoved,
                         simplex.displacement->median / a, simplex.displacement->rms / a);
  }
  if (!moved.empty()) {
    md += "- **Which construction moves the points** (\"unmoved\": less than 1% of a spacing; moves in lattice "
          "spacings, over every traced point, first realization): " + moved + ".";
    if (!dimensions_from(result, 4).empty())
      md += " The paper's construction (simplex noise, C2 kernel, one shared traversal, one RK4 step unless --steps) "
            "leaves a field that is nearly still in most of space from 4D on, so most of its points stay on their "
            "lattice sites and a few move far; ours moves every point by a comparable amount.";
    md += "\n";
  }
  // The paper's densities: its lattice sets (one point per cell of the lattice's box) against PDS and
  // Sobol on [0, 0.1 K]^n; they differ wherever the lattice's spacing is not 0.1 (6D and 7D).
  std::string densities;
  for (const SampleConfig& c : result.configs) {
    const LatticeSpec lattice = c.lattice();
    if (std::abs(lattice.spacing() - kPaperDelta) < 1e-12) continue;
    const Box cells = lattice.cells();
    densities += fmt::format("{}{}D: CNJ and jitter on the {}^{} lattice of spacing {:.2g} in [{:g}, {:g}]^{} (one point per "
                             "cell; {:.3g} times the unit cube's volume), PDS and Sobol in [0, {:g}]^{}, {:.3g} times denser",
                             densities.empty() ? "" : "; ", c.dimension, c.grid, c.dimension, lattice.spacing(), cells.lo,
                             cells.lo + cells.side, c.dimension, cells.volume(c.dimension), kPaperDelta * c.grid, c.dimension,
                             std::pow(lattice.spacing() / kPaperDelta, c.dimension));
  }
  if (!densities.empty())
    md += "- **Densities differ, as in the paper**: " + densities +
          ". Raw distances (the minimum, the median) are not comparable across those columns; nn_median_scaled in "
          "table1.csv (the median x (points / volume)^(1/n), each set's own volume) is. `dfvn-sample` without "
          "--protocol paper (the fair protocol) compares every method at one count in one domain.\n";
  double ours_total = 0.0, paper_total = 0.0, wall_total = 0.0;
  std::string wall;
  for (std::size_t d = 0; d < result.configs.size(); ++d) {
    for (Method m : methods)
      if (const auto p = paper_table1_cell(result.configs[d].dimension, m)) {
        ours_total += result.cell(d, m).seconds.mean;
        paper_total += p->seconds;
      }
    wall_total += result.wall_seconds[d];
    wall += fmt::format("{}{}D {:.3g} s", wall.empty() ? "" : ", ", result.configs[d].dimension, result.wall_seconds[d] / R);
  }
  md += fmt::format("- **Time** on {}: {:.1f} s for the table's cells{} against {:.0f} s in the paper (a {:.0f}x ratio; "
                    "different machines and languages, the paper's are single runs). The whole run took {:.0f} s, per "
                    "realization (with the simplex column{}): {}.\n",
                    result.machine, ours_total, R > 1 ? " (one realization, mean)" : "", paper_total,
                    paper_total / std::max(ours_total, 1e-9), wall_total, ", and the RDFs in the first", wall);
  md += "- The RDFs (rdf.csv, figure4.png: the first realization) are normalised by each set's own intensity, its points "
        "over the volume of the box it fills (for CNJ and jitter the box of their lattice's cells, above; for PDS and "
        "Sobol theirs), and edge-corrected, so they tend to 1 for uniform points; CNJ drops the points that leave the "
        "unit cube, which thins a band along its faces and lifts CNJ's curve above 1 by that thinning. The paper's tend "
        "to 0.5 and sag at large r (its estimator omits the factor 2 for unordered pairs and any edge correction).\n";
  return md;
}

}  // namespace dfvn
