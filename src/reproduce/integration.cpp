#include "dfvn/reproduce/integration.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <set>
#include <tuple>
#include <stdexcept>

#include <fmt/format.h>

#include "dfvn/core/repeats.hpp"
#include "dfvn/core/seeds.hpp"
#include "dfvn/io/atomic_file.hpp"
#include "dfvn/io/csv.hpp"
#include "dfvn/plot/gnuplot.hpp"
#include "dfvn/experiment/realizations.hpp"

namespace dfvn {

namespace {

// The smallest K with K^N >= 64 points: the first size of every dimension.
int smallest_integration_grid(int dimension) {
  int k = 2;
  while (std::pow(static_cast<double>(k), dimension) < 64.0) ++k;
  return k;
}

}  // namespace

void IntegrationConfig::validate() const {
  if (dimensions.empty()) throw std::invalid_argument("--dims must name at least one dimension");
  if (realizations < 2) throw std::invalid_argument("--realizations must be at least 2 (16 or more for the reading)");
  if (max_points < 64) throw std::invalid_argument("--max-points must be at least 64");
  if (methods.empty()) throw std::invalid_argument("--methods must name at least one method");
  if (const auto repeat = first_repeat(methods))
    throw std::invalid_argument(fmt::format("--methods names '{}' twice", to_string(*repeat)));
  if (const auto repeat = first_repeat(dimensions)) throw std::invalid_argument(fmt::format("--dims names {} twice", *repeat));
  for (int d : dimensions) {
    const int smallest = smallest_integration_grid(d);
    const double points = std::pow(static_cast<double>(smallest), d);
    if (points > static_cast<double>(max_points))
      throw std::invalid_argument(fmt::format("--max-points {} is below the smallest lattice of {}D, {}^{} = {:.0f} points; "
                                              "give at least {:.0f} or leave {}D out of --dims",
                                              max_points, d, smallest, d, points, points, d));
  }
  check_seed_range(seed, static_cast<std::uint64_t>(realizations), "--seed", "--realizations");
}

std::vector<int> integration_grids(int dimension, std::uint64_t max_points) {
  auto count = [&](int k) { return std::pow(static_cast<double>(k), dimension); };
  const int lo = smallest_integration_grid(dimension);
  int hi = lo;
  while (count(hi + 1) <= static_cast<double>(max_points)) ++hi;
  std::vector<int> grids;
  constexpr int kSizes = 5;
  for (int s = 0; s < kSizes; ++s) {
    // Evenly spaced in log K between lo and hi, rounded, without repeats.
    const double t = kSizes == 1 ? 0.0 : static_cast<double>(s) / (kSizes - 1);
    const int k = static_cast<int>(std::lround(std::exp(std::log(lo) + t * (std::log(hi) - std::log(lo)))));
    if (grids.empty() || grids.back() != k) grids.push_back(k);
  }
  return grids;
}

namespace {

// None from fewer than two distinct x (one size, or sizes of equal count) or a non-finite y (an error
// of 0): a slope of 0.0 written there read as "no convergence".
std::optional<double> fitted_slope(const std::vector<double>& x, const std::vector<double>& y) {
  for (double v : y)
    if (!std::isfinite(v)) return std::nullopt;
  const auto n = static_cast<double>(x.size());
  double mx = 0.0, my = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    mx += x[i] / n;
    my += y[i] / n;
  }
  double sxy = 0.0, sxx = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    sxy += (x[i] - mx) * (y[i] - my);
    sxx += (x[i] - mx) * (x[i] - mx);
  }
  if (!(sxx > 0.0)) return std::nullopt;
  return sxy / sxx;
}

}  // namespace

std::vector<double> integration_stage_weights(const IntegrationConfig& config) {
  // Per realization: generate the K^N points, then sum the six integrands over them (about one
  // statistics pass); Sobol's count is the nearest power of two, Poisson disk's below K^N.
  std::vector<double> weights;
  for (int dimension : config.dimensions)
    for (Method method : config.methods)
      for (int grid : integration_grids(dimension, config.max_points))
        weights.push_back(config.realizations * std::pow(static_cast<double>(grid), dimension) *
                          (1.0 + sampling_generation_cost(method)));
  return weights;
}

