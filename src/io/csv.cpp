#include "io/csv.hpp"

#include <charconv>
#include <cmath>
#include <fmt/format.h>

#include "core/message_text.hpp"

namespace dfvn {

namespace {

std::string_view trim(std::string_view s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return {};
  const auto last = s.find_last_not_of(" \t\r");
  return s.substr(first, last - first + 1);
}

// Splits a line at commas. A field may be quoted ("0.5", or "a ""b""" with doubled quotes inside, as
// in RFC 4180); spaces around a field or inside its quotes are ignored. Throws InputError naming the
// line and column for an unterminated quote or text after a closing quote.
std::vector<std::string> split_fields(std::string_view line, std::size_t line_number) {
  std::vector<std::string> fields;
  std::size_t at = 0;
  while (true) {
    const std::size_t column = fields.size() + 1;
    while (at < line.size() && (line[at] == ' ' || line[at] == '\t')) ++at;
    std::string field;
    if (at < line.size() && line[at] == '"') {
      bool closed = false;
      for (++at; at < line.size(); ++at) {
        if (line[at] != '"') {
          field += line[at];
        } else if (at + 1 < line.size() && line[at + 1] == '"') {
          field += '"';
          ++at;
        } else {
          closed = true;
          ++at;
          break;
        }
      }
      if (!closed) throw InputError(fmt::format("line {}, column {}: unterminated quote", line_number, column));
      const std::size_t comma = line.find(',', at);
      if (!trim(line.substr(at, comma == std::string_view::npos ? std::string_view::npos : comma - at)).empty())
        throw InputError(fmt::format("line {}, column {}: text after the closing quote", line_number, column));
      field = std::string(trim(field));
      at = comma;
    } else {
      const std::size_t comma = line.find(',', at);
      field = std::string(trim(line.substr(at, comma == std::string_view::npos ? std::string_view::npos : comma - at)));
      at = comma;
    }
    fields.push_back(std::move(field));
    if (at == std::string_view::npos) break;
    ++at;
  }
  return fields;
}

enum class ParseResult { ok, not_a_number, out_of_range, not_finite };

ParseResult parse_double(std::string_view text, double& value) {
  // from_chars takes no '+'; allow one, but not a second sign ("+-1").
  if (!text.empty() && text.front() == '+') {
    text.remove_prefix(1);
    if (!text.empty() && (text.front() == '+' || text.front() == '-')) return ParseResult::not_a_number;
  }
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
    // A UTF-8 byte order mark (EF BB BF), as spreadsheet programs write it, is not part of the data.
    if (line_number == 1 && line.starts_with("\xEF\xBB\xBF")) line.erase(0, 3);
    if (trim(line).empty()) continue;
    const auto fields = split_fields(line, line_number);
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
    // The first line may be a header: no field of it a number, quoted or not ("0.1" is a number).
    if (line_number == 1 && non_numeric == dimension) continue;
    const std::string bad = quote_for_message(fields[first_bad]);
    switch (first_problem) {
      case ParseResult::not_finite:
        throw InputError(fmt::format("line {}, column {}: {} is not a finite number (NaN and Inf are not allowed)",
                                     line_number, first_bad + 1, bad));
      case ParseResult::out_of_range:
        throw InputError(fmt::format("line {}, column {}: {} is out of the range of a double", line_number,
                                     first_bad + 1, bad));
      default:
        throw InputError(fmt::format("line {}, column {}: {} is not a number", line_number, first_bad + 1, bad));
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
