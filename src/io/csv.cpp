#include "io/csv.hpp"

#include <charconv>
#include <cmath>
#include <fmt/format.h>

namespace dfvn {

namespace {

std::string_view trim(std::string_view s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return {};
  const auto last = s.find_last_not_of(" \t\r");
  return s.substr(first, last - first + 1);
}

std::vector<std::string_view> split_fields(std::string_view line) {
  std::vector<std::string_view> fields;
  std::size_t start = 0;
  while (true) {
    const auto comma = line.find(',', start);
    fields.push_back(trim(line.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start)));
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return fields;
}

enum class ParseResult { ok, not_a_number, out_of_range, not_finite };

ParseResult parse_double(std::string_view text, double& value) {
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (text.empty() || ptr != end) return ParseResult::not_a_number;
  if (ec == std::errc::result_out_of_range) return ParseResult::out_of_range;
  if (ec != std::errc()) return ParseResult::not_a_number;
  if (!std::isfinite(value)) return ParseResult::not_finite;
  return ParseResult::ok;
}

}  // namespace

PointTable read_points_csv(std::istream& in, int dimension) {
  if (dimension < 1 || dimension > 16)
    throw std::invalid_argument("read_points_csv: dimension must be in 1..16");
  PointTable table;
  table.dimension = dimension;
  std::string line;
  std::size_t line_number = 0;
  while (std::getline(in, line)) {
    ++line_number;
    if (trim(line).empty()) continue;
    const auto fields = split_fields(line);
    if (static_cast<int>(fields.size()) != dimension)
      throw InputError(fmt::format("line {}: expected {} comma-separated columns (--dim {}), found {}",
                                   line_number, dimension, dimension, fields.size()));
    double values[16];
    int non_numeric = 0;
    std::size_t first_bad = 0;
    ParseResult first_problem = ParseResult::ok;
    for (std::size_t j = 0; j < fields.size(); ++j) {
      const ParseResult r = parse_double(fields[j], values[j]);
      if (r != ParseResult::ok) {
        if (first_problem == ParseResult::ok) {
          first_problem = r;
          first_bad = j;
        }
        non_numeric += (r == ParseResult::not_a_number);
      }
    }
    if (first_problem == ParseResult::ok) {
      table.coordinates.insert(table.coordinates.end(), values, values + dimension);
      continue;
    }
    // A first line without any number is a header.
    if (table.coordinates.empty() && line_number == 1 && non_numeric == dimension) continue;
    const std::string_view bad = fields[first_bad];
    switch (first_problem) {
      case ParseResult::not_finite:
        throw InputError(fmt::format("line {}, column {}: '{}' is not a finite number (NaN and Inf are not allowed)",
                                     line_number, first_bad + 1, bad));
      case ParseResult::out_of_range:
        throw InputError(fmt::format("line {}, column {}: '{}' is out of the range of a double", line_number,
                                     first_bad + 1, bad));
      default:
        throw InputError(fmt::format("line {}, column {}: '{}' is not a number", line_number, first_bad + 1, bad));
    }
  }
  if (in.bad()) throw InputError("read error");
  return table;
}

void append_double(std::string& out, double value) { fmt::format_to(std::back_inserter(out), "{:.17g}", value); }

std::string numbered_header(std::string_view prefix, int count, int first_index) {
  std::string out;
  for (int i = 0; i < count; ++i) {
    if (i) out += ',';
    fmt::format_to(std::back_inserter(out), "{}{}", prefix, first_index + i);
  }
  return out;
}

}  // namespace dfvn
