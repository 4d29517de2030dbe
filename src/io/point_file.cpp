#include "dfvn/io/point_file.hpp"

#include "dfvn/core/message_text.hpp"

#include <bit>
#include <limits>
#include <sstream>
#include <cstdint>
#include <string>

#include <fmt/format.h>

#include <stdexcept>

#include "dfvn/io/atomic_file.hpp"
#include "dfvn/io/csv.hpp"
#include "dfvn/io/utk_bin.hpp"

namespace dfvn {

void write_npy_header(std::ostream& out, const std::string& shape) {
  static_assert(std::endian::native == std::endian::little, "'<f8' output assumes a little-endian machine");
  std::string header = fmt::format("{{'descr': '<f8', 'fortran_order': False, 'shape': ({}), }}", shape);
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
}

namespace {

void write_coordinates(std::ostream& out, const PointSet& points) {
  out.write(reinterpret_cast<const char*>(points.coordinates.data()),
            static_cast<std::streamsize>(points.coordinates.size() * sizeof(double)));
}

}  // namespace

void write_npy(std::ostream& out, const PointSet& points) {
  write_npy_header(out, fmt::format("{}, {}", points.size(), points.dimension));
  write_coordinates(out, points);
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
  if (name == "bin") return PointFormat::bin;
  throw std::invalid_argument("unknown point format " + quote_for_message(name) + " (allowed: csv, npy, dat, bin)");
}

void write_point_file(const std::string& path, const PointSet& points, PointFormat format) {
  AtomicOutput out(path);
  switch (format) {
    case PointFormat::csv: write_points_csv(out.stream(), points); break;
    case PointFormat::npy: write_npy(out.stream(), points); break;
    case PointFormat::dat: write_points_dat(out.stream(), points); break;
    case PointFormat::bin: write_utk_bin(out.stream(), points); break;
  }
  out.commit();
}

PointFileWriter::PointFileWriter(const std::string& path, PointFormat format, int dimension, std::uint64_t count,
                                 bool count_known)
    : out_(path), format_(format), dimension_(dimension), count_(count_known ? count : 0), count_known_(count_known) {
  if (format_ == PointFormat::bin && count > std::numeric_limits<std::uint32_t>::max())
    throw std::invalid_argument(fmt::format("UTK's .bin holds at most 2^32 - 1 points a set; this set has {}", count));
  const std::string h = header(count_);
  out_.stream().write(h.data(), static_cast<std::streamsize>(h.size()));
}

std::string PointFileWriter::header(std::uint64_t count) const {
  switch (format_) {
    case PointFormat::csv: return numbered_header("x", dimension_) + '\n';
    case PointFormat::npy: {
      std::ostringstream text;
      write_npy_header(text, fmt::format("{}, {}", count, dimension_));
      return text.str();
    }
    case PointFormat::bin: {
      const auto n = static_cast<std::uint32_t>(count);
      return std::string(reinterpret_cast<const char*>(&n), 4);
    }
    case PointFormat::dat: return {};
  }
  return {};
}

void PointFileWriter::append(const double* coordinates, std::uint64_t rows) {
  if (format_ == PointFormat::bin && rows_ + rows > std::numeric_limits<std::uint32_t>::max())
    throw std::invalid_argument("UTK's .bin holds at most 2^32 - 1 points a set");
  const PointSet block{dimension_, Coordinates(coordinates, coordinates + rows * static_cast<std::uint64_t>(dimension_)),
                       Box{}};
  switch (format_) {
    case PointFormat::csv: write_points_text(out_.stream(), block, std::string(), ','); break;
    case PointFormat::dat: write_points_text(out_.stream(), block, std::string(), ' '); break;
    case PointFormat::npy:
    case PointFormat::bin:
      out_.stream().write(reinterpret_cast<const char*>(coordinates),
                          static_cast<std::streamsize>(rows * static_cast<std::uint64_t>(dimension_) * sizeof(double)));
      break;
  }
  rows_ += rows;
}

void PointFileWriter::commit() {
  if (count_known_ && rows_ != count_)
    throw std::logic_error(fmt::format("a streamed point file promised {} rows and got {}", count_, rows_));
  if (!count_known_ && (format_ == PointFormat::npy || format_ == PointFormat::bin)) {
    const std::string placeholder = header(0), final_header = header(rows_);
    if (placeholder.size() != final_header.size()) throw std::logic_error("the npy header changed its length");
    std::ostream& stream = out_.stream();
    stream.flush();
    stream.seekp(0);
    if (!stream) throw std::runtime_error(fmt::format("{}: cannot go back to write the point count (a streamed {} file "
                                                      "whose count is known only at the end needs a regular file)",
                                                      out_.path(), format_ == PointFormat::npy ? "npy" : "bin"));
    stream.write(final_header.data(), static_cast<std::streamsize>(final_header.size()));
    stream.seekp(0, std::ios::end);
  }
  out_.commit();
}

void check_point_sets_fit(const std::vector<PointSet>& sets, PointFormat format) {
  if (sets.empty()) throw std::invalid_argument("no point set to write");
  for (const PointSet& set : sets)
    if (set.dimension != sets.front().dimension)
      throw std::invalid_argument(fmt::format("the sets are {}D and {}D: one file holds sets of one dimension",
                                              sets.front().dimension, set.dimension));
  if (sets.size() == 1) return;
  if (format == PointFormat::csv)
    throw std::invalid_argument(fmt::format("csv holds one point set, not {}: use dat ('#' between sets), npy or bin",
                                            sets.size()));
  if (format == PointFormat::npy)
    for (std::size_t s = 1; s < sets.size(); ++s)
      if (sets[s].size() != sets.front().size())
        throw std::invalid_argument(fmt::format("npy holds sets of one size as an array (sets, points, N); set 0 has {} "
                                                "points, set {} has {}: use dat or bin",
                                                sets.front().size(), s, sets[s].size()));
}

void write_point_sets(std::ostream& out, const std::vector<PointSet>& sets, PointFormat format) {
  check_point_sets_fit(sets, format);
  if (sets.size() == 1 && format != PointFormat::bin) {
    switch (format) {
      case PointFormat::csv: write_points_csv(out, sets.front()); break;
      case PointFormat::npy: write_npy(out, sets.front()); break;
      default: write_points_dat(out, sets.front()); break;
    }
    return;
  }
  switch (format) {
    case PointFormat::npy:
      write_npy_header(out, fmt::format("{}, {}, {}", sets.size(), sets.front().size(), sets.front().dimension));
      for (const PointSet& set : sets) write_coordinates(out, set);
      break;
    case PointFormat::dat:
      // UTK's write_text_pointsets: "#" between sets, none after the last.
      for (std::size_t s = 0; s < sets.size(); ++s) {
        if (s) out << "#\n";
        write_points_dat(out, sets[s]);
      }
      break;
    case PointFormat::bin:
      for (const PointSet& set : sets) write_utk_bin(out, set);
      break;
    case PointFormat::csv: break;  // refused by check_point_sets_fit
  }
}

void write_point_sets_file(const std::string& path, const std::vector<PointSet>& sets, PointFormat format) {
  check_point_sets_fit(sets, format);
  AtomicOutput out(path);
  write_point_sets(out.stream(), sets, format);
  out.commit();
}

}  // namespace dfvn
