#include "dfvn/io/point_reader.hpp"

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

#include <sys/stat.h>
#include <unistd.h>

#include <fmt/format.h>

#include "dfvn/core/message_text.hpp"
#include "dfvn/io/utk_bin.hpp"

namespace dfvn {

InputFormat parse_input_format(std::string_view name) {
  if (name == "csv") return InputFormat::csv;
  if (name == "npy") return InputFormat::npy;
  if (name == "dat") return InputFormat::dat;
  if (name == "bin") return InputFormat::bin;
  throw std::invalid_argument("unknown input format '" + std::string(name) + "' (allowed: csv, npy, dat, bin)");
}

std::string_view to_string(InputFormat format) {
  switch (format) {
    case InputFormat::csv: return "csv";
    case InputFormat::npy: return "npy";
    case InputFormat::dat: return "dat";
    case InputFormat::bin: return "bin";
  }
  return "?";
}

InputFormat input_format_from_path(const std::string& path) {
  const std::string extension = std::filesystem::path(path).extension().string();
  if (extension == ".csv") return InputFormat::csv;
  if (extension == ".npy") return InputFormat::npy;
  if (extension == ".dat" || extension == ".txt") return InputFormat::dat;
  if (extension == ".bin") return InputFormat::bin;
  if (path == "-") throw std::invalid_argument("standard input ('-') has no extension to tell its format; give --format csv|npy|dat|bin");
  throw std::invalid_argument("cannot tell the format of '" + path + "' from its extension; give --format csv|npy|dat|bin");
}

namespace {

void check_dimension(int dimension, const std::string& where) {
  if (dimension < kMinInputDimension || dimension > kMaxInputDimension)
    throw InputError(fmt::format("{}: {} coordinates per point; allowed {}..{}", where, dimension, kMinInputDimension,
                                 kMaxInputDimension));
}

// CSV: the column count of the first line that is not blank fixes the dimension.
std::vector<PointTable> parse_csv(std::string_view bytes) {
  std::istringstream lines{std::string(bytes)};
  std::string line;
  std::size_t line_number = 0;
  int dimension = 0;
  while (std::getline(lines, line)) {
    ++line_number;
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    dimension = static_cast<int>(std::count(line.begin(), line.end(), ',')) + 1;
    break;
  }
  if (dimension == 0) throw InputError("the file holds no points");
  check_dimension(dimension, fmt::format("line {}", line_number));
  std::istringstream in{std::string(bytes)};
  PointTable table;
  try {
    table = read_points_csv(in, dimension);
  } catch (const InputError& e) {
    // read_points_csv names the --dim of `field`; here the first line fixed the column count.
    std::string message = e.what();
    const std::string option = fmt::format(" (--dim {})", dimension);
    if (const auto at = message.find(option); at != std::string::npos) message.replace(at, option.size(), " (as in the first line)");
    throw InputError(message);
  }
  if (table.rows() == 0) throw InputError("the file holds no points, only a header");
  return {std::move(table)};
}

// dat: whitespace-separated numbers; '#' lines end a set. Every set must have the same dimension.
std::vector<PointTable> parse_dat(std::string_view bytes) {
  std::vector<PointTable> sets;
  PointTable current;
  int dimension = 0;
  auto close_set = [&] {
    if (current.rows() > 0) sets.push_back(std::move(current));
    current = PointTable{dimension, {}};
  };
  std::istringstream lines{std::string(bytes)};
  std::string line;
  std::size_t line_number = 0;
  while (std::getline(lines, line)) {
    ++line_number;
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos) continue;
    if (line[first] == '#') {
      close_set();
      continue;
    }
    std::vector<double> values;
    std::istringstream fields(line);
    std::string field;
    while (fields >> field) {
      double value = 0.0;
      const NumberText problem = parse_coordinate(field, value);  // the one number reader (io/csv.hpp)
      if (problem != NumberText::ok) throw InputError(coordinate_error(problem, line_number, values.size() + 1, field));
      values.push_back(value);
    }
    if (dimension == 0) {
      dimension = static_cast<int>(std::min<std::size_t>(values.size(), 1u << 20));
      check_dimension(dimension, fmt::format("line {}", line_number));
      current.dimension = dimension;
    }
    if (values.size() != static_cast<std::size_t>(dimension))
      throw InputError(fmt::format("line {}: expected {} whitespace-separated numbers (as in the first point), found {}",
                                   line_number, dimension, values.size()));
    current.coordinates.insert(current.coordinates.end(), values.begin(), values.end());
  }
  close_set();
  if (sets.empty()) throw InputError("the file holds no points");
  return sets;
}

// The header of an .npy file: the Python dict literal {'descr': '<f8', 'fortran_order': False,
// 'shape': (3, 2), } that numpy.save writes, read by a small strict scanner (no regular expressions:
// libstdc++'s recurse once per character and overflow the stack on a long header).
struct NpyHeader {
  std::string descr;
  bool fortran_order = false;
  std::vector<std::uint64_t> shape;
};

// The shape for messages, as Python prints it: "(3, 2)", "(6,)", "()"; beyond 3 extents, their count.
std::string shape_text(const std::vector<std::uint64_t>& shape) {
  if (shape.size() == 1) return fmt::format("({},)", shape[0]);
  if (shape.size() > 3) return fmt::format("({}, {}, {}, ... {} extents)", shape[0], shape[1], shape[2], shape.size());
  std::string text = "(";
  for (std::size_t i = 0; i < shape.size(); ++i) text += (i ? ", " : "") + std::to_string(shape[i]);
  return text + ")";
}

class NpyHeaderScanner {
 public:
  explicit NpyHeaderScanner(std::string_view text) : text_(text) {}

