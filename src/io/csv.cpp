#include "dfvn/io/csv.hpp"

#include <algorithm>
#include <charconv>
#include <iterator>
#include <sstream>
#include <cmath>
#include <fmt/format.h>

#include "dfvn/core/message_text.hpp"

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

}  // namespace

NumberText parse_coordinate(std::string_view text, double& value) {
  // from_chars takes no '+'; allow one, but not a second sign ("+-1", "++1").
  if (!text.empty() && text.front() == '+') {
    text.remove_prefix(1);
    if (!text.empty() && (text.front() == '+' || text.front() == '-')) return NumberText::not_a_number;
  }
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (text.empty() || ptr != end) return NumberText::not_a_number;
  if (ec == std::errc::result_out_of_range) return NumberText::out_of_range;
  if (ec != std::errc()) return NumberText::not_a_number;
  if (!std::isfinite(value)) return NumberText::not_finite;
  return NumberText::ok;
}

std::string coordinate_error(NumberText problem, std::size_t line, std::size_t column, std::string_view text) {
  const std::string bad = quote_for_message(text);
  switch (problem) {
    case NumberText::not_finite:
      return fmt::format("line {}, column {}: {} is not a finite number (NaN and Inf are not allowed)", line, column, bad);
    case NumberText::out_of_range:
      return fmt::format("line {}, column {}: {} is out of the range of a double", line, column, bad);
    case NumberText::not_a_number:
    case NumberText::ok:
      break;
  }
  return fmt::format("line {}, column {}: {} is not a number", line, column, bad);
}

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
    NumberText first_problem = NumberText::ok;
    for (std::size_t j = 0; j < fields.size(); ++j) {
      const NumberText r = parse_coordinate(fields[j], values[j]);
      if (r != NumberText::ok) {
        if (first_problem == NumberText::ok) {
          first_problem = r;
          first_bad = j;
        }
        non_numeric += (r == NumberText::not_a_number);
      }
    }
    if (first_problem == NumberText::ok) {
      table.coordinates.insert(table.coordinates.end(), values, values + dimension);
      continue;
    }
    // The first line may be a header: no field of it a number, quoted or not ("0.1" is a number).
    if (line_number == 1 && non_numeric == dimension) continue;
    throw InputError(coordinate_error(first_problem, line_number, first_bad + 1, fields[first_bad]));
  }
  if (in.bad()) throw InputError("read error");
  return table;
}

namespace {

std::string replace_first(std::string text, const std::string& from, const std::string& to) {
  if (const auto at = text.find(from); at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

// Whitespace-separated fields of one line.
std::vector<std::string> split_whitespace(std::string_view line) {
  std::vector<std::string> fields;
  std::size_t at = 0;
  while (true) {
    at = line.find_first_not_of(" \t\r", at);
    if (at == std::string_view::npos) break;
    const std::size_t end = std::min(line.find_first_of(" \t\r", at), line.size());
    fields.emplace_back(line.substr(at, end - at));
    at = end;
  }
  return fields;
}

PointTable read_points_whitespace(std::istream& in, int dimension, bool inferred) {
  PointTable table;
  table.dimension = dimension;
  std::string line;
  std::size_t line_number = 0;
  bool seen_data_line = false;
  while (std::getline(in, line)) {
    ++line_number;
    if (line_number == 1 && line.starts_with("\xEF\xBB\xBF")) line.erase(0, 3);
    const std::string_view text = trim(line);
    if (text.empty() || text.front() == '#') continue;
    const auto fields = split_whitespace(text);
    const bool first = !seen_data_line;
    seen_data_line = true;
    if (static_cast<int>(fields.size()) != dimension)
      throw InputError(fmt::format("line {}: expected {} whitespace-separated columns ({}), found {}", line_number, dimension,
                                   inferred ? std::string("as in the first line") : fmt::format("--dim {}", dimension),
                                   fields.size()));
    double values[16];
    int non_numeric = 0;
    for (std::size_t j = 0; j < fields.size(); ++j) non_numeric += parse_coordinate(fields[j], values[j]) == NumberText::not_a_number;
    if (first && non_numeric == dimension) continue;  // a header line
    for (std::size_t j = 0; j < fields.size(); ++j) {
      const NumberText r = parse_coordinate(fields[j], values[j]);
      if (r != NumberText::ok) throw InputError(coordinate_error(r, line_number, j + 1, fields[j]));
    }
    table.coordinates.insert(table.coordinates.end(), values, values + dimension);
  }
  if (in.bad()) throw InputError("read error");
  return table;
}

}  // namespace

PointTable read_points_text(std::istream& in, int dimension) {
  if (dimension < 0 || dimension > 16) throw std::invalid_argument("read_points_text: dimension must be in 0..16");
  const std::string bytes(std::istreambuf_iterator<char>(in), {});
  if (in.bad()) throw InputError("read error");
  // The first line that is neither blank nor a comment decides the layout (and, if asked, the dimension).
  std::size_t begin = 0, line_number = 0;
  std::string_view first_line;
  while (begin < bytes.size()) {
    const std::size_t end = std::min(bytes.find('\n', begin), bytes.size());
    ++line_number;
    std::string_view line = std::string_view(bytes).substr(begin, end - begin);
    if (line_number == 1 && line.starts_with("\xEF\xBB\xBF")) line.remove_prefix(3);
    begin = end + 1;
    const std::string_view text = trim(line);
    if (text.empty() || text.front() == '#') continue;
    first_line = text;
    break;
  }
  const bool comma = first_line.find(',') != std::string_view::npos;
  const bool inferred = dimension == 0;
  if (inferred) {
    if (first_line.empty()) throw InputError("no points in the input");
    const std::size_t columns = comma ? split_fields(first_line, line_number).size() : split_whitespace(first_line).size();
    if (columns > 16) throw InputError(fmt::format("line {}: {} columns; at most 16 are read", line_number, columns));
    dimension = static_cast<int>(columns);
  }
  std::istringstream text(bytes);
  if (!comma) return read_points_whitespace(text, dimension, inferred);
  try {
    return read_points_csv(text, dimension);
  } catch (const InputError& e) {
    if (!inferred) throw;
    throw InputError(replace_first(e.what(), fmt::format(" (--dim {})", dimension), " (as in the first line)"));
  }
}

void append_double(std::string& out, double value) {
  const std::size_t start = out.size();
  fmt::format_to(std::back_inserter(out), "{:.17g}", value);
  if (std::isfinite(value) && out.find_first_of(".e", start) == std::string::npos) out += ".0";
}

std::string format_real(double value, int significant) {
  std::string text;
  fmt::format_to(std::back_inserter(text), "{:.{}g}", value, significant);
  if (std::isfinite(value) && text.find_first_of(".e") == std::string::npos) text += ".0";
  return text;
}

std::string csv_quoted(std::string_view text) {
  std::string out = "\"";
  for (char c : text) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + '"';
}

std::string numbered_header(std::string_view prefix, int count, int first_index) {
  std::string out;
  for (int i = 0; i < count; ++i) {
    if (i) out += ',';
    fmt::format_to(std::back_inserter(out), "{}{}", prefix, first_index + i);
  }
  return out;
}

}  // namespace dfvn