IntegrationResult run_integration(const IntegrationConfig& config, const StageProgress& progress) {
  config.validate();
  IntegrationResult result{config, {}, {}};
  constexpr std::size_t kFamilies = std::size(kGenzFamilies);
  for (int dimension : config.dimensions) {
    const std::vector<int> grids = integration_grids(dimension, config.max_points);
    for (Method method : config.methods) {
      for (int grid : grids) {
        // squared relative errors per family and realization
        std::vector<std::vector<double>> squared(kFamilies);
        double points_sum = 0.0;
        for (int r = 0; r < config.realizations; ++r) {
          if (progress)
            progress(fmt::format("{}D {} K={}", dimension, to_string(method), grid),
                     static_cast<double>(r) / config.realizations);
          SampleConfig sample;
          sample.dimension = dimension;
          sample.grid = grid;
          sample.seed = config.seed + static_cast<std::uint64_t>(r);
          sample.threads = config.threads;
          sample.protocol = Protocol::fair;  // every method in [0,1]^N, at the density of K^N points
          sample.methods = {method};
          MethodPlan plan = plan_method(sample, method);
          if (method == Method::sobol) {  // Sobol at its own sizes: the power of two nearest K^N
            const int exponent = static_cast<int>(std::lround(std::log2(static_cast<double>(plan.requested))));
            plan.requested = std::uint64_t{1} << exponent;
          }
          // Poisson disk runs to saturation: stopped at a count, Bridson's front would cover only part of
          // the cube (in 6D-7D radius 1/K admits more than K^N points) and bias the mean.
          // It samples the unit cube at radius 1/K (the integrands live on the cube; CNJ on the torus, the
          // main job's domain, whose points are in [0,1)^N too).
          if (method == Method::pds) {
            plan.requested = std::numeric_limits<std::uint64_t>::max();
            plan.domain = Domain::unit(DomainKind::cube);
            plan.pds_radius = 1.0 / grid;
          }
          MethodResult generated;
          generated.plan = plan;
          generate_points(sample, generated);
          const PointSet& points = generated.points;
          points_sum += static_cast<double>(points.size());
          for (std::size_t f = 0; f < kFamilies; ++f) {
            // The integrand's parameters depend on the realization only: every method integrates the
            // same R functions.
            const GenzIntegrand integrand = random_genz_integrand(kGenzFamilies[f], dimension, sample.seed);
            double sum = 0.0;  // in index order: independent of the thread count
            for (std::size_t i = 0; i < points.size(); ++i) sum += integrand(points.point(i));
            const double estimate = sum / static_cast<double>(points.size());
            const double exact = integrand.exact_integral();
            const double relative = (estimate - exact) / exact;
            squared[f].push_back(relative * relative);
          }
        }
        for (std::size_t f = 0; f < kFamilies; ++f) {
          const MeanSd s = mean_sd(squared[f]);
          IntegrationCell cell{dimension, kGenzFamilies[f], method, grid, points_sum / config.realizations,
                               std::sqrt(s.mean), 0.0};
          cell.standard_error =
              cell.rms_relative_error > 0.0 ? s.sd / (2.0 * cell.rms_relative_error * std::sqrt(double(config.realizations))) : 0.0;
          result.cells.push_back(cell);
        }
      }
    }
  }
  // Slopes: per dimension, family and method, over the sizes.
  std::map<std::tuple<int, int, int>, std::pair<std::vector<double>, std::vector<double>>> series;
  for (const auto& c : result.cells) {
    auto& [x, y] = series[{c.dimension, static_cast<int>(c.family), static_cast<int>(c.method)}];
    x.push_back(std::log(c.points));
    y.push_back(std::log(c.rms_relative_error));
  }
  for (const auto& [key, xy] : series)
    result.slopes.push_back({std::get<0>(key), static_cast<GenzFamily>(std::get<1>(key)), static_cast<Method>(std::get<2>(key)),
                             fitted_slope(xy.first, xy.second)});
  return result;
}

