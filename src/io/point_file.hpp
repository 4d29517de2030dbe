// Point-set files: CSV with header x0..x{N-1} (17 significant digits), NumPy .npy (format 1.0:
// float64, shape (points, N), C order; numpy.load reads it), or dat: one point a line, coordinates
// separated by spaces (17 significant digits), no header; the text format of UTK's tools and pbrt-v4's
// pspec, where '#' lines separate sets, and numpy.loadtxt reads a file of one set; or bin: UTK's
// binary records (io/utk_bin.hpp). Several sets in one file (sample --sets M): dat with a line "#"
// between sets (UTK's write_text_pointsets), npy of shape (M, points, N), bin with one record per set;
// csv holds one set.
#pragma once

#include <cstdint>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "dfvn/core/point_set.hpp"
#include "dfvn/io/atomic_file.hpp"

namespace dfvn {

// The .npy header (format 1.0) of float64 data of this shape, e.g. "3, 2" or "8, 1024, 2"; the data
// follows it in C order.
void write_npy_header(std::ostream& out, const std::string& shape);
void write_npy(std::ostream& out, const PointSet& points);
void write_points_csv(std::ostream& out, const PointSet& points);
void write_points_dat(std::ostream& out, const PointSet& points);

enum class PointFormat { csv, npy, dat, bin };
PointFormat parse_point_format(std::string_view name);  // "csv" | "npy" | "dat" | "bin"

// Writes the points to `path` ("-" = standard output), whole or not at all. Throws std::runtime_error.
void write_point_file(const std::string& path, const PointSet& points, PointFormat format);

// Throws std::invalid_argument, naming the format and the reason, unless one file of `format` can hold
// these sets: csv holds one set, npy sets of one size (an array (M, points, N)); all of one dimension.
// One point set written a block of rows at a time, with the bytes write_point_file gives for the whole
// set (a streamed run's slabs, experiment/streamed_sampling.hpp). npy's shape and bin's count come first:
// give `count` when it is known; otherwise (count_known false) a placeholder is written and commit()
// writes the final count over it, which needs a file (not standard output or a device). Whole or not at
// all, as AtomicOutput.
class PointFileWriter {
 public:
  PointFileWriter(const std::string& path, PointFormat format, int dimension, std::uint64_t count, bool count_known);
  void append(const double* coordinates, std::uint64_t rows);
  void commit();  // throws std::runtime_error if the count cannot be written back
  std::uint64_t rows() const { return rows_; }

 private:
  std::string header(std::uint64_t count) const;
  AtomicOutput out_;
  PointFormat format_;
  int dimension_;
  std::uint64_t count_;
  bool count_known_;
  std::uint64_t rows_ = 0;
};

void check_point_sets_fit(const std::vector<PointSet>& sets, PointFormat format);
// The sets in one stream or file (whole or not at all), in the layouts above; one set is written as
// write_point_file writes it (npy (points, N), dat without a '#' line).
void write_point_sets(std::ostream& out, const std::vector<PointSet>& sets, PointFormat format);
void write_point_sets_file(const std::string& path, const std::vector<PointSet>& sets, PointFormat format);

}  // namespace dfvn
