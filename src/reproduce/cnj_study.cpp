#include "dfvn/reproduce/cnj_study.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <numbers>
#include <stdexcept>
#include <tuple>

#include <fmt/format.h>

#include "dfvn/core/quantile.hpp"
#include "dfvn/core/repeats.hpp"
#include "dfvn/core/seeds.hpp"
#include "dfvn/core/stopwatch.hpp"
#include "dfvn/io/atomic_file.hpp"
#include "dfvn/io/csv.hpp"
#include "dfvn/noise/noise_domain.hpp"
#include "dfvn/plot/gnuplot.hpp"
#include "dfvn/reproduce/reproduce.hpp"
#include "dfvn/sampling/curl_noise_jitter.hpp"
#include "dfvn/sampling/jitter.hpp"
#include "dfvn/sampling/lattice.hpp"
#include "dfvn/stats/lattice_displacement.hpp"
#include "dfvn/stats/nearest_neighbour.hpp"

namespace dfvn {

std::string_view to_string(StudyLattice lattice) { return lattice == StudyLattice::paper ? "paper" : "interior"; }

StudyLattice parse_study_lattice(std::string_view name) {
  if (name == "interior") return StudyLattice::interior;
  if (name == "paper") return StudyLattice::paper;
  throw std::invalid_argument(fmt::format("--lattice must be interior or paper, not '{}'", name));
}

void CnjStudyConfig::validate() const {
  if (dimensions.empty()) throw std::invalid_argument("--dims must name at least one dimension");
  for (int d : dimensions) study_grid(lattice, d);
  if (seeds < 1 || seeds > 1000) throw std::invalid_argument(fmt::format("--realizations must be in 1..1000, got {}", seeds));
  check_seed_range(seed, static_cast<std::uint64_t>(seeds), "--seed", "--realizations");
  if (bases.empty() || frequencies.empty() || step_scales.empty() || steps.empty())
    throw std::invalid_argument("the study needs at least one basis, frequency, step scale and step count");
  // Each value as CNJ would check it, but named by the option that gave it (CNJ's own message names
  // neither the list nor the dimension).
  for (double f : frequencies) {
    if (!std::isfinite(f) || !(f > 0.0))
      throw std::invalid_argument(fmt::format("--cycles-per-spacing must be finite and positive, got {:g}", f));
    for (int d : dimensions) {
      const LatticeSpec spec{d, study_grid(lattice, d), lattice == StudyLattice::paper ? Protocol::paper : Protocol::fair};
      const double field_frequency = f / spec.spacing();
      if (!(field_frequency >= kMinNoiseFrequency && field_frequency <= kMaxNoiseFrequency))
        throw std::invalid_argument(fmt::format(
            "--cycles-per-spacing {:g} is a field frequency of {:g} cycles per unit length in {}D (K = {}), outside the "
            "noise's [2^-50, 2^50]",
            f, field_frequency, d, spec.grid));
    }
  }
  for (double c : step_scales)
    if (!std::isfinite(c) || !(c > 0.0) || c > CnjOptions::kMaxStepScale)
      throw std::invalid_argument(fmt::format("--step-scales must be in (0, 2^20], got {:g}", c));
  for (int m : steps)
    if (m < 1 || m > CnjOptions::kMaxSteps)
      throw std::invalid_argument(fmt::format("--steps must be in 1..{}, got {}", CnjOptions::kMaxSteps, m));
  // A value named twice would put two copies of the same runs in one cell and halve its variance.
  if (const auto d = first_repeat(dimensions)) throw std::invalid_argument(fmt::format("--dims names {} twice", *d));
  if (const auto b = first_repeat(bases))
    throw std::invalid_argument(fmt::format("--noises names {} twice", to_string(*b)));
  if (const auto f = first_repeat(frequencies))
    throw std::invalid_argument(fmt::format("--cycles-per-spacing names {:g} twice", *f));
  if (const auto c = first_repeat(step_scales))
    throw std::invalid_argument(fmt::format("--step-scales names {:g} twice", *c));
  if (const auto m = first_repeat(steps)) throw std::invalid_argument(fmt::format("--steps names {} twice", *m));
}

int cnj_study_grid(int dimension) {
  switch (dimension) {
    case 2: return 24;
    case 3: return 12;
    case 4: return 8;
    case 5: return 6;
    case 6: return 5;
    case 7: return 5;
    case 8: return 4;
    default: throw std::invalid_argument(fmt::format("the CNJ study covers dimensions 2..8, not {}", dimension));
  }
}

int study_grid(StudyLattice lattice, int dimension) {
  if (lattice == StudyLattice::interior) return cnj_study_grid(dimension);
  if (dimension < 3 || dimension > 7)
    throw std::invalid_argument(fmt::format("the paper lattice covers dimensions 3..7 (Table 1), not {}", dimension));
  return table1_grid(dimension);
}

namespace {

// Interior sites: every lattice coordinate index in [1, K-2].
std::vector<unsigned char> interior_mask(const LatticeSpec& lattice) {
  const std::uint64_t count = lattice.point_count();
  std::vector<unsigned char> mask(count);
  const auto k = static_cast<std::uint64_t>(lattice.grid);
  for (std::uint64_t i = 0; i < count; ++i) {
    bool inside = true;
    std::uint64_t rest = i;
    for (int a = 0; a < lattice.dimension; ++a, rest /= k) {
      const std::uint64_t digit = rest % k;
      inside = inside && digit >= 1 && digit + 2 <= k;
    }
    mask[i] = inside;
  }
  return mask;
}

// NN distances of every point, summarised over the counted ones, in spacings.
Packing packing_of(const PointSet& points, const std::vector<unsigned char>& counted, double spacing, int threads) {
  const std::vector<double> distances = nearest_neighbour_distances(points, KnnBackend::nanoflann, threads);
  std::vector<double> inner;
  for (std::size_t i = 0; i < distances.size(); ++i)
    if (counted[i]) inner.push_back(distances[i] / spacing);
  if (inner.size() < 2) throw std::logic_error("the study lattice has fewer than two counted points");
  std::sort(inner.begin(), inner.end());
  return {inner.front(), quantile_of_sorted(inner, 0.01)};
}

// Largest h in (0, 1/2] with (sin(2 pi h) / (2 pi h))^2 = order (the function falls from 1 to 0 there).
double jitter_half_width_for_order(double order) {
  auto g = [](double h) {
    const double x = 2.0 * std::numbers::pi * h;
    const double s = std::sin(x) / x;
    return s * s;
  };
  if (order <= 0.0) return 0.5;
  if (order >= 1.0) return 1e-9;
  double lo = 1e-9, hi = 0.5;
  for (int i = 0; i < 100; ++i) {
    const double mid = 0.5 * (lo + hi);
    (g(mid) > order ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// The points of `points` inside [0,1]^N.
PointSet inside_unit_cube(const PointSet& points) {
  PointSet kept{points.dimension, {}, points.domain};
  const auto n = static_cast<std::size_t>(points.dimension);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double* x = &points.coordinates[i * n];
    if (std::all_of(x, x + n, [](double v) { return v >= 0.0 && v <= 1.0; }))
      kept.coordinates.insert(kept.coordinates.end(), x, x + n);
  }
  return kept;
}

// How the study reads a point set's packing: over the interior sites (interior lattice) or over every
// point that stayed in [0,1]^N, after dropping the others (paper lattice).
struct PackingRule {
  StudyLattice lattice;
  std::vector<unsigned char> interior;  // interior lattice only
  double spacing;
  int threads;

  Packing operator()(const PointSet& points) const {
    if (lattice == StudyLattice::interior) return packing_of(points, interior, spacing, threads);
    const PointSet kept = inside_unit_cube(points);
    return packing_of(kept, std::vector<unsigned char>(kept.size(), 1), spacing, threads);
  }
};

Packing jitter_packing(const LatticeSpec& lattice, double half_width_spacings, std::uint64_t seed, const PackingRule& rule) {
  return rule(jittered_lattice(lattice, half_width_spacings * lattice.spacing(), seed, rule.threads));
}

}  // namespace

namespace {

// Expected costs in nearest-neighbour passes over the lattice's points: a cell traces CNJ (about 2.4
// passes per integration step, measured in 5D) and measures four packings (CNJ and three jitters);
// the jitter curve measures 12 jittered sets.
constexpr double kTraceStepCost = 2.4, kCellPackings = 4.0, kJitterCurveCost = 12.0 * 1.2;

std::string cell_stage(int n, NoiseBasis basis, double frequency, double step_scale, int steps, std::uint64_t seed) {
  return fmt::format("{}D {} F={:g} C={:g} M={} seed {}", n, to_string(basis), frequency, step_scale, steps, seed);
}

}  // namespace

std::vector<double> cnj_study_stage_weights(const CnjStudyConfig& config) {
  std::vector<double> weights;
  for (int n : config.dimensions) {
    const double points =
        static_cast<double>(LatticeSpec{n, study_grid(config.lattice, n), Protocol::fair}.point_count());
    for (std::size_t b = 0; b < config.bases.size(); ++b)
      for (std::size_t f = 0; f < config.frequencies.size(); ++f)
        for (std::size_t c = 0; c < config.step_scales.size(); ++c)
          for (int steps : config.steps)
            for (int s = 0; s < config.seeds; ++s) weights.push_back(points * (kCellPackings + kTraceStepCost * steps));
    weights.push_back(points * kJitterCurveCost);
  }
  return weights;
}

CnjStudyResult run_cnj_study(const CnjStudyConfig& config, const StageProgress& progress) {
  config.validate();
  Stopwatch stopwatch;
  CnjStudyResult result;
  result.config = config;
  for (int n : config.dimensions) {
    const bool paper = config.lattice == StudyLattice::paper;
    const LatticeSpec lattice{n, study_grid(config.lattice, n), paper ? Protocol::paper : Protocol::fair};
    const double a = lattice.spacing();
    const PackingRule packing{config.lattice, paper ? std::vector<unsigned char>{} : interior_mask(lattice), a,
                              config.threads};
    for (NoiseBasis basis : config.bases)
      for (double frequency : config.frequencies)
        for (double step_scale : config.step_scales)
          for (int steps : config.steps)
            for (int s = 0; s < config.seeds; ++s) {
              CnjStudyRow row;
              row.dimension = n;
              row.grid = lattice.grid;
              row.basis = basis;
              row.frequency = frequency;
              row.step_scale = step_scale;
              row.steps = steps;
              row.seed = config.seed + static_cast<std::uint64_t>(s);
              if (progress) progress(cell_stage(n, basis, frequency, step_scale, steps, row.seed), 0.0);
              CnjOptions options;
              options.noise = basis;
              options.frequency = frequency;
              options.step_scale = step_scale;
              options.trace.steps = steps;
              options.domain = DomainKind::cube;
              options.domain_mode = DomainMode::drop;  // the free field: the study measures interior packing
              const CnjResult cnj = curl_noise_jitter(lattice, options, row.seed, config.threads);
              // Every traced point, inside [0,1]^N or not: x = site + displacement.
              PointSet moved{n, Coordinates(cnj.displacements.begin(), cnj.displacements.end()), Box{0.0, 1.0}};
              std::vector<double> site(static_cast<std::size_t>(n));
              for (std::size_t i = 0; i < moved.size(); ++i) {
                lattice.point(i, site.data());
                for (int j = 0; j < n; ++j) moved.coordinates[i * n + j] += site[j];
              }
              const LatticeDisplacementSummary d =
                  summarize_lattice_displacements(n, lattice.grid, a, cnj.displacements);
              row.rms_displacement = d.rms / a;
              row.median_over_rms = d.rms > 0.0 ? d.median / d.rms : 0.0;
              row.fraction_unmoved = d.fraction_unmoved;
              row.neighbour_disorder = d.neighbour_disorder;
              row.lattice_order = d.lattice_order;
              row.skipped_update_fraction =
                  static_cast<double>(cnj.trace_stats.skipped_updates) / static_cast<double>(moved.size());
              row.cnj = packing(moved);
              if (paper)
                row.dropped_fraction = 1.0 - static_cast<double>(inside_unit_cube(moved).size()) /
                                                 static_cast<double>(moved.size());
              row.h_rms = row.rms_displacement * std::sqrt(3.0 / n);
              row.h_disorder = row.neighbour_disorder / std::sqrt(2.0 * n / 3.0);
              row.h_order = jitter_half_width_for_order(row.lattice_order);
              row.jitter_rms = jitter_packing(lattice, row.h_rms, row.seed, packing);
              row.jitter_disorder = jitter_packing(lattice, row.h_disorder, row.seed, packing);
              row.jitter_order = jitter_packing(lattice, row.h_order, row.seed, packing);
              result.rows.push_back(row);
            }
    const std::string curve_stage = fmt::format("{}D jitter curve", n);
    constexpr double kHalfWidths[] = {0.05, 0.1, 0.15, 0.2, 0.25, 0.3, 0.35, 0.4, 0.45, 0.5, 0.6, 0.7};
    for (std::size_t k = 0; k < std::size(kHalfWidths); ++k) {
      const double h = kHalfWidths[k];
      if (progress) progress(curve_stage, static_cast<double>(k) / static_cast<double>(std::size(kHalfWidths)));
      JitterCurvePoint p;
      p.dimension = n;
      p.half_width = h;
      const PointSet points = jittered_lattice(lattice, h * a, config.seed, config.threads);
      const auto d = summarize_lattice_displacements(n, lattice.grid, a, lattice_displacements(lattice, points));
      p.rms_displacement = d.rms / a;
      p.neighbour_disorder = d.neighbour_disorder;
      p.lattice_order = d.lattice_order;
      p.packing = packing(points);
      result.jitter_curve.push_back(p);
    }
    if (progress) progress(curve_stage, 1.0);
  }
  result.seconds = stopwatch.seconds();
  return result;
}

namespace {

// Per-seed differences CNJ - jitter of one packing comparison: their mean and its standard error.
struct PairedDifference {
  double sum = 0.0, sum2 = 0.0;
  int runs = 0;
  void add(double d) { sum += d, sum2 += d * d, ++runs; }
  double mean() const { return runs ? sum / runs : 0.0; }
  double standard_error() const {
    if (runs < 2) return 0.0;
    const double variance = std::max(0.0, (sum2 - sum * sum / runs) / (runs - 1));
    return std::sqrt(variance / runs);
  }
  // Two seeds or more and the mean within two standard errors of 0: the comparison cannot tell them apart.
  bool tie() const { return runs >= 2 && std::abs(mean()) <= 2.0 * standard_error(); }
};

// Means over seeds of one (dimension, basis, frequency, step scale, steps) cell.
struct CellMean {
  int dimension = 0;
  NoiseBasis basis{};
  double frequency = 0.0, step_scale = 0.0;
  int steps = 1;
  int runs = 0;
  double rms = 0.0, median_over_rms = 0.0, unmoved = 0.0, disorder = 0.0, order = 0.0, skipped = 0.0, dropped = 0.0;
  double q01 = 0.0, min = 0.0;
  double q01_vs_rms = 0.0, min_vs_rms = 0.0, q01_vs_disorder = 0.0, q01_vs_order = 0.0;  // ratios CNJ / jitter
  PairedDifference q01_rms_difference, min_rms_difference, q01_disorder_difference, q01_order_difference;
};

std::vector<CellMean> cell_means(const CnjStudyResult& result) {
  // Seed sums of the jitter packings, beside each cell; the ratios are of seed means.
  struct JitterSums {
    double q01_rms = 0.0, min_rms = 0.0, q01_disorder = 0.0, q01_order = 0.0;
  };
  std::map<std::tuple<int, int, double, double, int>, std::pair<CellMean, JitterSums>> cells;
  for (const CnjStudyRow& r : result.rows) {
    auto& [c, jitter] = cells[{r.dimension, static_cast<int>(r.basis), r.frequency, r.step_scale, r.steps}];
    c.dimension = r.dimension;
    c.basis = r.basis;
    c.frequency = r.frequency;
    c.step_scale = r.step_scale;
    c.steps = r.steps;
    ++c.runs;
    c.rms += r.rms_displacement;
    c.median_over_rms += r.median_over_rms;
    c.unmoved += r.fraction_unmoved;
    c.disorder += r.neighbour_disorder;
    c.order += r.lattice_order;
    c.skipped += r.skipped_update_fraction;
    c.dropped += r.dropped_fraction;
    c.q01 += r.cnj.nn_q01;
    c.min += r.cnj.nn_min;
    jitter.q01_rms += r.jitter_rms.nn_q01;
    jitter.min_rms += r.jitter_rms.nn_min;
    jitter.q01_disorder += r.jitter_disorder.nn_q01;
    jitter.q01_order += r.jitter_order.nn_q01;
    c.q01_rms_difference.add(r.cnj.nn_q01 - r.jitter_rms.nn_q01);
    c.min_rms_difference.add(r.cnj.nn_min - r.jitter_rms.nn_min);
    c.q01_disorder_difference.add(r.cnj.nn_q01 - r.jitter_disorder.nn_q01);
    c.q01_order_difference.add(r.cnj.nn_q01 - r.jitter_order.nn_q01);
  }
  std::vector<CellMean> out;
  for (auto& [key, cell] : cells) {
    auto& [c, jitter] = cell;
    const double n = c.runs;
    for (double* v : {&c.rms, &c.median_over_rms, &c.unmoved, &c.disorder, &c.order, &c.skipped, &c.dropped, &c.q01, &c.min})
      *v /= n;
    c.q01_vs_rms = c.q01 / (jitter.q01_rms / n);
    c.min_vs_rms = c.min / (jitter.min_rms / n);
    c.q01_vs_disorder = c.q01 / (jitter.q01_disorder / n);
    c.q01_vs_order = c.q01 / (jitter.q01_order / n);
    out.push_back(c);
  }
  return out;
}

const CellMean* find_cell(const std::vector<CellMean>& cells, int dimension, NoiseBasis basis, double frequency,
                          double step_scale, int steps) {
  for (const CellMean& c : cells)
    if (c.dimension == dimension && c.basis == basis && c.frequency == frequency && c.step_scale == step_scale &&
        c.steps == steps)
      return &c;
  return nullptr;
}

// "frequency / step scale", and " / M steps" when the study compares step counts.
std::string cell_label(const CellMean& c, const CnjStudyConfig& config) {
  if (config.steps.size() == 1) return fmt::format("{:g} / {:g}", c.frequency, c.step_scale);
  return fmt::format("{:g} / {:g} / {} step{}", c.frequency, c.step_scale, c.steps, c.steps == 1 ? "" : "s");
}

bool moves_points(const CellMean& c) { return c.unmoved <= 0.01 && c.median_over_rms >= 0.5; }
bool beats_jitter_at_equal_rms(const CellMean& c) { return c.q01_vs_rms > 1.0 && c.min_vs_rms > 1.0; }

// A ratio of seed means, and who wins; a tie when the per-seed differences do not tell CNJ and jitter apart.
std::string verdict(double ratio, const PairedDifference& difference) {
  if (difference.tie())
    return fmt::format("x{:.2f} (tie: CNJ - jitter {:+.3f} ± {:.3f} s.e.)", ratio, difference.mean(),
                       difference.standard_error());
  return ratio > 1.0 ? fmt::format("**x{:.2f}** (CNJ wins)", ratio) : fmt::format("x{:.2f} (jitter wins)", ratio);
}

const char* beats_word(double ratio, const PairedDifference& difference) {
  return difference.tie() ? "ties with" : ratio > 1.0 ? "beats" : "does not beat";
}

}  // namespace

std::optional<CnjDefaultsChoice> choose_cnj_defaults(const CnjStudyResult& result) {
  const auto cells = cell_means(result);
  std::optional<CnjDefaultsChoice> best;
  for (double f : result.config.frequencies)
    for (double c : result.config.step_scales)
      for (int m : result.config.steps) {
        bool qualifies = true;
        double log_sum = 0.0;
        for (int n : result.config.dimensions) {
          const CellMean* cell = find_cell(cells, n, kDefaultNoiseBasis, f, c, m);
          if (!cell || !moves_points(*cell) || !beats_jitter_at_equal_rms(*cell)) {
            qualifies = false;
            break;
          }
          log_sum += std::log(cell->q01_vs_disorder);
        }
        if (!qualifies) continue;
        const double score = std::exp(log_sum / static_cast<double>(result.config.dimensions.size()));
        if (!best || score > best->score) best = CnjDefaultsChoice{f, c, m, score};
      }
  return best;
}

std::string cnj_study_markdown(const CnjStudyResult& result) {
  const CnjStudyConfig& cfg = result.config;
  const auto cells = cell_means(result);
  CnjOptions defaults;
  defaults.domain = DomainKind::cube;
  defaults.domain_mode = DomainMode::drop;  // as every run of the study
  const int default_steps = cnj_steps(defaults);
  const bool paper = cfg.lattice == StudyLattice::paper;
  std::string md = paper ? "# CNJ against jitter on the paper's lattice\n\n" : "# CNJ against jitter: the study\n\n";
  std::string steps_text;
  for (std::size_t i = 0; i < cfg.steps.size(); ++i) steps_text += fmt::format("{}{}", i ? ", " : "", cfg.steps[i]);
  md += fmt::format(
      "Curl noise jittering ({}) of {}, "
      "against uniform jitter of the same lattice, {} seed(s) per cell (seeds {}..{}). Packing = nearest-neighbour "
      "distance {}, nn_q01 = its 1% quantile, all in lattice spacings. Each CNJ run is compared with three jitter runs of the "
      "same lattice and seed, whose half-width h matches CNJ's RMS displacement (h = rms sqrt(3/N)), neighbour "
      "disorder (RMS relative displacement of lattice neighbours; h = disorder / sqrt(2N/3)) or lattice order "
      "(surviving Bragg amplitude; (sin 2 pi h / 2 pi h)^2 = order). Ratios are CNJ / jitter of seed means; "
      "above 1, CNJ packs better, unless the per-seed differences CNJ - jitter have a mean within two standard "
      "errors of 0 (a tie, with that mean and standard error in spacings). {:.0f} s on this machine ({} thread(s) requested, 0 = all cores).\n\n",
      cfg.steps == std::vector<int>{1}
          ? std::string("one RK4 step + Gauss-Newton reprojection")
          : fmt::format("M = {} RK4 steps of t / M, each followed by a Gauss-Newton reprojection", steps_text),
      paper ? "the paper's Table 1 lattice (linspace(0.05, 0.95, K) per axis)" : "a cell-centred K^N lattice in [0,1]^N",
      cfg.seeds, cfg.seed, cfg.seed + static_cast<std::uint64_t>(cfg.seeds) - 1,
      paper ? "over every point that stays in [0,1]^N (points that leave are dropped, for CNJ and jitter alike, as the "
              "paper does)"
            : "over the interior sites (at least one spacing from the lattice's outer layer; no point is dropped)",
      result.seconds, cfg.threads);
  md += "Lattices: ";
  for (std::size_t i = 0; i < cfg.dimensions.size(); ++i) {
    const int n = cfg.dimensions[i], k = study_grid(cfg.lattice, n);
    md += paper ? fmt::format("{}{}D K={} ({:.0f} points)", i ? ", " : "", n, k, std::pow(k, n))
                : fmt::format("{}{}D K={} ({:.0f} points, {:.0f} interior)", i ? ", " : "", n, k, std::pow(k, n),
                              std::pow(k - 2, n));
  }
  md += ".\n\n";

  // The answers, per dimension: the library defaults, then the best cell of each comparison.
  md += "## Answers per dimension\n\n";
  md += fmt::format(
      "For the library defaults ({} noise, frequency {:g} cycles per spacing, step scale {:g}, {} integration "
      "step{}):\n\n",
      to_string(defaults.noise), defaults.frequency, defaults.step_scale, default_steps,
      default_steps == 1 ? "" : "s");
  md += "| n | RMS move | median/RMS | unmoved | dropped | q01 vs jitter at equal RMS | nn_min vs jitter at equal RMS | "
        "q01 at equal disorder | q01 at equal order |\n| --- | --- | --- | --- | --- | --- | --- | --- | --- |\n";
  for (int n : cfg.dimensions) {
    const CellMean* c = find_cell(cells, n, defaults.noise, defaults.frequency, defaults.step_scale, default_steps);
    if (!c) {
      md += fmt::format("| {} | (defaults not in the studied grid) | | | | | | | |\n", n);
      continue;
    }
    md += fmt::format("| {} | {:.3f} | {:.2f} | {:.2f}% | {:.1f}% | {} | {} | {} | {} |\n", n, c->rms, c->median_over_rms,
                      100.0 * c->unmoved, 100.0 * c->dropped, verdict(c->q01_vs_rms, c->q01_rms_difference), verdict(c->min_vs_rms, c->min_rms_difference),
                      verdict(c->q01_vs_disorder, c->q01_disorder_difference), verdict(c->q01_vs_order, c->q01_order_difference));
  }
  md += fmt::format("\nThe best any studied cell of each basis does (largest ratio; its frequency / step scale{} in "
                    "brackets):\n\n",
                    cfg.steps.size() == 1 ? "" : " / steps");
  md += "| n | basis | best q01 at equal RMS | best q01 at equal disorder | best q01 at equal order |\n"
        "| --- | --- | --- | --- | --- |\n";
  for (int n : cfg.dimensions)
    for (NoiseBasis b : cfg.bases) {
      const CellMean *best_rms = nullptr, *best_disorder = nullptr, *best_order = nullptr;
      for (const CellMean& c : cells) {
        if (c.dimension != n || c.basis != b) continue;
        if (!best_rms || c.q01_vs_rms > best_rms->q01_vs_rms) best_rms = &c;
        if (!best_disorder || c.q01_vs_disorder > best_disorder->q01_vs_disorder) best_disorder = &c;
        if (!best_order || c.q01_vs_order > best_order->q01_vs_order) best_order = &c;
      }
      if (!best_rms) continue;
      md += fmt::format("| {} | {} | x{:.2f} ({}) | x{:.2f} ({}) | x{:.2f} ({}) |\n", n, to_string(b),
                        best_rms->q01_vs_rms, cell_label(*best_rms, cfg), best_disorder->q01_vs_disorder,
                        cell_label(*best_disorder, cfg), best_order->q01_vs_order, cell_label(*best_order, cfg));
    }

  // The reading, from the numbers.
  md += "\n## Reading\n\n";
  for (int n : cfg.dimensions) {
    const CellMean* c = find_cell(cells, n, defaults.noise, defaults.frequency, defaults.step_scale, default_steps);
    if (!c) continue;
    const char* rms_word = beats_word(c->q01_vs_rms, c->q01_rms_difference);
    const char* disorder_word = beats_word(c->q01_vs_disorder, c->q01_disorder_difference);
    const char* order_word = beats_word(c->q01_vs_order, c->q01_order_difference);
    md += fmt::format(
        "- **{}D**: with the defaults, CNJ {} jitter at equal RMS displacement (q01 x{:.2f}, min x{:.2f}{}), {} it at "
        "equal neighbour disorder (x{:.2f}) and {} it at equal lattice order (x{:.2f}); it moves every point "
        "({:.2f}% under 1% of a spacing, median/RMS {:.2f}) but keeps {:.0f}% of the lattice's Bragg amplitude "
        "(jitter at that RMS: {:.0f}%).\n",
        n, rms_word, c->q01_vs_rms, c->min_vs_rms, c->min_rms_difference.tie() ? ", a tie" : "", disorder_word, c->q01_vs_disorder, order_word, c->q01_vs_order,
        100.0 * c->unmoved, c->median_over_rms, 100.0 * c->order,
        100.0 * std::pow(std::sin(2 * std::numbers::pi * c->rms * std::sqrt(3.0 / n)) /
                             (2 * std::numbers::pi * c->rms * std::sqrt(3.0 / n)), 2));
  }
  for (int n : cfg.dimensions) {
    const CellMean* s =
        find_cell(cells, n, NoiseBasis::simplex, defaults.frequency, defaults.step_scale, default_steps);
    if (!s) continue;
    md += fmt::format("- **simplex {}D** (same frequency, step scale and steps): {:.1f}% of points unmoved, median/RMS "
                      "displacement {:.2g}, q01 vs jitter at equal RMS x{:.2f}.\n",
                      n, 100.0 * s->unmoved, s->median_over_rms, s->q01_vs_rms);
  }
  md += "- Gains at equal RMS displacement that shrink or vanish at equal neighbour disorder and equal lattice order "
        "come from coherent motion: a low-frequency field moves neighbours together, which keeps nearest-neighbour "
        "distances large but also keeps the lattice.\n";

  const auto choice = choose_cnj_defaults(result);
  md += "\n## The defaults and the rule that chose them\n\n";
  md += "Rule (src/reproduce/cnj_study.hpp, choose_cnj_defaults): on the default basis and means over seeds, keep "
        "the (frequency, step scale, steps) cells that in every studied dimension move points (at most 1% unmoved, "
        "median/RMS displacement at least 0.5) and beat jitter at equal RMS displacement in both nn_q01 and nn_min; "
        "take the one with the largest geometric mean over dimensions of the q01 ratio at equal neighbour disorder, "
        "the comparison that does not reward moving neighbours together.\n\n";
  if (choice)
    md += fmt::format("The rule picks frequency {:g}, step scale {:g} and {} step{} (score {:.3f}); the library defaults "
                      "are {:g}, {:g} and {}: {}.\n",
                      choice->frequency, choice->step_scale, choice->steps, choice->steps == 1 ? "" : "s",
                      choice->score, defaults.frequency, defaults.step_scale, default_steps,
                      choice->frequency == defaults.frequency && choice->step_scale == defaults.step_scale &&
                              choice->steps == default_steps
                          ? "the same"
                          : "DIFFERENT (run on the full grid and seeds before changing them)");
  else
    md += "No studied cell meets the rule's conditions in every dimension here.\n";

  md += "\n## Every cell\n\n| n | basis | frequency | step scale | steps | RMS move | median/RMS | unmoved | disorder | order | "
        "skipped GN | q01 | min | q01/jit(rms) | min/jit(rms) | q01/jit(disorder) | q01/jit(order) |\n"
        "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |\n";
  for (const CellMean& c : cells)
    md += fmt::format("| {} | {} | {:g} | {:g} | {} | {:.3f} | {:.2f} | {:.2f}% | {:.3f} | {:.3f} | {:.3f} | {:.3f} | {:.3f} | "
                      "{:.2f} | {:.2f} | {:.2f} | {:.2f} |\n",
                      c.dimension, to_string(c.basis), c.frequency, c.step_scale, c.steps, c.rms, c.median_over_rms,
                      100.0 * c.unmoved, c.disorder, c.order, c.skipped, c.q01, c.min, c.q01_vs_rms, c.min_vs_rms,
                      c.q01_vs_disorder, c.q01_vs_order);
  return md;
}

std::vector<std::string> cnj_study_output_files() {
  return {"cnj_study.csv", "cnj_study_jitter.csv", "cnj_study.md", "cnj_study.png"};
}

std::string write_cnj_study(const CnjStudyResult& result, const Log& log) {
  const std::filesystem::path dir = result.config.out_dir;
  std::string rows =
      "dim,grid,noise,cycles_per_spacing,step_scale,seed,rms_displacement,median_over_rms,frac_unmoved,neighbour_disorder,"
      "lattice_order,skipped_update_fraction,cnj_nn_min,cnj_nn_q01,h_rms,jitter_rms_nn_min,jitter_rms_nn_q01,"
      "h_disorder,jitter_disorder_nn_min,jitter_disorder_nn_q01,h_order,jitter_order_nn_min,jitter_order_nn_q01,dropped_fraction,steps\n";
  for (const CnjStudyRow& r : result.rows)
  {
    // Reals as format_real writes them ("1.0", never "1"), to 9 significant digits as every statistic.
    rows += fmt::format("{},{},{},{},{},{}", r.dimension, r.grid, to_string(r.basis), format_real(r.frequency),
                        format_real(r.step_scale), r.seed);
    for (double v : {r.rms_displacement, r.median_over_rms, r.fraction_unmoved, r.neighbour_disorder, r.lattice_order,
                     r.skipped_update_fraction, r.cnj.nn_min, r.cnj.nn_q01, r.h_rms, r.jitter_rms.nn_min,
                     r.jitter_rms.nn_q01, r.h_disorder, r.jitter_disorder.nn_min, r.jitter_disorder.nn_q01, r.h_order,
                     r.jitter_order.nn_min, r.jitter_order.nn_q01, r.dropped_fraction})
      rows += ',', rows += format_real(v);
    rows += fmt::format(",{}\n", r.steps);
  }
  std::string curve = "dim,half_width,rms_displacement,neighbour_disorder,lattice_order,nn_min,nn_q01\n";
  for (const JitterCurvePoint& p : result.jitter_curve)
    curve += fmt::format("{},{},{},{},{},{},{}\n", p.dimension, format_real(p.half_width), format_real(p.rms_displacement),
                         format_real(p.neighbour_disorder), format_real(p.lattice_order), format_real(p.packing.nn_min),
                         format_real(p.packing.nn_q01));
  const std::string md = cnj_study_markdown(result);
  write_file_atomically((dir / "cnj_study.csv").string(), rows);
  write_file_atomically((dir / "cnj_study_jitter.csv").string(), curve);
  write_file_atomically((dir / "cnj_study.md").string(), md);
  std::string dims, bases;
  for (int d : result.config.dimensions) dims += fmt::format("{} ", d);
  for (const CnjStudyRow& r : result.rows)
    if (bases.find(std::string(to_string(r.basis)) + " ") == std::string::npos) bases += std::string(to_string(r.basis)) + " ";
  draw_figure(PlotProgram::cnj_study, (dir / "cnj_study.png").string(),
              {(dir / "cnj_study.csv").string(), (dir / "cnj_study_jitter.csv").string(), dims, bases,
               fmt::format("{} realizations from seed {}, {} lattice", result.config.seeds, result.config.seed,
                           result.config.lattice == StudyLattice::interior ? "interior sites of the" : "the paper's Table 1")},
              log);
  return md;
}

}  // namespace dfvn
