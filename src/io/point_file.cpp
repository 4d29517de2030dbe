#include "dfvn/io/point_file.hpp"

#include "dfvn/core/message_text.hpp"

#include <bit>
#include <cstdint>
#include <string>

#include <fmt/format.h>

#include <stdexcept>

#include "dfvn/io/atomic_file.hpp"
#include "dfvn/io/csv.hpp"

namespace dfvn {

void write_npy(std::ostream& out, const PointSet& points) {
  static_assert(std::endian::native == std::endian::little, "'<f8' output assumes a little-endian machine");
  std::string header = fmt::format("{{'descr': '<f8', 'fortran_order': False, 'shape': ({}, {}), }}", points.size(),
                                   points.dimension);
  // Magic (6) + version (2) + header length (2) + header, padded with spaces and ended by '\n' to a
  // multiple of 64 bytes (the format's alignment rule).
  const std::size_t unpadded = 10 + header.size() + 1;
  header.append((64 - unpadded % 64) % 64, ' ');
  header += '\n';
  const auto length = static_cast<std::uint16_t>(header.size());
  out.write("\x93NUMPY\x01\x00", 8);
  const char length_bytes[2] = {static_cast<char>(length & 0xFF), static_cast<char>(length >> 8)};
  out.write(length_bytes, 2);
  out.write(header.data(), static_cast<std::streamsize>(header.size()));
  out.write(reinterpret_cast<const char*>(points.coordinates.data()),
            static_cast<std::streamsize>(points.coordinates.size() * sizeof(double)));
}

namespace {

// One point a line, coordinates separated by `separator`, after `header`. Formatted and written in
// blocks of rows: memory stays small for any number of points.
void write_points_text(std::ostream& out, const PointSet& points, std::string text, char separator) {
  constexpr std::size_t kBlockRows = 4096;
  for (std::size_t i = 0; i < points.size(); ++i) {
    for (int j = 0; j < points.dimension; ++j) {
      if (j) text += separator;
      append_double(text, points.point(i)[j]);
    }
    text += '\n';
    if ((i + 1) % kBlockRows == 0) {
      out.write(text.data(), static_cast<std::streamsize>(text.size()));
      text.clear();
    }
  }
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
}

}  // namespace

void write_points_csv(std::ostream& out, const PointSet& points) {
  write_points_text(out, points, numbered_header("x", points.dimension) + '\n', ',');
}

void write_points_dat(std::ostream& out, const PointSet& points) { write_points_text(out, points, std::string(), ' '); }

PointFormat parse_point_format(std::string_view name) {
  if (name == "csv") return PointFormat::csv;
  if (name == "npy") return PointFormat::npy;
  if (name == "dat") return PointFormat::dat;
  throw std::invalid_argument("unknown point format " + quote_for_message(name) + " (allowed: csv, npy, dat)");
}

void write_point_file(const std::string& path, const PointSet& points, PointFormat format) {
  AtomicOutput out(path);
  switch (format) {
    case PointFormat::csv: write_points_csv(out.stream(), points); break;
    case PointFormat::npy: write_npy(out.stream(), points); break;
    case PointFormat::dat: write_points_dat(out.stream(), points); break;
  }
  out.commit();
}

}  // namespace dfvn
