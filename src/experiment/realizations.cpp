#include "dfvn/experiment/realizations.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <stdexcept>
#include <string_view>

#include <fmt/format.h>

#include "dfvn/io/csv.hpp"

namespace dfvn {

MeanSd mean_sd(const std::vector<double>& values) {
  MeanSd out;
  if (values.empty()) return out;
  for (double v : values) out.mean += v;
  out.mean /= static_cast<double>(values.size());
  if (values.size() < 2) return out;
  double squares = 0.0;
  for (double v : values) squares += (v - out.mean) * (v - out.mean);
  out.sd = std::sqrt(squares / static_cast<double>(values.size() - 1));
  return out;
}

namespace {

// Splits at commas outside double quotes.
std::vector<std::string> split_csv(const std::string& line) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (char c : line) {
    if (c == '"') quoted = !quoted;
    if (c == ',' && !quoted) {
      fields.emplace_back();
    } else {
      fields.back() += c;
    }
  }
  return fields;
}

// A number in a CSV cell: a real as format_real writes it or an integer (a count); nan or inf have no
// mean. Words and empty cells are not numbers.
bool parse_number(const std::string& text, double& value) {
  if (text.empty()) return false;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  return error == std::errc() && end == text.data() + text.size() && std::isfinite(value);
}

// The statistics of the point sets and the times: summarised even when they happen not to vary (two
// sets with the same closest pair, two timings within a microsecond), unlike a constant setting.
bool is_statistic(const std::string& column) {
  static const std::vector<std::string> kStatistics = {
      "nn_min", "nn_q01", "nn_median", "nn_mean", "nn_median_scaled", "rms_displacement", "median_displacement",
      "frac_unmoved", "neighbour_disorder", "lattice_order", "cd", "wd", "md", "l2_star"};
  return std::find(kStatistics.begin(), kStatistics.end(), column) != kStatistics.end() || column.starts_with("seconds");
}

std::size_t column_index(const std::vector<std::string>& columns, const std::string& name) {
  for (std::size_t c = 0; c < columns.size(); ++c)
    if (columns[c] == name) return c;
  throw std::invalid_argument("realization_summary_csv: no column '" + name + "'");
}

}  // namespace

double standard_error(const MeanSd& s, std::size_t count) {
  return count > 0 ? s.sd / std::sqrt(static_cast<double>(count)) : 0.0;
}

std::string realization_summary_csv(const std::string& header, const std::vector<std::string>& rows,
                                    const std::vector<std::string>& group_columns, const std::string& label_column) {
  const std::vector<std::string> columns = split_csv(header);
  const std::size_t label = column_index(columns, label_column);
  std::vector<std::size_t> group;
  for (const auto& name : group_columns) group.push_back(column_index(columns, name));

  std::vector<std::vector<std::vector<std::string>>> groups;  // group -> rows -> fields
  std::vector<std::string> keys;
  for (const auto& row : rows) {
    std::vector<std::string> fields = split_csv(row);
    if (fields.size() != columns.size()) throw std::invalid_argument("realization_summary_csv: ragged row: " + row);
    std::string key;
    for (std::size_t c : group) key += fields[c] + '\x1f';
    std::size_t g = 0;
    while (g < keys.size() && keys[g] != key) ++g;
    if (g == keys.size()) {
      keys.push_back(key);
      groups.emplace_back();
    }
    groups[g].push_back(std::move(fields));
  }

  std::string out;
  for (const std::string& name : group_columns) out += name + ",";
  out += "statistic,realizations,mean,sd,standard_error\n";
  for (const auto& members : groups) {
    std::string key;
    for (std::size_t c : group) key += members.front()[c] + ",";
    for (std::size_t c = 0; c < columns.size(); ++c) {
      if (c == label || std::find(group.begin(), group.end(), c) != group.end()) continue;
      std::vector<double> values;
      bool varies = false;
      for (const auto& fields : members) {
        double v = 0.0;
        if (!parse_number(fields[c], v)) break;
        varies = varies || fields[c] != members.front()[c];
        values.push_back(v);
      }
      if (values.size() != members.size() || (!varies && !is_statistic(columns[c]))) continue;
      const MeanSd s = mean_sd(values);
      const double se = standard_error(s, values.size());
      const bool seconds = columns[c].starts_with("seconds");
      const auto real = [&](double v) { return seconds ? fmt::format("{:.6f}", v) : format_real(v); };
      out += fmt::format("{}{},{},{},{},{}\n", key, columns[c], values.size(), real(s.mean), real(s.sd), real(se));
    }
  }
  return out;
}

}  // namespace dfvn
