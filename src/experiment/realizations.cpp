#include "dfvn/experiment/realizations.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <stdexcept>
#include <string_view>

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

// A real number as format_real writes it: a decimal point or an exponent ("1.0", "2e-07"); integers
// ("512") and words are not reals, and nan or inf have no mean.
bool parse_real(const std::string& text, double& value) {
  if (text.empty() || text.find_first_of(".eE") == std::string::npos) return false;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  return error == std::errc() && end == text.data() + text.size() && std::isfinite(value);
}

std::size_t column_index(const std::vector<std::string>& columns, const std::string& name) {
  for (std::size_t c = 0; c < columns.size(); ++c)
    if (columns[c] == name) return c;
  throw std::invalid_argument("realization_summary_rows: no column '" + name + "'");
}

}  // namespace

std::string realization_summary_rows(const std::string& header, const std::vector<std::string>& rows,
                                     const std::vector<std::string>& group_columns, const std::string& label_column) {
  const std::vector<std::string> columns = split_csv(header);
  const std::size_t label = column_index(columns, label_column);
  const std::size_t stat = column_index(columns, "stat");
  std::vector<std::size_t> group;
  for (const auto& name : group_columns) group.push_back(column_index(columns, name));

  std::vector<std::vector<std::vector<std::string>>> groups;  // group -> rows -> fields
  std::vector<std::string> keys;
  for (const auto& row : rows) {
    std::vector<std::string> fields = split_csv(row);
    if (fields.size() != columns.size()) throw std::invalid_argument("realization_summary_rows: ragged row: " + row);
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
  for (const auto& members : groups) {
    std::vector<std::string> mean_row(columns.size()), sd_row(columns.size());
    for (std::size_t c = 0; c < columns.size(); ++c) {
      if (std::find(group.begin(), group.end(), c) != group.end()) {
        mean_row[c] = sd_row[c] = members.front()[c];
        continue;
      }
      if (c == label || c == stat) continue;
      std::vector<double> values;
      for (const auto& fields : members) {
        double v = 0.0;
        if (!parse_real(fields[c], v)) break;
        values.push_back(v);
      }
      if (values.size() != members.size()) continue;
      const MeanSd s = mean_sd(values);
      mean_row[c] = format_real(s.mean);
      sd_row[c] = format_real(s.sd);
    }
    mean_row[stat] = "mean";
    sd_row[stat] = "sd";
    for (const auto* row : {&mean_row, &sd_row}) {
      for (std::size_t c = 0; c < columns.size(); ++c) out += (c ? "," : "") + (*row)[c];
      out += '\n';
    }
  }
  return out;
}

}  // namespace dfvn
