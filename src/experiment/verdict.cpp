#include "dfvn/experiment/verdict.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>
#include <stdexcept>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "dfvn/experiment/realizations.hpp"

namespace dfvn {

namespace {

struct StatisticSource {
  const char* name;
  const char* description;
  std::function<double(const NearestNeighbourSummary&)> read;
};

const StatisticSource kSources[] = {
    {"nn_min", "The smallest nearest-neighbour distance (the closest pair)",
     [](const NearestNeighbourSummary& s) { return s.min; }},
    {"nn_q01", "The 1% quantile of the nearest-neighbour distances (the closest pairs but a few)",
     [](const NearestNeighbourSummary& s) { return s.q01; }},
    {"nn_median_scaled", "The median nearest-neighbour distance in mean spacings (the density removed)",
     [](const NearestNeighbourSummary& s) { return s.median_scaled; }},
};

std::optional<VerdictEntry> find(const VerdictStatistic& statistic, Method method) {
  for (const VerdictEntry& e : statistic.ranked)
    if (e.method == method) return e;
  return std::nullopt;
}

std::string number(double value) { return fmt::format("{:.4g}", value); }

std::string ratio(const VerdictEntry& e, const std::optional<VerdictEntry>& reference) {
  if (!reference || reference->mean == 0.0) return "";
  return fmt::format("{:.3g}x", e.mean / reference->mean);
}

// "exceeds 2 s.e." / "within 2 s.e." / "" (one realization).
std::string significance(const VerdictEntry& a, const VerdictEntry& b) {
  if (a.realizations < 2 || b.realizations < 2) return "";
  return differs_beyond_two_standard_errors(a, b) ? "the difference exceeds two standard errors"
                                                  : "the difference is within two standard errors";
}

std::string domain_sentence(const SampleConfig& config, const std::vector<SamplingRealization>& runs) {
  const int n = config.dimension;
  // Every result's domain and count, in the first run.
  std::vector<const MethodResult*> results;
  for (const MethodResult& r : runs.front().results) results.push_back(&r);
  bool one_domain = true, one_count = true;
  for (const MethodResult* r : results) {
    one_domain = one_domain && r->plan.domain == results.front()->plan.domain;
    one_count = one_count && r->point_count == results.front()->point_count;
  }
  const Domain& d = results.front()->plan.domain;
  const char* metric = d.kind == DomainKind::torus    ? "minimum-image distances"
                       : d.kind == DomainKind::sphere ? "great-circle distances"
                                                      : "Euclidean distances";
  std::string text;
  if (one_domain)
    text = fmt::format("every set in {}, measured with {}", d.describe(n), metric);
  else
    text = fmt::format("the sets in different boxes (the paper's: {}), measured with Euclidean distances; "
                       "nn_median_scaled removes the density, nn_min and nn_q01 do not",
                       fmt::join([&] {
                         std::vector<std::string> boxes;
                         for (const MethodResult* r : results)
                           boxes.push_back(fmt::format("{} {}", to_string(r->plan.method), r->plan.domain.describe(n)));
                         return boxes;
                       }(),
                                 "; "));
  text += one_count ? fmt::format(", {} points each", results.front()->point_count)
                    : std::string(", with different counts (the points column of the stats CSV)");
  return text;
}

}  // namespace

bool differs_beyond_two_standard_errors(const VerdictEntry& a, const VerdictEntry& b) {
  if (a.realizations < 2 || b.realizations < 2) return false;
  return std::abs(a.mean - b.mean) > 2.0 * std::hypot(a.standard_error, b.standard_error);
}

std::vector<VerdictStatistic> verdict_statistics(const std::vector<SamplingRealization>& runs) {
  std::vector<VerdictStatistic> out;
  if (runs.empty()) return out;
  std::vector<Method> methods;
  for (const MethodResult& r : runs.front().results)
    if (r.measured) methods.push_back(r.plan.method);
  if (methods.empty()) return out;
  for (const StatisticSource& source : kSources) {
    VerdictStatistic statistic{source.name, source.description, {}};
    for (Method m : methods) {
      std::vector<double> values;
      for (const SamplingRealization& run : runs)
        for (const MethodResult& r : run.results)
          if (r.plan.method == m && r.measured) values.push_back(source.read(r.nearest));
      const MeanSd s = mean_sd(values);
      const int count = static_cast<int>(values.size());
      statistic.ranked.push_back({m, s.mean, count > 1 ? s.sd / std::sqrt(static_cast<double>(count)) : 0.0, count});
    }
    std::stable_sort(statistic.ranked.begin(), statistic.ranked.end(),
                     [](const VerdictEntry& a, const VerdictEntry& b) { return a.mean > b.mean; });
    out.push_back(std::move(statistic));
  }
  return out;
}

std::string verdict_markdown(const SampleConfig& config, const std::vector<SamplingRealization>& runs) {
  const std::vector<VerdictStatistic> statistics = verdict_statistics(runs);
  if (statistics.empty()) throw std::invalid_argument("the verdict needs the statistics of at least one set");
  const int realizations = statistics.front().ranked.front().realizations;
  std::string md = "# Verdict\n\n";
  md += fmt::format(
      "dfvn-sample sample, {}D, K = {}, the {} protocol: {}; {} realization{} (seed{} {}).\n\n", config.dimension,
      config.grid, to_string(config.protocol), domain_sentence(config, runs), realizations, realizations == 1 ? "" : "s",
      realizations == 1 ? "" : "s",
      realizations == 1 ? std::to_string(runs.front().seed)
                        : fmt::format("{}..{}", runs.front().seed, runs.back().seed));
  md += "Every statistic below is a nearest-neighbour distance: larger means the points keep further apart, the "
        "blue-noise property Table 1 of the paper compares. ";
  md += realizations > 1
            ? fmt::format("Values are means over the {} realizations with their standard error (sd / sqrt({})); a "
                          "difference counts when it exceeds two standard errors of the difference.\n\n",
                          realizations, realizations)
            : "With one realization the seed-to-seed spread is unknown: run --realizations R (R >= 2) to tell "
              "whether a difference exceeds it.\n\n";
  const bool has_matched = find(statistics.front(), Method::jitter_matched).has_value();
  const bool has_pds = find(statistics.front(), Method::pds).has_value();
  for (const VerdictStatistic& statistic : statistics) {
    md += fmt::format("## {}\n\n{}.\n\n", statistic.name, statistic.description);
    md += "| rank | method | value |";
    if (realizations > 1) md += " s.e. |";
    if (has_matched) md += " vs jitter-matched |";
    if (has_pds) md += " vs pds |";
    md += "\n|---|---|---|";
    if (realizations > 1) md += "---|";
    if (has_matched) md += "---|";
    if (has_pds) md += "---|";
    md += "\n";
    const auto matched = find(statistic, Method::jitter_matched), pds = find(statistic, Method::pds);
    for (std::size_t k = 0; k < statistic.ranked.size(); ++k) {
      const VerdictEntry& e = statistic.ranked[k];
      md += fmt::format("| {} | {} | {} |", k + 1, to_string(e.method), number(e.mean));
      if (realizations > 1) md += fmt::format(" {} |", number(e.standard_error));
      if (has_matched) md += fmt::format(" {} |", ratio(e, matched));
      if (has_pds) md += fmt::format(" {} |", ratio(e, pds));
      md += "\n";
    }
    md += "\n";
  }
  // CNJ's place, when it ran.
  if (find(statistics.front(), Method::cnj)) {
    md += "## CNJ\n\n";
    for (const VerdictStatistic& statistic : statistics) {
      const VerdictEntry cnj = *find(statistic, Method::cnj);
      const auto at = std::find_if(statistic.ranked.begin(), statistic.ranked.end(),
                                   [](const VerdictEntry& e) { return e.method == Method::cnj; });
      const std::size_t rank = static_cast<std::size_t>(at - statistic.ranked.begin()) + 1;
      md += fmt::format("- {}: CNJ ranks {} of {} ({}).", statistic.name, rank, statistic.ranked.size(), number(cnj.mean));
      for (Method other : {Method::jitter_matched, Method::pds, Method::sobol, Method::jitter}) {
        const auto o = find(statistic, other);
        if (!o) continue;
        const std::string name(to_string(other));
        const std::string spread = significance(cnj, *o);
        if (cnj.mean < o->mean)
          md += fmt::format(" It loses to {} ({} of its value{}).", name, ratio(cnj, o), spread.empty() ? "" : "; " + spread);
        else if (cnj.mean > o->mean)
          md += fmt::format(" It beats {} ({} its value{}).", name, ratio(cnj, o), spread.empty() ? "" : "; " + spread);
        else
          md += fmt::format(" It ties with {}.", name);
      }
      md += "\n";
    }
    md += "\n";
  }
  return md;
}

std::vector<std::string> verdict_summary(const SampleConfig& config, const std::vector<SamplingRealization>& runs) {
  (void)config;
  const std::vector<VerdictStatistic> statistics = verdict_statistics(runs);
  std::vector<std::string> lines;
  for (const VerdictStatistic& statistic : statistics) {
    if (statistic.name != "nn_median_scaled" && statistic.name != "nn_min") continue;
    std::vector<std::string> parts;
    for (const VerdictEntry& e : statistic.ranked) parts.push_back(fmt::format("{} {}", to_string(e.method), number(e.mean)));
    std::string line = fmt::format("verdict by {} (larger packs better): {}", statistic.name, fmt::join(parts, " > "));
    if (const auto cnj = find(statistic, Method::cnj); cnj && statistic.ranked.size() > 1) {
      const auto at = std::find_if(statistic.ranked.begin(), statistic.ranked.end(),
                                   [](const VerdictEntry& e) { return e.method == Method::cnj; });
      line += fmt::format("; cnj is {} of {}", static_cast<std::size_t>(at - statistic.ranked.begin()) + 1,
                          statistic.ranked.size());
      if (at != statistic.ranked.begin())
        line += fmt::format(" ({} of {}'s)", ratio(*cnj, statistic.ranked.front()), to_string(statistic.ranked.front().method));
    }
    lines.push_back(line);
  }
  return lines;
}

}  // namespace dfvn
