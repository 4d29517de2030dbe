// The main job's verdict: which method packs best by each statistic that was computed, by how much
// against jitter moved as far as CNJ and against Poisson disk, and whether a difference exceeds the
// seed-to-seed spread (sample --report, and its summary on standard error).
#pragma once

#include <string>
#include <vector>

#include "dfvn/experiment/json_report.hpp"

namespace dfvn {

// One statistic of every method over the realizations: mean, standard error (sd / sqrt(R), 0 for one
// realization), in the order the methods ran.
struct VerdictEntry {
  Method method;
  double mean = 0.0;
  double standard_error = 0.0;
  int realizations = 0;
};

struct VerdictStatistic {
  std::string name;         // the stats CSV's column: nn_min, nn_q01, nn_median_scaled
  std::string description;  // what it measures, in words
  std::vector<VerdictEntry> ranked;  // best first (the largest: every statistic here is a distance)
};

// The statistics a verdict ranks, from the runs' nearest-neighbour summaries (every realization's);
// empty when no run measured its sets. Ties keep the order the methods ran.
std::vector<VerdictStatistic> verdict_statistics(const std::vector<SamplingRealization>& runs);

// Whether two entries differ by more than twice the standard error of their difference,
// sqrt(se_a^2 + se_b^2); false with fewer than two realizations (the spread is unknown).
bool differs_beyond_two_standard_errors(const VerdictEntry& a, const VerdictEntry& b);

// The Markdown report (--report FILE): the run in one paragraph (dimension, lattice, protocol, domain
// and metric, points, realizations), a table per statistic ranking the methods with mean, standard error
// and the ratio to jitter-matched and to Poisson disk (where they ran), and a reading of CNJ's place
// that says plainly where it loses. Names only the methods and statistics that were run.
std::string verdict_markdown(const SampleConfig& config, const std::vector<SamplingRealization>& runs);

// The same in a few lines for standard error: the ranking by nn_median_scaled and CNJ's place in it.
std::vector<std::string> verdict_summary(const SampleConfig& config, const std::vector<SamplingRealization>& runs);

}  // namespace dfvn
