// Reading points from CSV and writing numbers so that they read back to the same double.
#pragma once

#include <cstddef>
#include <istream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "dfvn/core/bulk_memory.hpp"

namespace dfvn {

// Bad input data. The message names the line (and column) and the problem.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Points as a row-major table: coordinates.size() == rows * dimension.
struct PointTable {
  int dimension = 0;
  Coordinates coordinates;
  std::size_t rows() const { return dimension ? coordinates.size() / dimension : 0; }
  const double* row(std::size_t i) const { return coordinates.data() + i * dimension; }
};

// The one reader of a coordinate in every text point file (CSV, whitespace-separated, UTK's dat): an
// optional sign ('+' or '-', only one), then the whole field as std::from_chars reads a double in
// general format ("0.5", "-1e-3", ".5"; no hexadecimal, no spaces, nothing after the number).
enum class NumberText { ok, not_a_number, out_of_range, not_finite };
NumberText parse_coordinate(std::string_view text, double& value);

// The InputError message for a field that is not ok, naming its line and column (1-based) and the
// text, shortened and escaped (core/message_text.hpp): "line 3, column 2: '+-1' is not a number".
std::string coordinate_error(NumberText problem, std::size_t line, std::size_t column, std::string_view text);

// One point per line, `dimension` comma-separated finite numbers, each optionally in double quotes
// ("0.5" is the number 0.5). The first line may be a header (no field of it a number, e.g.
// "x0,x1,x2") and may start with a UTF-8 byte order mark; blank lines are skipped. Throws InputError
// naming the line (and column) on a wrong column count, an unterminated quote, text that is not a
// number (including a second sign, "+-1"), or NaN/Inf; the offending text is quoted shortened and
// escaped (core/message_text.hpp).
PointTable read_points_csv(std::istream& in, int dimension);

// Points as text in either layout: comma-separated (as read_points_csv) or separated by spaces and
// tabs (numpy.savetxt's default; lines starting with '#' are comments, and the first other line may be
// a header). The first line that is neither blank nor a comment decides which: a comma makes it CSV.
// `dimension` 0: the column count of that line (1..16), named in errors as "as in the first line".
PointTable read_points_text(std::istream& in, int dimension);

// The one way every real number is written in the tool's CSV (and text point) files: `significant`
// digits ("%.9g"), with ".0" appended when that leaves neither a decimal point nor an exponent, so a
// column of reals never changes type between rows or runs ("1.0" beside "0.6", never "1"; "1e+20" and
// "2.5e-07" keep their exponent). NaN and infinities are spelled "nan", "inf" and "-inf". Counts and
// other integers are written as integers ("512"), never through this function.
std::string format_real(double value, int significant = 9);

// format_real(value, 17) appended to `out`: 17 significant digits ("%.17g", ".0" added as above), so the
// text reads back to the identical double. Point coordinates and field values use it.
void append_double(std::string& out, double value);

// `text` as one CSV field (RFC 4180): in double quotes, each quote inside doubled, every other byte as
// it is (commas, newlines and non-UTF-8 bytes are then part of the field), e.g. q"uo.csv -> "q""uo.csv".
std::string csv_quoted(std::string_view text);

// "x0,x1,...,x{n-1}" style header: prefix0,prefix1,...
std::string numbered_header(std::string_view prefix, int count, int first_index = 0);

}  // namespace dfvn