  NpyHeader parse() {
    NpyHeader header;
    bool has_descr = false, has_order = false, has_shape = false;
    expect('{');
    while (true) {
      skip_space();
      if (peek() == '}') break;
      const std::string key = string_literal();
      expect(':');
      if (key == "descr") {
        header.descr = string_literal();
        has_descr = true;
      } else if (key == "fortran_order") {
        header.fortran_order = boolean();
        has_order = true;
      } else if (key == "shape") {
        shape(header);
        has_shape = true;
      } else {
        throw InputError("npy: header has a key " + quote_for_message(key) +
                         " (allowed: 'descr', 'fortran_order', 'shape')");
      }
      skip_space();
      if (peek() == ',') {
        ++at_;
        continue;
      }
      if (peek() != '}') fail("',' or '}'");
    }
    ++at_;
    skip_space();
    if (at_ != text_.size()) fail("the end of the header");
    if (!has_descr) throw InputError("npy: header has no 'descr'");
    if (!has_order) throw InputError("npy: header has no 'fortran_order'");
    if (!has_shape) throw InputError("npy: header has no 'shape'");
    return header;
  }

 private:
  std::string_view text_;
  std::size_t at_ = 0;

  char peek() const { return at_ < text_.size() ? text_[at_] : '\0'; }
  void skip_space() {
    while (at_ < text_.size() && (text_[at_] == ' ' || text_[at_] == '\t' || text_[at_] == '\n' || text_[at_] == '\r')) ++at_;
  }
  [[noreturn]] void fail(std::string_view wanted) const {
    throw InputError(fmt::format("npy: header is not a dict literal: expected {} at byte {} of the header", wanted, at_));
  }
  void expect(char c) {
    skip_space();
    if (peek() != c) fail(fmt::format("'{}'", c));
    ++at_;
  }
  std::string string_literal() {
    skip_space();
    const char quote = peek();
    if (quote != '\'' && quote != '"') fail("a quoted string");
    const std::size_t end = text_.find(quote, at_ + 1);
    if (end == std::string_view::npos) fail("a closing quote");
    std::string value(text_.substr(at_ + 1, end - at_ - 1));
    at_ = end + 1;
    return value;
  }
  bool boolean() {
    skip_space();
    for (const auto& [word, value] : {std::pair{std::string_view("True"), true}, {std::string_view("False"), false}})
      if (text_.substr(at_, word.size()) == word) {
        at_ += word.size();
        return value;
      }
    fail("True or False");
  }
  // (a, b), (a,) or (): extents in decimal digits, each at most 2^64 - 1.
  void shape(NpyHeader& header) {
    expect('(');
    while (true) {
      skip_space();
      if (peek() == ')') break;
      const std::size_t first = at_;
      while (at_ < text_.size() && text_[at_] >= '0' && text_[at_] <= '9') ++at_;
      if (at_ == first) fail("a shape extent (digits)");
      std::uint64_t extent = 0;
      const auto [ptr, error] = std::from_chars(text_.data() + first, text_.data() + at_, extent);
      if (error != std::errc())
        throw InputError("npy: shape extent " + quote_for_message(text_.substr(first, at_ - first)) +
                         " is above 2^64 - 1");
      header.shape.push_back(extent);
      skip_space();
      if (peek() == ',') {
        ++at_;
        continue;
      }
      if (peek() != ')') fail("',' or ')' in the shape");
    }
    ++at_;
  }
};

// NPY format 1.0-3.0: magic "\x93NUMPY", major, minor, header length (2 bytes in 1.x, 4 in 2.x/3.x,
// little endian), the header dict, then the data. The dtype must be float64 or float32 (item_size).
struct NpyLayout {
  NpyHeader header;
  std::size_t item_size = 0;
  std::size_t data_start = 0;
};

NpyLayout npy_layout(std::string_view bytes) {
  if (bytes.size() < 10 || bytes.substr(0, 6) != std::string_view("\x93NUMPY", 6))
    throw InputError("not a NumPy .npy file (no \\x93NUMPY magic)");
  const int major = static_cast<unsigned char>(bytes[6]);
  std::size_t header_length = 0, header_start = 0;
  if (major == 1) {
    header_length = static_cast<unsigned char>(bytes[8]) | (std::size_t{static_cast<unsigned char>(bytes[9])} << 8);
    header_start = 10;
  } else if (major == 2 || major == 3) {
    if (bytes.size() < 12) throw InputError("npy: truncated header");
    for (int b = 0; b < 4; ++b) header_length |= std::size_t{static_cast<unsigned char>(bytes[8 + b])} << (8 * b);
    header_start = 12;
  } else {
    throw InputError(fmt::format("npy: format version {} is not supported (allowed 1, 2, 3)", major));
  }
  // header_start + header_length < 2^33: no overflow.
  if (bytes.size() < header_start + header_length) throw InputError("npy: truncated header");
  NpyLayout layout;
  layout.header = NpyHeaderScanner(bytes.substr(header_start, header_length)).parse();
  const std::string& descr = layout.header.descr;
  const bool little = std::endian::native == std::endian::little;
  if ((descr == "<f8" && little) || descr == "=f8") layout.item_size = 8;
  else if ((descr == "<f4" && little) || descr == "=f4") layout.item_size = 4;
  else
    throw InputError(fmt::format("npy: dtype {} is not supported (allowed float64 '<f8' and float32 '<f4')",
                                 quote_for_message(descr)));
  layout.data_start = header_start + header_length;
  return layout;
}

double npy_element(const char* data, std::uint64_t element, std::size_t item_size) {
  if (item_size == 8) {
    double value;
    std::memcpy(&value, data + element * 8, 8);
    return value;
  }
  float single;
  std::memcpy(&single, data + element * 4, 4);
  return single;
}

}  // namespace