namespace {

const IntegrationCell* largest_cell(const IntegrationResult& r, int dimension, GenzFamily family, Method method) {
  const IntegrationCell* best = nullptr;
  for (const auto& c : r.cells)
    if (c.dimension == dimension && c.family == family && c.method == method && (!best || c.grid > best->grid)) best = &c;
  return best;
}

std::optional<double> slope_of(const IntegrationResult& r, int dimension, GenzFamily family, Method method) {
  for (const auto& s : r.slopes)
    if (s.dimension == dimension && s.family == family && s.method == method) return s.slope;
  return std::nullopt;
}

std::string slope_text(const std::optional<double>& slope) { return slope ? fmt::format("{:.2f}", *slope) : "n/a"; }

bool ran(const IntegrationConfig& config, Method method) {
  return std::find(config.methods.begin(), config.methods.end(), method) != config.methods.end();
}

// The median of the defined slopes of `method` in dimension d (over the families); none if none.
std::optional<double> median_slope(const IntegrationResult& r, Method method, std::optional<int> dimension = {}) {
  std::vector<double> slopes;
  for (const auto& s : r.slopes)
    if (s.method == method && (!dimension || s.dimension == *dimension) && s.slope) slopes.push_back(*s.slope);
  if (slopes.empty()) return std::nullopt;
  std::sort(slopes.begin(), slopes.end());
  const std::size_t n = slopes.size();
  return n % 2 ? slopes[n / 2] : 0.5 * (slopes[n / 2 - 1] + slopes[n / 2]);
}

}  // namespace

