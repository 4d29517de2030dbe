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

// The summary rows of a CSV table whose rows are realizations (issue 24, tidy outputs). The table has
// a `stat` column whose value is a word: "value" in every data row, "mean" or "sd" in a summary row,
// so no column changes type. `rows`: data lines without their newline, all with the columns of
// `header` (comma-separated; a field may be a double-quoted text without commas inside quotes). Rows
// are grouped by the values of `group_columns` (e.g. "method"), in order of first appearance; for each
// group two rows are returned, stat = "mean" and "sd": the group columns keep their value,
// `label_column` (e.g. "seed") is empty, and every column whose cell is a real number in every row of
// the group (written with a decimal point or exponent, io/csv.hpp's format_real) gets its mean (sample
// sd) as format_real writes it. Every other column, integer counts (points, dropped) and words alike,
// is empty in the summary rows: its values are in the data rows.
std::string realization_summary_rows(const std::string& header, const std::vector<std::string>& rows,
                                     const std::vector<std::string>& group_columns, const std::string& label_column);

}  // namespace dfvn
