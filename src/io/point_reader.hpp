// Reading anyone's point sets: CSV (with or without a header line), NumPy .npy (float64 or float32,
// shape (points, N) or (points,)) and the whitespace `dat` format of UTK (one point per line, lines
// starting with '#' separate sets).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "dfvn/io/csv.hpp"

namespace dfvn {

enum class InputFormat { csv, npy, dat };
InputFormat parse_input_format(std::string_view name);  // "csv" | "npy" | "dat"
std::string_view to_string(InputFormat format);
// From the file name's extension (.csv, .npy, .dat, .txt = dat); throws std::invalid_argument otherwise.
InputFormat input_format_from_path(const std::string& path);

// Dimensions an input point set may have.
inline constexpr int kMinInputDimension = 1;
inline constexpr int kMaxInputDimension = 8;

// The point sets of the file: one for csv and npy, one per '#'-separated block for dat. Every set
// has the same dimension, in kMinInputDimension..kMaxInputDimension, and at least one point. Throws
// InputError with one line naming what was wrong: the line (and column) of text files, the dtype or
// shape of .npy files.
std::vector<PointTable> read_point_sets(const std::string& path, InputFormat format);

// The same from bytes already in memory (for tests).
std::vector<PointTable> parse_point_sets(std::string_view bytes, InputFormat format);

}  // namespace dfvn
