// Statistics over realizations (seeds s..s+R-1, or the sets of one file): mean and standard deviation.
#pragma once

#include <string>
#include <vector>

namespace dfvn {

struct MeanSd {
  double mean = 0.0;
  double sd = 0.0;  // sample standard deviation (divisor R - 1); 0 for one realization
};
MeanSd mean_sd(const std::vector<double>& values);

// Summary rows of a CSV table whose rows are realizations. `rows`: data lines without their newline,
// all with the columns of `header` (comma-separated; a field may be a double-quoted text without
// commas inside quotes). Rows are grouped by the values of `group_columns` (e.g. "method"), in order
// of first appearance; for each group two rows are returned, "mean" and "sd" in `label_column`
// (e.g. "seed"): every column that is a number in every row of the group gets its mean (sd), the
// group columns keep their value, every other column is left empty.
std::string realization_summary_rows(const std::string& header, const std::vector<std::string>& rows,
                                     const std::vector<std::string>& group_columns, const std::string& label_column);

}  // namespace dfvn
