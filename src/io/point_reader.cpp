#include "io/point_reader.hpp"

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>
#include <sstream>

#include <fmt/format.h>

namespace dfvn {

InputFormat parse_input_format(std::string_view name) {
  if (name == "csv") return InputFormat::csv;
  if (name == "npy") return InputFormat::npy;
  if (name == "dat") return InputFormat::dat;
  throw std::invalid_argument("unknown input format '" + std::string(name) + "' (allowed: csv, npy, dat)");
}

std::string_view to_string(InputFormat format) {
  switch (format) {
    case InputFormat::csv: return "csv";
    case InputFormat::npy: return "npy";
    case InputFormat::dat: return "dat";
  }
  return "?";
}

InputFormat input_format_from_path(const std::string& path) {
  const std::string extension = std::filesystem::path(path).extension().string();
  if (extension == ".csv") return InputFormat::csv;
  if (extension == ".npy") return InputFormat::npy;
  if (extension == ".dat" || extension == ".txt") return InputFormat::dat;
  throw std::invalid_argument("cannot tell the format of '" + path + "' from its extension; give --format csv|npy|dat");
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
    int column = 0;
    while (fields >> field) {
      ++column;
      double value = 0.0;
      const char* begin = field.c_str() + (field[0] == '+' ? 1 : 0);
      char* end = nullptr;
      errno = 0;
      value = std::strtod(begin, &end);
      if (end == begin || *end != '\0')
        throw InputError(fmt::format("line {}, column {}: '{}' is not a number", line_number, column, field));
      if (!std::isfinite(value) || errno == ERANGE)
        throw InputError(fmt::format("line {}, column {}: '{}' is not a finite number", line_number, column, field));
      values.push_back(value);
    }
    if (dimension == 0) {
      dimension = static_cast<int>(values.size());
      check_dimension(dimension, fmt::format("line {}", line_number));
      current.dimension = dimension;
    }
    if (static_cast<int>(values.size()) != dimension)
      throw InputError(fmt::format("line {}: expected {} whitespace-separated numbers (as in the first point), found {}",
                                   line_number, dimension, values.size()));
    current.coordinates.insert(current.coordinates.end(), values.begin(), values.end());
  }
  close_set();
  if (sets.empty()) throw InputError("the file holds no points");
  return sets;
}

// NPY format 1.0-3.0: magic "\x93NUMPY", major, minor, header length (2 bytes in 1.x, 4 in 2.x/3.x,
// little endian), a Python dict literal {'descr': ..., 'fortran_order': ..., 'shape': (...)}, data.
std::vector<PointTable> parse_npy(std::string_view bytes) {
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
  if (bytes.size() < header_start + header_length) throw InputError("npy: truncated header");
  const std::string header(bytes.substr(header_start, header_length));
  std::smatch m;
  if (!std::regex_search(header, m, std::regex(R"('descr'\s*:\s*'([^']*)')")))
    throw InputError("npy: header has no 'descr'");
  const std::string descr = m[1];
  const bool little = std::endian::native == std::endian::little;
  std::size_t item_size = 0;
  if ((descr == "<f8" && little) || descr == "=f8") item_size = 8;
  else if ((descr == "<f4" && little) || descr == "=f4") item_size = 4;
  else
    throw InputError(fmt::format("npy: dtype '{}' is not supported (allowed float64 '<f8' and float32 '<f4')", descr));
  const bool fortran = std::regex_search(header, std::regex(R"('fortran_order'\s*:\s*True)"));
  if (!std::regex_search(header, m, std::regex(R"('shape'\s*:\s*\(([^)]*)\))")))
    throw InputError("npy: header has no 'shape'");
  std::vector<std::uint64_t> shape;
  {
    std::string dims = m[1];
    std::replace(dims.begin(), dims.end(), ',', ' ');
    std::istringstream in(dims);
    std::uint64_t extent = 0;
    while (in >> extent) shape.push_back(extent);
  }
  const std::string shape_text = "(" + std::string(m[1]) + ")";
  if (shape.empty() || shape.size() > 2)
    throw InputError(fmt::format("npy: shape {} is not (points, dimension) or (points,)", shape_text));
  const std::uint64_t rows = shape[0];
  const int dimension = shape.size() == 2 ? static_cast<int>(std::min<std::uint64_t>(shape[1], 1u << 20)) : 1;
  check_dimension(dimension, "npy: shape " + shape_text);
  if (rows == 0) throw InputError(fmt::format("npy: shape {} holds no points", shape_text));
  const std::size_t data_start = header_start + header_length;
  const std::uint64_t need = rows * static_cast<std::uint64_t>(dimension) * item_size;
  if (bytes.size() - data_start != need)
    throw InputError(fmt::format("npy: shape {} of dtype '{}' needs {} data bytes, the file has {}", shape_text, descr,
                                 need, bytes.size() - data_start));
  PointTable table{dimension, std::vector<double>(rows * static_cast<std::uint64_t>(dimension))};
  const char* data = bytes.data() + data_start;
  for (std::uint64_t i = 0; i < rows; ++i) {
    for (int k = 0; k < dimension; ++k) {
      // C order: element (i, k) at i * N + k; Fortran order: at k * rows + i.
      const std::uint64_t element = fortran ? k * rows + i : i * dimension + k;
      double value;
      if (item_size == 8) {
        std::memcpy(&value, data + element * 8, 8);
      } else {
        float single;
        std::memcpy(&single, data + element * 4, 4);
        value = single;
      }
      if (!std::isfinite(value))
        throw InputError(fmt::format("npy: element ({}, {}) is {} (only finite numbers are allowed)", i, k, value));
      table.coordinates[i * dimension + k] = value;
    }
  }
  return {std::move(table)};
}

}  // namespace

std::vector<PointTable> parse_point_sets(std::string_view bytes, InputFormat format) {
  switch (format) {
    case InputFormat::csv: return parse_csv(bytes);
    case InputFormat::npy: return parse_npy(bytes);
    case InputFormat::dat: return parse_dat(bytes);
  }
  throw std::logic_error("unknown input format");
}

std::vector<PointTable> read_point_sets(const std::string& path, InputFormat format) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("cannot read the file");
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw InputError("read error");
  return parse_point_sets(bytes, format);
}

}  // namespace dfvn
