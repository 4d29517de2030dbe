// A run's results as JSON (--json FILE), so that a script needs no CSV parsing: the parameters, every
// method's (or set's) statistics and the values derived from the options. Numbers are written with
// the 17 significant digits that read back to the same double; a value that does not apply is left
// out (or null where its object is), never written as a made-up number.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "dfvn/experiment/experiment.hpp"
#include "dfvn/stats/point_set_statistics.hpp"

namespace dfvn {

// The results of one seed of a sampling run.
struct SamplingRealization {
  std::uint64_t seed = 0;
  std::vector<MethodResult> results;
};

// {"program", "version", "parameters": {...}, "results": [one object per realization and method],
// "summary": {method: {statistic: {"mean", "sd"}}} (with more than one realization)}. `timing`: include
// the seconds (off: two runs with the same seed give the same bytes).
std::string sampling_json(const SampleConfig& config, const std::vector<SamplingRealization>& realizations, bool timing);

// What made one point set, for the sidecar beside its file (io/point_sidecar.hpp): {"program",
// "version", "method", "protocol", "seeds" (one per set in the file), "requested", "generation" (the
// facts of the stats CSV's columns: radius, trace time, ...), "notes", "run" (the --json parameters)},
// as one line of JSON text.
std::string point_set_made_by_json(const SampleConfig& config, const MethodResult& result,
                                   const std::vector<std::uint64_t>& seeds);

// `dfvn-sample stats`: {"program", "version", "parameters": {"input", "format", "domain_side", ...},
// "sets": [one object per set], "summary"} (summary with more than one set). JSON strings are UTF-8:
// bytes of `input` that are not valid UTF-8 are written as U+FFFD.
struct PointStatisticsRun {
  std::string input;
  std::string format;
  double domain_side = 1.0;
  PointSetStatisticsOptions options;
  std::vector<PointSetStatistics> sets;
  std::vector<int> dimensions;
  bool timing = true;
};
std::string point_statistics_json(const PointStatisticsRun& run);

}  // namespace dfvn
