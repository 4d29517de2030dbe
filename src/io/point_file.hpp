// Point-set files: CSV with header x0..x{N-1} (17 significant digits), NumPy .npy (format 1.0:
// float64, shape (points, N), C order; numpy.load reads it), or dat: one point a line, coordinates
// separated by spaces (17 significant digits), no header; the text format of UTK's tools and pbrt-v4's
// pspec, where '#' lines separate sets (a file of ours holds one set), and numpy.loadtxt reads it.
#pragma once

#include <ostream>
#include <string>
#include <string_view>

#include "dfvn/core/point_set.hpp"

namespace dfvn {

void write_npy(std::ostream& out, const PointSet& points);
void write_points_csv(std::ostream& out, const PointSet& points);
void write_points_dat(std::ostream& out, const PointSet& points);

enum class PointFormat { csv, npy, dat };
PointFormat parse_point_format(std::string_view name);  // "csv" | "npy" | "dat"

// Writes the points to `path` ("-" = standard output), whole or not at all. Throws std::runtime_error.
void write_point_file(const std::string& path, const PointSet& points, PointFormat format);

}  // namespace dfvn
