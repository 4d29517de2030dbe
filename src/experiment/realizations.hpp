// Statistics over realizations (seeds s..s+R-1, or the sets of one file): mean and standard deviation.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace dfvn {

struct MeanSd {
  double mean = 0.0;
  double sd = 0.0;  // sample standard deviation (divisor R - 1); 0 for one realization
};
MeanSd mean_sd(const std::vector<double>& values);

// The standard error of a mean over `count` values with sample standard deviation `sd`: sd / sqrt(count).
double standard_error(const MeanSd& s, std::size_t count);

// The summary of a CSV table whose rows are realizations (seeds s..s+R-1, or the sets of one file), as a
// table of its own (`--summary FILE`): its header is `group_columns` then
// statistic,realizations,mean,sd,standard_error, and it has one row per group (in order of first
// appearance) and per column whose cells are numbers in every row of the group:
// mean, sample sd and sd / sqrt(R) as reals (statistics to 9 significant digits, a seconds_* column's
// to 6 decimals). A column constant over the realizations (a setting, such as domain_side or
// cycles_per_spacing) is not summarised, unless it is a statistic of the sets (nn_*, the displacement
// columns, the discrepancies) or a time (seconds_*), which always is; words, empty cells and `label_column` (the seed or set
// number) never are. `rows`: data lines without their newline, with the columns of `header`
// (comma-separated; a field may be a double-quoted text without commas inside quotes).
std::string realization_summary_csv(const std::string& header, const std::vector<std::string>& rows,
                                    const std::vector<std::string>& group_columns, const std::string& label_column);

}  // namespace dfvn