NpyMatrix parse_npy_matrix(std::string_view bytes) {
  const NpyLayout layout = npy_layout(bytes);
  const std::vector<std::uint64_t>& shape = layout.header.shape;
  if (shape.size() != 2)
    throw InputError(fmt::format("npy: shape {} is not a 2D array (rows, columns)", shape_text(shape)));
  if (shape[0] < 2 || shape[1] < 2 || shape[0] > kMaxNpyMatrixSide || shape[1] > kMaxNpyMatrixSide)
    throw InputError(fmt::format("npy: shape {} needs 2..{} rows and columns", shape_text(shape), kMaxNpyMatrixSide));
  const std::uint64_t count = shape[0] * shape[1];  // at most 2^32
  const std::uint64_t available = bytes.size() - layout.data_start;
  if (count * layout.item_size != available)
    throw InputError(fmt::format("npy: shape {} of dtype '{}' needs {} data bytes, the file has {}", shape_text(shape),
                                 layout.header.descr, count * layout.item_size, available));
  NpyMatrix matrix{static_cast<int>(shape[0]), static_cast<int>(shape[1]), std::vector<double>(count)};
  const char* data = bytes.data() + layout.data_start;
  for (std::uint64_t i = 0; i < shape[0]; ++i)
    for (std::uint64_t j = 0; j < shape[1]; ++j) {
      const double value = npy_element(data, layout.header.fortran_order ? j * shape[0] + i : i * shape[1] + j, layout.item_size);
      if (!std::isfinite(value))
        throw InputError(fmt::format("npy: element ({}, {}) is {} (only finite numbers are allowed)", i, j, value));
      matrix.values[i * shape[1] + j] = value;
    }
  return matrix;
}

NpyMatrix read_npy_matrix(const std::string& path) { return parse_npy_matrix(read_whole_file(path)); }