std::string integration_markdown(const IntegrationResult& result) {
  const auto& config = result.config;
  const bool has_cnj = ran(config, Method::cnj), has_jitter = ran(config, Method::jitter),
             has_random = ran(config, Method::random);
  // Every sentence below names only the methods, dimensions and sizes that were run.
  std::string method_notes;
  if (ran(config, Method::sobol)) method_notes += " Sobol at the power of two nearest K^N;";
  if (ran(config, Method::pds))
    method_notes += " Poisson disk (radius 1/K) runs until it is saturated, so its count follows from the radius;";
  std::string md = "# Integration error: does CNJ help to integrate functions? (Section 6.1)\n\n";
  md += fmt::format(
      "Genz's six families on [0,1]^N with random parameters per realization (difficulties b = 9.0, 7.25, 1.85, 7.03, "
      "20.4, 4.3), integrated by the plain mean over each point set. RMS relative error over R = {} realizations "
      "(seeds {}..{}; a realization draws new point sets and new integrands, the same integrands for every method), "
      "with its standard error; every method in [0,1]^N (the fair protocol) at the density of a K^N lattice;{} The slope "
      "is the least-squares slope of log RMS error against log points (plain Monte Carlo: -0.5); n/a where a "
      "dimension has a single size.\n\n",
      config.realizations, config.seed, config.seed + static_cast<std::uint64_t>(config.realizations - 1), method_notes);
  // Per dimension: error at the largest size, then the slope.
  std::set<int> dims(config.dimensions.begin(), config.dimensions.end());
  for (int d : dims) {
    const std::vector<int> grids = integration_grids(d, config.max_points);
    md += fmt::format("## {}D (largest K = {}, about {} points{})\n\n", d, grids.back(),
                      static_cast<std::uint64_t>(std::pow(double(grids.back()), d)),
                      grids.size() == 1 ? "; the only size, so no slope" : "");
    md += "| family |";
    for (Method m : config.methods) md += fmt::format(" {} |", to_string(m));
    md += "\n| --- |";
    for (std::size_t i = 0; i < config.methods.size(); ++i) md += " --- |";
    md += "\n";
    for (GenzFamily f : kGenzFamilies) {
      md += fmt::format("| {} |", to_string(f));
      for (Method m : config.methods) {
        const IntegrationCell* c = largest_cell(result, d, f, m);
        md += c ? fmt::format(" {:.2e} ± {:.1e} (slope {}) |", c->rms_relative_error, c->standard_error,
                              slope_text(slope_of(result, d, f, m)))
                : " |";
      }
      md += "\n";
    }
    md += "\n";
  }
  // The reading, computed from the numbers above.
  md += "## Reading\n\n";
  int cells = 0, cnj_beats_jitter = 0, jitter_beats_cnj = 0, cnj_beats_random = 0, cnj_best = 0;
  std::map<std::string, int> wins;
  std::vector<double> ratios;
  for (int d : dims)
    for (GenzFamily f : kGenzFamilies) {
      ++cells;
      const IntegrationCell* best = nullptr;
      for (Method m : config.methods) {
        const IntegrationCell* c = largest_cell(result, d, f, m);
        if (c && (!best || c->rms_relative_error < best->rms_relative_error)) best = c;
      }
      if (best) ++wins[std::string(to_string(best->method))];
      if (!has_cnj) continue;
      const IntegrationCell* cnj = largest_cell(result, d, f, Method::cnj);
      if (best == cnj) ++cnj_best;
      if (has_jitter) {
        const IntegrationCell* jitter = largest_cell(result, d, f, Method::jitter);
        ratios.push_back(cnj->rms_relative_error / jitter->rms_relative_error);
        // "beats" only when the gap exceeds two standard errors of the difference
        const double se = std::hypot(cnj->standard_error, jitter->standard_error);
        if (jitter->rms_relative_error - cnj->rms_relative_error > 2.0 * se) ++cnj_beats_jitter;
        if (cnj->rms_relative_error - jitter->rms_relative_error > 2.0 * se) ++jitter_beats_cnj;
      }
      if (has_random) {
        const IntegrationCell* random = largest_cell(result, d, f, Method::random);
        if (random->rms_relative_error - cnj->rms_relative_error > 2.0 * std::hypot(cnj->standard_error, random->standard_error))
          ++cnj_beats_random;
      }
    }
  md += fmt::format("- **Who wins** (lowest RMS error at the largest size, over {} dimension x family cells): ", cells);
  std::vector<std::pair<int, std::string>> ranking;
  for (const auto& [m, n] : wins) ranking.push_back({-n, m});
  std::sort(ranking.begin(), ranking.end());
  for (std::size_t i = 0; i < ranking.size(); ++i)
    md += fmt::format("{}{} {}", i ? ", " : "", ranking[i].second, -ranking[i].first);
  md += ".\n";
  double median_ratio = 0.0;
  if (has_cnj && has_jitter) {
    std::sort(ratios.begin(), ratios.end());
    median_ratio = ratios.size() % 2 ? ratios[ratios.size() / 2]
                                     : 0.5 * (ratios[ratios.size() / 2 - 1] + ratios[ratios.size() / 2]);
    md += fmt::format(
        "- **CNJ against the jittering it starts from**: CNJ's error is lower by more than two standard errors in {} of "
        "{} cells and higher in {}; the ratio CNJ / jitter error has median {:.2f} (range {:.2f}..{:.2f}). CNJ is the "
        "best method in {} cells.\n",
        cnj_beats_jitter, cells, jitter_beats_cnj, median_ratio, ratios.front(), ratios.back(), cnj_best);
  }
  if (has_cnj) {
    // The share of the lattice CNJ keeps at the largest size: below 1 only if points were dropped.
    std::string kept;
    double least_kept = 1.0;
    for (int d : dims) {
      const IntegrationCell* c = largest_cell(result, d, GenzFamily::gaussian, Method::cnj);
      const double share = c->points / std::pow(static_cast<double>(c->grid), d);
      least_kept = std::min(least_kept, share);
      kept += fmt::format("{}{:.1f}% in {}D", kept.empty() ? "" : ", ", 100.0 * share, d);
    }
    // CNJ's median slope per dimension, lowest and highest dimension with one.
    std::string slopes;
    std::optional<std::pair<int, double>> first_slope, last_slope;
    for (int d : dims)
      if (const auto m = median_slope(result, Method::cnj, d)) {
        if (!first_slope) first_slope = {d, *m};
        last_slope = {d, *m};
      }
    if (first_slope && last_slope && first_slope->first != last_slope->first)
      slopes = fmt::format("; its median slope is {:.2f} in {}D and {:.2f} in {}D", first_slope->second, first_slope->first,
                           last_slope->second, last_slope->first);
    if (has_jitter && median_ratio > 1.0) {
      if (least_kept < 0.9995)
        md += "- **Why CNJ loses to jitter**: CNJ drops the points its trace carries out of [0,1]^N; it keeps " + kept +
              " at the largest size" + slopes +
              ". The lost points lie near the faces, so the boundary layer is under-sampled and the plain mean is "
              "biased; the bias does not shrink like the variance, which flattens CNJ's slopes.\n";
      else
        md += "- **Why CNJ loses to jitter is not the boundary**: CNJ keeps every point (" + kept +
              " at the largest size; the field is bounded by the cube, Eq. 13), and still its median error is above "
              "jitter's" + slopes +
              ". This study does not establish the cause. One candidate, untested: the field's wavelength is tied to "
              "the lattice (5 spacings at the default frequency), so as the set grows the displaced integrand "
              "f(x + u(x)) gains detail as fast as the lattice refines, and the lattice's accuracy on smooth "
              "integrands does not carry over.\n";
    } else {
      md += "- **Points CNJ keeps**: " + kept + " at the largest size" + slopes + "." +
            (has_jitter ? std::string() : " Jitter was not run, so CNJ is not compared with the jittering it starts from.") +
            "\n";
    }
  }
  if (has_cnj && has_random)
    md += fmt::format("- **CNJ against uniform random points**: lower error (by more than two standard errors) in {} of {} cells.\n",
                      cnj_beats_random, cells);
  // Which methods converged faster than Monte Carlo here: median slope over every cell below -0.6.
  std::string steeper;
  for (Method m : config.methods)
    if (const auto slope = median_slope(result, m); slope && *slope < -0.6)
      steeper += fmt::format("{}{} {:.2f}", steeper.empty() ? "" : ", ", to_string(m), *slope);
  md += "- Slopes near -0.5 mean Monte Carlo convergence; steeper slopes mean the set's structure pays off" +
        (steeper.empty() ? std::string(" (no method's median slope is below -0.6 here)")
                         : " (median slope below -0.6 here: " + steeper + ")") +
        ". Oscillatory errors are relative to an integral that a random phase can bring near 0, which inflates them "
        "for every method alike (the integrands are shared).\n";
  return md;
}

