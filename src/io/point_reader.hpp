// Reading anyone's point sets: CSV (with or without a header line), NumPy .npy (float64 or float32,
// shape (points, N), (points,) or (sets, points, N)), the whitespace `dat` format of UTK (one point per
// line, lines starting with '#' separate sets) and UTK's binary .bin (io/utk_bin.hpp).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "dfvn/io/csv.hpp"

namespace dfvn {

enum class InputFormat { csv, npy, dat, bin };
InputFormat parse_input_format(std::string_view name);  // "csv" | "npy" | "dat" | "bin"
std::string_view to_string(InputFormat format);
// From the file name's extension (.csv, .npy, .dat, .txt = dat, .bin); throws std::invalid_argument
// otherwise (also for "-", standard input, which has none).
InputFormat input_format_from_path(const std::string& path);

// Dimensions an input point set may have.
inline constexpr int kMinInputDimension = 1;
inline constexpr int kMaxInputDimension = 8;

// The point sets of the file ("-": standard input, read to its end): one for csv and for npy of shape
// (points, N) or (points,), M for npy of shape (M, points, N), one per '#'-separated block for dat,
// one per record for bin. Every set has the same dimension, in kMinInputDimension..kMaxInputDimension,
// and at least one point. `bin_dimension`: the dimension of a .bin file, which does not store it (0:
// the only one that fits, io/utk_bin.hpp); other formats ignore it. Throws InputError with one line
// naming what was wrong: the line (and column) of text files, the dtype or shape of .npy files, the
// set and byte of .bin files.
std::vector<PointTable> read_point_sets(const std::string& path, InputFormat format, int bin_dimension = 0);

// The same from bytes already in memory (for tests).
std::vector<PointTable> parse_point_sets(std::string_view bytes, InputFormat format, int bin_dimension = 0);

// A 2D float64 or float32 .npy array (C or Fortran order) of shape (rows, columns), each 2..kMaxNpyMatrixSide,
// every element finite, as rows x columns values in C order (element (i, j) at i * columns + j): the
// height fields of --lift npy:FILE. Throws InputError with one line naming the dtype, the shape (not 2D,
// too small or large, the data size) or the first element that is not finite.
inline constexpr std::uint64_t kMaxNpyMatrixSide = 65536;
struct NpyMatrix {
  int rows = 0;
  int columns = 0;
  std::vector<double> values;
};
NpyMatrix parse_npy_matrix(std::string_view bytes);
NpyMatrix read_npy_matrix(const std::string& path);  // "-": standard input

// Throws InputError saying why `path` ("-": standard input, always readable) cannot be read: missing,
// a directory, no permission.
void check_readable_file(const std::string& path);

// Every byte of the file ("-": standard input). Throws InputError if it cannot be read.
std::string read_whole_file(const std::string& path);

}  // namespace dfvn