namespace {

std::vector<PointTable> parse_npy(std::string_view bytes) {
  const NpyLayout layout = npy_layout(bytes);
  const NpyHeader& header = layout.header;
  const std::string& descr = header.descr;
  const std::size_t item_size = layout.item_size;
  const std::string shape = shape_text(header.shape);
  if (header.shape.empty() || header.shape.size() > 3)
    throw InputError(fmt::format("npy: shape {} is not (points, dimension), (points,) or (sets, points, dimension)", shape));
  // (sets, points, N): `sets` sets of `points` rows each, the rows of all sets in one table here.
  const bool several = header.shape.size() == 3;
  const std::uint64_t set_count = several ? header.shape[0] : 1;
  const std::uint64_t set_rows = several ? header.shape[1] : header.shape[0];
  const int dimension =
      header.shape.size() >= 2 ? static_cast<int>(std::min<std::uint64_t>(header.shape.back(), 1u << 20)) : 1;
  check_dimension(dimension, "npy: shape " + shape);
  if (set_count == 0 || set_rows == 0) throw InputError(fmt::format("npy: shape {} holds no points", shape));
  std::uint64_t rows = 0;
  if (__builtin_mul_overflow(set_count, set_rows, &rows))
    throw InputError(fmt::format("npy: shape {} holds more than 2^64 points", shape));
  const std::size_t data_start = layout.data_start;
  const std::uint64_t available = bytes.size() - data_start;
  // rows x N x item size in checked arithmetic: a header may declare (2^62, 8), whose product wraps.
  const std::uint64_t row_bytes = static_cast<std::uint64_t>(dimension) * item_size;  // at most 64
  if (rows > available / row_bytes || rows * row_bytes != available) {
    std::uint64_t need = 0;
    const std::string need_text = __builtin_mul_overflow(rows, row_bytes, &need)
                                      ? fmt::format("{:.4g}", static_cast<double>(rows) * static_cast<double>(row_bytes))
                                      : std::to_string(need);
    throw InputError(fmt::format("npy: shape {} of dtype '{}' needs {} data bytes, the file has {}", shape, descr,
                                 need_text, available));
  }
  PointTable table{dimension, Coordinates(rows * static_cast<std::uint64_t>(dimension))};
  const char* data = bytes.data() + data_start;
  // Row i of the whole array is point i % set_rows of set i / set_rows. C order: element (i, k) at
  // i * N + k in both shapes; Fortran order: (s, p, k) at k * sets * points + p * sets + s.
  for (std::uint64_t i = 0; i < rows; ++i) {
    for (int k = 0; k < dimension; ++k) {
      // C order: element (i, k) at i * N + k; Fortran order: at k * rows + i.
      const std::uint64_t element =
          !header.fortran_order ? i * dimension + k
          : several ? k * rows + (i % set_rows) * set_count + i / set_rows
                    : k * rows + i;
      const double value = npy_element(data, element, item_size);
      if (!std::isfinite(value))
        throw InputError(fmt::format("npy: element ({}, {}) is {} (only finite numbers are allowed)", i, k, value));
      table.coordinates[i * dimension + k] = value;
    }
  }
  if (!several) return {std::move(table)};
  std::vector<PointTable> sets;
  const std::uint64_t set_values = set_rows * static_cast<std::uint64_t>(dimension);
  for (std::uint64_t s = 0; s < set_count; ++s) {
    PointTable set{dimension, Coordinates(set_values)};
    std::memcpy(set.coordinates.data(), table.coordinates.data() + s * set_values, set_values * sizeof(double));
    sets.push_back(std::move(set));
  }
  return sets;
}

}  // namespace

std::vector<PointTable> parse_point_sets(std::string_view bytes, InputFormat format, int bin_dimension) {
  switch (format) {
    case InputFormat::csv: return parse_csv(bytes);
    case InputFormat::npy: return parse_npy(bytes);
    case InputFormat::dat: return parse_dat(bytes);
    case InputFormat::bin: return parse_utk_bin(bytes, bin_dimension);
  }
  throw std::logic_error("unknown input format");
}

void check_readable_file(const std::string& path) {
  if (path == "-") return;
  struct stat status {};
  if (::stat(path.c_str(), &status) != 0) throw InputError(std::string("cannot read the file: ") + std::strerror(errno));
  if (S_ISDIR(status.st_mode)) throw InputError("cannot read the file: it is a directory");
  if (::access(path.c_str(), R_OK) != 0) throw InputError(std::string("cannot read the file: ") + std::strerror(errno));
}

std::string read_whole_file(const std::string& path) {
  check_readable_file(path);
  // One read loop for files and pipes alike, in 1 MiB blocks: standard input costs what a file costs.
  std::FILE* file = path == "-" ? stdin : std::fopen(path.c_str(), "rb");
  if (!file) throw InputError(std::string("cannot read the file: ") + std::strerror(errno));
  std::string bytes;
  constexpr std::size_t kBlock = std::size_t{1} << 20;
  std::size_t used = 0;
  while (true) {
    bytes.resize(used + kBlock);
    const std::size_t got = std::fread(bytes.data() + used, 1, kBlock, file);
    used += got;
    if (got < kBlock) break;
  }
  const bool failed = std::ferror(file) != 0;
  if (file != stdin) std::fclose(file);
  if (failed) throw InputError(std::string(path == "-" ? "read error on standard input: " : "read error: ") + std::strerror(errno));
  bytes.resize(used);
  return bytes;
}

std::vector<PointTable> read_point_sets(const std::string& path, InputFormat format, int bin_dimension) {
  return parse_point_sets(read_whole_file(path), format, bin_dimension);
}

}  // namespace dfvn