std::vector<std::string> integration_output_files(const IntegrationConfig& config) {
  std::vector<std::string> files = {"integration.csv", "integration_slopes.csv", "integration.md"};
  for (int d : config.dimensions) files.push_back(fmt::format("integration_{}d.png", d));
  return files;
}

std::string write_integration(const IntegrationResult& result, const Log& log) {
  const std::string dir = result.config.out_dir;
  // mean_points: the mean count over the realizations, a real (CNJ in drop mode and Poisson disk vary).
  std::string cells = "dim,family,method,grid,mean_points,rms_relative_error,standard_error,realizations\n";
  for (const auto& c : result.cells)
    cells += fmt::format("{},{},{},{},{},{},{},{}\n", c.dimension, to_string(c.family), to_string(c.method), c.grid,
                         format_real(c.points), format_real(c.rms_relative_error), format_real(c.standard_error),
                         result.config.realizations);
  std::string slopes = "dim,family,method,slope\n";
  for (const auto& s : result.slopes)
    slopes += fmt::format("{},{},{},{}\n", s.dimension, to_string(s.family), to_string(s.method),
                          s.slope ? fmt::format("{:.4f}", *s.slope) : std::string());  // empty: no slope
  const std::string md = integration_markdown(result);
  for (const auto& [name, text] :
       {std::pair{"integration.csv", cells}, {"integration_slopes.csv", slopes}, {"integration.md", md}})
    write_file_atomically((std::filesystem::path(dir) / name).string(), text);
  // One figure per dimension (scripts/integration.gp).
  std::string methods;
  for (Method m : result.config.methods) methods += fmt::format("{}{}", methods.empty() ? "" : " ", to_string(m));
  for (int d : result.config.dimensions) {
    // The n^-1/2 guide of each family runs through random's smallest set, when random was run.
    std::string guides;
    for (GenzFamily family : kGenzFamilies) {
      const IntegrationCell* first = nullptr;
      for (const auto& c : result.cells)
        if (c.dimension == d && c.family == family && c.method == Method::random && (!first || c.points < first->points))
          first = &c;
      guides += first ? fmt::format("{:.9g} {:.9g} ", first->points, first->rms_relative_error) : std::string("- - ");
    }
    draw_figure(PlotProgram::integration, (std::filesystem::path(dir) / fmt::format("integration_{}d.png", d)).string(),
                {(std::filesystem::path(dir) / "integration.csv").string(), std::to_string(d), methods, guides,
                 fmt::format("{} realizations, seeds {}..{}, Genz's six families in [0,1]^{}", result.config.realizations,
                             result.config.seed, result.config.seed + static_cast<std::uint64_t>(result.config.realizations - 1), d)},
                log);
  }
  return md;
}

}  // namespace dfvn
